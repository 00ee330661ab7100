// `vsgl-bench verify --capture DIR`: the correctness run (DESIGN.md §11) a user does on their own GPU:
// the FIS generators pass by pass, then the k-means generators step by step.
// One line per check with its measured error and tolerance; exit 1 if any check fails.
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bench/cli/commands.hpp"
#include "bench/cli/generator_options.hpp"
#include "bench/cli/gpu_session.hpp"
#include "harness/capture/capture_files.hpp"
#include "harness/core/platform_path.hpp"
#include "harness/core/atomic_file.hpp"
#include "harness/core/error.hpp"
#include "harness/formats/verify_model.hpp"
#include "harness/verify/fis_verification.hpp"
#include "harness/verify/kmeans_verification.hpp"
#include "harness/vk/device_info.hpp"

namespace vsgl::cli {

namespace {

struct VerifyOptions {
  std::string capture;
  std::optional<std::string> json;
  VerifyConfig config;
  std::vector<std::string> pyramids{"texture", "buffer"};
  DeviceOptions device;
};

// One check as the verify document holds it.
VerifyCheck document_check(const CheckResult& r) {
  VerifyCheck c;
  c.view = r.view;
  c.generator = r.generator;
  c.check = r.check;
  c.kind = r.measurement ? VerifyCheckKind::kMeasurement : VerifyCheckKind::kCheck;
  c.measured = r.measured;
  if (r.measurement) c.expected = r.expected;
  else c.tolerance = r.tolerance;
  c.passed = r.passed();
  c.detail = r.detail;
  return c;
}

int run_verify(VerifyOptions& o) {
  const std::string* capture_dir = &o.capture;
  const auto& json_path = o.json;
  VerifyConfig& config = o.config;
  config.pyramids.clear();
  for (const auto& item : o.pyramids) config.pyramids.push_back(*parse_pyramid_path(item));
  GpuSession session = GpuSession::open(o.device);

  const Capture capture = load_capture(path_from_utf8(*capture_dir));
  std::printf("verify %s (scene %s) on %s\n", capture_dir->c_str(), capture.meta.scene.c_str(),
              session.device().info().name.c_str());
  auto results = verify_fis(session.device(), capture, config);
  const auto kmeans = verify_kmeans(session.device(), capture, config);
  results.insert(results.end(), kmeans.begin(), kmeans.end());
  uint32_t failed = 0;
  for (const auto& r : results) {
    std::printf("%s\n", format_check(r).c_str());
    failed += r.passed() ? 0 : 1;
  }
  std::printf("%zu checks, %u failed\n", results.size(), failed);
  if (json_path) {
    VerifyDocument doc{*capture_dir, capture.meta.scene, device_record(session.device().info()), {}};
    for (const auto& r : results) doc.checks.push_back(document_check(r));
    write_text_atomic(*json_path, verify_file_text(doc));
  }
  return session.finish(failed == 0 ? 0 : static_cast<int>(ExitCode::kFailure));
}

}  // namespace

Command add_verify_command(CLI::App& parent) {
  CLI::App* app = parent.add_subcommand(
      "verify",
      "the correctness run to do on your own GPU (DESIGN.md §11): all four generators on both views against their "
      "CPU references, FIS pass by pass (moments, pyramid, sampler, Eq. 1 / Eq. 3, VSGLs, power, sample histogram), "
      "k-means step by step (assignment, sort and ranges, per-cluster sums, total power, membership); one line per "
      "check with its error and tolerance, exit 1 if any fails");
  auto o = std::make_shared<VerifyOptions>();
  app->add_option("--capture", o->capture, "capture directory (written by `vsgl-bench record`)")
      ->required()
      ->type_name("DIR");
  add_optional(*app, "--json", o->json, "also write the checks as JSON")->type_name("FILE");
  add_camera_vsgls_option(*app, o->config.camera_vsgls);
  add_light_vsgls_option(*app, o->config.light_vsgls);
  add_K_option(*app, o->config.K);
  add_list_option(*app, "--pyramid", o->pyramids, "FIS pyramid paths to check: texture, buffer", pyramid_name());
  add_mipmapping_option(*app, o->config.mipmapping,
                        "texture path's mip strategy for the generator checks (the pyramid check covers all three): "
                        "single-pass, blit or per-level");
  add_device_options(*app, o->device);
  return {app, [o] { return run_verify(*o); }};
}

}  // namespace vsgl::cli
