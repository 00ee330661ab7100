// `vsgl-bench quality`: the paper's quality claims as numbers (DESIGN.md §11a; the 2016 paper's Fig. 1, 5
// and 6): kernel coverage, too-bright VSGLs, power, flicker, the K sweep and the error against a
// VPL reference, written as OUT/<scene>/quality.json, quality.md and PNGs (harness/quality/quality_run.hpp).
#include <cstdio>
#include <filesystem>
#include <string>

#include "bench/cli/commands.hpp"
#include "bench/cli/generator_options.hpp"
#include "bench/cli/gpu_session.hpp"
#include "harness/core/atomic_file.hpp"
#include "harness/capture/capture.hpp"
#include "harness/capture/capture_files.hpp"
#include "harness/core/error.hpp"
#include "harness/quality/png_image.hpp"
#include "harness/quality/quality_report.hpp"
#include "harness/quality/quality_run.hpp"

namespace vsgl::cli {

int run_quality(Args& args) {
  const auto capture_arg = args.value("--capture");
  QualityConfig config;
  config.generators = args.list("--generators", "fis_tok15,fis_modified,kmeans_2d,kmeans_3d");
  config.frames = args.u32("--frames", config.frames, 2);
  config.light_vsgls = args.u32("--light-vsgls", config.light_vsgls, 1);
  config.camera_vsgls = args.u32("--camera-vsgls", config.camera_vsgls, 1);
  config.K = args.positive_float("--K", config.K);
  config.kmeans_iterations = args.u32("--kmeans-iterations", config.kmeans_iterations);
  {
    GeneratorConfig gc;
    read_pyramid_options(args, gc);
    config.pyramid = gc.pyramid;
    config.mipmapping = gc.mipmapping;
  }
  config.error_stride = args.u32("--error-stride", config.error_stride, 1);
  config.flicker_width = args.u32("--flicker-width", config.flicker_width, 1);
  config.reference_rsm = args.u32("--reference-rsm", config.reference_rsm, 1);
  config.sequence_reference_rsm = args.u32("--sequence-reference-rsm", config.sequence_reference_rsm, 1);
  if (const auto seq = args.value("--sequence")) config.sequence = std::filesystem::path(*seq);
  const auto k_items = args.list("--k-sweep", "1,2,4,8");
  const std::filesystem::path out_root = args.string("--out", "results/quality");
  config.source_dir = VSGL_SOURCE_DIR;
  GpuSession session = GpuSession::open(args);
  args.finish();
  if (!capture_arg) throw UsageError("quality needs --capture DIR (a capture written by `vsgl-bench record`)");
  config.k_sweep.clear();
  for (const auto& item : k_items) {
    float K = 0.0f;
    try {
      K = std::stof(item);
    } catch (const std::exception&) {
      throw UsageError("--k-sweep: '" + item + "' is not a number");
    }
    if (!(K > 0.0f)) throw UsageError("--k-sweep: K must be positive, got '" + item + "'");
    config.k_sweep.push_back(K);
  }
  if (config.sequence) (void)sequence_frames(*config.sequence, config.frames);  // fail before the long work

  const Capture capture = load_capture(*capture_arg);
  std::fprintf(stderr, "quality: %s on %s\n", capture.meta.scene.c_str(), session.device().info().name.c_str());
  QualityResult result = run_quality(session.device(), capture, *capture_arg, config, [](const std::string& line) {
    std::fprintf(stderr, "  %s\n", line.c_str());
  });
  add_claim_verdicts(result.json);
  const std::string markdown = quality_markdown(result.json, result.pictures);

  const std::filesystem::path out_dir = out_root / capture.meta.scene;
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec) throw InputError(out_dir.string() + ": cannot create the output directory (" + ec.message() + ")");
  for (const auto& p : result.pictures) write_png_atomic(out_dir / p.file, p.image);
  write_text_atomic(out_dir / "quality.md", markdown);
  write_text_atomic(out_dir / "quality.json", result.json.dump(1) + "\n");  // last: it names the pictures' run
  std::fputs(markdown.c_str(), stdout);
  std::printf("\nwrote %s (quality.json, quality.md, %zu PNGs)\n", out_dir.string().c_str(), result.pictures.size());
  return session.finish(0);
}

}  // namespace vsgl::cli
