// Writes seed inputs for fuzz_capture: a small synthetic capture (both views W x H, written by
// the real writer, harness/capture/capture_files.cpp write_capture) packed as gbuffer.exr SEP
// rsm.exr SEP capture.json [SEP visibility_geometry.bin]. Usage: make_capture_seed OUT_DIR. Three
// seeds: one whose RSM has its BRSM PDF, one without (has_pdf false, one channel fewer), and one
// with the visibility geometry (DESIGN.md §8a) as well.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "fuzz_input_files.hpp"
#include "harness/capture/capture.hpp"
#include "harness/capture/capture_files.hpp"

namespace {

void fill_view(vsgl::ViewImage& v, vsgl::ViewKind kind, uint32_t w, uint32_t h, bool has_pdf) {
  v.resize(kind, w, h);
  v.has_pdf = has_pdf;
  for (uint32_t y = 0; y < h; ++y) {
    for (uint32_t x = 0; x < w; ++x) {
      const bool valid = (x + y) % 5 != 0;  // a few texels without geometry
      v.at(vsgl::kPX, x, y) = 0.25f * static_cast<float>(x);
      v.at(vsgl::kPY, x, y) = 0.25f * static_cast<float>(y);
      v.at(vsgl::kPZ, x, y) = -2.0f;
      v.at(vsgl::kValid, x, y) = valid ? 1.0f : 0.0f;
      v.at(vsgl::kNZ, x, y) = valid ? 1.0f : 0.0f;
      for (int c = vsgl::kDR; c <= vsgl::kSB; ++c)
        v.at(static_cast<vsgl::Channel>(c), x, y) = valid ? 0.1f * static_cast<float>(1 + (c + x) % 7) : 0.0f;
      v.at(vsgl::kRoughness, x, y) = 0.3f;
      v.at(vsgl::kPdf, x, y) = has_pdf && valid ? 1.0f + static_cast<float>((x * 3 + y) % 4) : 0.0f;
    }
  }
}

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void write_seed(const std::filesystem::path& out_dir, const std::string& name, bool rsm_pdf, bool geometry) {
  vsgl::Capture c;
  c.meta.scene = "fuzz-seed";
  c.meta.device = "none (synthetic)";
  c.meta.tool_version = "fuzz";
  fill_view(c.gbuffer, vsgl::ViewKind::kCamera, 8, 8, true);
  fill_view(c.rsm, vsgl::ViewKind::kLight, 8, 8, rsm_pdf);
  // This version's importance, so that the seed loads past the sidecar (capture_files.hpp).
  c.meta.brsm_importance = std::string(vsgl::kBrsmImportanceModel);
  c.meta.brsm_bias_alpha = double{vsgl::gpu::kBiasReductionAlpha};
  if (geometry) {
    vsgl::VisibilityGeometry g;
    g.triangle_vertices = {{0, 0, -2}, {2, 0, -2}, {0, 2, -2}, {0, 0, 0}, {0, 2, 0}, {2, 0, 0}};
    g.points = {{{0.5f, 0.5f, -2}, {0, 0, 1}, 0}, {{0.25f, 0.5f, 0}, {0, 0, -1}, 1}};
    g.point_seed = 7;
    c.visibility_geometry = std::move(g);
  }
  const std::filesystem::path dir = out_dir / (name + ".capture");
  vsgl::write_capture(c, dir);
  (void)vsgl::load_capture(dir);  // the seed must be a capture that loads
  const std::string sep(vsgl::fuzz::kFilePartSeparator);
  std::ofstream out(out_dir / name, std::ios::binary | std::ios::trunc);
  out << slurp(dir / "gbuffer.exr") << sep << slurp(dir / "rsm.exr") << sep << slurp(dir / "capture.json");
  if (geometry) out << sep << slurp(dir / vsgl::kVisibilityGeometryFile);
  std::filesystem::remove_all(dir);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: make_capture_seed OUT_DIR\n");
    return 2;
  }
  std::filesystem::create_directories(argv[1]);
  write_seed(argv[1], "capture_8x8_brsm", true, false);
  write_seed(argv[1], "capture_8x8_no_rsm_pdf", false, false);
  write_seed(argv[1], "capture_8x8_visibility_geometry", true, true);
  return 0;
}
