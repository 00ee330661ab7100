// `vsgl-bench quality`: the paper's quality claims as numbers (DESIGN.md §11a; the 2016 paper's Fig. 1, 5
// and 6): kernel coverage, too-bright VSGLs, power, flicker, the K sweep and the error against a
// VPL reference, written as OUT/<scene>/quality.json, quality.md and PNGs (harness/quality/quality_run.hpp).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "bench/cli/commands.hpp"
#include "bench/cli/generator_options.hpp"
#include "bench/cli/gpu_session.hpp"
#include "bench/cli/visibility_options.hpp"
#include "harness/core/path_text.hpp"
#include "harness/core/platform_path.hpp"
#include "harness/core/atomic_file.hpp"
#include "harness/capture/capture.hpp"
#include "harness/capture/capture_files.hpp"
#include "harness/core/error.hpp"
#include "harness/quality/png_image.hpp"
#include "harness/quality/quality_claims.hpp"
#include "harness/quality/quality_report.hpp"
#include "harness/quality/quality_run.hpp"

namespace vsgl::cli {

namespace {

struct QualityOptions {
  std::string capture;
  QualityConfig config;
  std::vector<std::string> k_sweep{"1", "2", "4", "8"};
  std::string out = "results/quality";
  VisibilityOptions visibility;
  DeviceOptions device;
};

int run_quality_command(QualityOptions& o) {
  const std::string* capture_arg = &o.capture;
  QualityConfig& config = o.config;
  const std::filesystem::path out_root = path_from_utf8(o.out);
  config.k_sweep.clear();
  for (const auto& item : o.k_sweep) config.k_sweep.push_back(std::stof(item));
  config.visibility = visibility_settings(o.visibility);
  if (config.sequence) (void)sequence_frames(*config.sequence, config.frames);  // fail before the long work
  GpuSession session = GpuSession::open(o.device);

  const Capture capture = load_capture(path_from_utf8(*capture_arg));
  std::fprintf(stderr, "quality: %s on %s\n", capture.meta.scene.c_str(), session.device().info().name.c_str());
  QualityResult result = run_quality(session.device(), capture, *capture_arg, config, [](const std::string& line) {
    std::fprintf(stderr, "  %s\n", line.c_str());
  });
  add_claim_verdicts(result.json);
  const std::string markdown = quality_markdown(result.json, result.pictures);

  const std::filesystem::path out_dir = out_root / capture.meta.scene;
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec) throw InputError(path_text(out_dir) + ": cannot create the output directory (" + ec.message() + ")");
  for (const auto& p : result.pictures) write_png_atomic(out_dir / p.file, p.image);
  write_text_atomic(out_dir / "quality.md", markdown);
  write_text_atomic(out_dir / "quality.json", result.json.dump(1) + "\n");  // last: it names the pictures' run
  std::fputs(markdown.c_str(), stdout);
  std::printf("\nwrote %s (quality.json, quality.md, %zu PNGs)\n", path_text(out_dir).c_str(), result.pictures.size());
  return session.finish(0);
}

}  // namespace

Command add_quality_command(CLI::App& parent) {
  CLI::App* app = parent.add_subcommand(
      "quality",
      "the paper's quality claims as numbers (Fig. 1, 5, 6): kernel coverage (gap, overlap, count-weighted error "
      "beside the lattice's own floor), PDF mass per kernel, how high-frequency each view's PDF is, too-bright "
      "VSGLs, total power, flicker, a K sweep, every frame's error against a per-texel VPL reference (relMSE, "
      "relative and scaled RMSE, FLIP), Fig. 7's occluded light with visibility, verdicts from paired frames; writes "
      "OUT/<scene>/quality.json, quality.md and PNGs");
  auto o = std::make_shared<QualityOptions>();
  QualityConfig& c = o->config;
  app->add_option("--capture", o->capture, "capture directory (written by `vsgl-bench record`)")
      ->required()
      ->type_name("DIR");
  app->add_option("--frames", c.frames, "static-scene frames (only the lattice offset changes)")
      ->check(at_least(2))
      ->capture_default_str();
  app->add_option_function<std::string>(
         "--sequence", [&c](const std::string& dir) { c.sequence = path_from_utf8(dir); },
         "also the flicker over a recorded sequence (record --frames F)")
      ->type_name("DIR");
  add_generators_option(*app, c.generators, joined_names(c.generators));
  add_list_option(*app, "--k-sweep", o->k_sweep, "K values of the Fig. 6 sweep (FIS generators)", positive_number());
  app->add_option("--error-stride", c.error_stride,
                  "G-buffer stride of the reference comparison; 0: full size when the reference is predicted to "
                  "shade within --reference-budget, else 8")
      ->check(at_least(0))
      ->capture_default_str();
  app->add_option("--reference-budget", c.reference_budget_s,
                  "seconds the references may take at full size (with --error-stride 0)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app->add_option("--flicker-width", c.flicker_width,
                  "width of the animated sequence's images (G-buffer stride W_gbuf/W); the static frames use the "
                  "reference comparison's stride")
      ->check(at_least(1))
      ->capture_default_str();
  app->add_option("--reference-rsm", c.reference_rsm, "reference RSM side (every lit texel a VPL); 0: the full RSM")
      ->check(at_least(0))
      ->capture_default_str();
  app->add_option_function<std::string>(
         "--reference-capture", [&c](const std::string& dir) { c.reference_capture = path_from_utf8(dir); },
         "the reference's VPLs from this capture's RSM: the same frame recorded with a larger --rsm (same scene, "
         "--gbuffer and device); the generators keep the capture's RSM (DESIGN.md §11a)")
      ->type_name("DIR");
  app->add_option("--sequence-reference-rsm", c.sequence_reference_rsm, "the same for each sequence frame")
      ->check(at_least(1))
      ->capture_default_str();
  add_visibility_options(*app, o->visibility,
                         "Fig. 7's frames (DESIGN.md §11a.2: the light occluded by the columns, judged against a "
                         "reference with exact visibility; none leaves Fig. 7 out, and the other measures are "
                         "without visibility whatever it says)");
  app->add_option("--visibility-reference-rsm", c.visibility_reference_rsm,
                  "Fig. 7's exact-visibility reference: RSM side (every lit texel a VPL traced to every pixel); 0: "
                  "as --reference-rsm")
      ->check(at_least(0))
      ->capture_default_str();
  app->add_option("--control-frames", c.control_frames,
                  "Fig. 7's control (each generator's VSGLs with exact visibility from their means) at this many "
                  "of the first frames")
      ->check(at_least(0))
      ->capture_default_str();
  add_light_vsgls_option(*app, c.light_vsgls);
  add_camera_vsgls_option(*app, c.camera_vsgls);
  add_K_option(*app, c.K);
  add_kmeans_iterations_option(*app, c.kmeans_iterations);
  add_pyramid_option(*app, c.pyramid);
  add_mipmapping_option(*app, c.mipmapping, "FIS texture path's mip chain: single-pass, blit or per-level");
  app->add_option("--out", o->out, "output root")->type_name("DIR")->capture_default_str();
  add_device_options(*app, o->device);
  return {app, [o] { return run_quality_command(*o); }};
}

}  // namespace vsgl::cli
