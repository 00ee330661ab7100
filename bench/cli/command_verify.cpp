// `vsgl-bench verify --capture DIR`: the correctness run (DESIGN.md §11) a user does on their own GPU:
// the FIS generators pass by pass, then the k-means generators step by step.
// One line per check with its measured error and tolerance; exit 1 if any check fails.
#include <cstdio>
#include <nlohmann/json.hpp>

#include "bench/cli/commands.hpp"
#include "bench/cli/generator_options.hpp"
#include "bench/cli/gpu_session.hpp"
#include "harness/capture/capture_files.hpp"
#include "harness/core/atomic_file.hpp"
#include "harness/core/error.hpp"
#include "harness/verify/fis_verification.hpp"
#include "harness/verify/kmeans_verification.hpp"

namespace vsgl::cli {

int run_verify(Args& args) {
  const auto capture_dir = args.value("--capture");
  const auto json_path = args.value("--json");
  VerifyConfig config;
  config.camera_vsgls = args.u32("--camera-vsgls", config.camera_vsgls, 1);
  config.light_vsgls = args.u32("--light-vsgls", config.light_vsgls, 1);
  config.K = args.positive_float("--K", config.K);
  config.pyramids.clear();
  for (const auto& item : args.list("--pyramid", "texture,buffer")) config.pyramids.push_back(parse_pyramid_option(item));
  if (const auto m = args.value("--mipmapping")) {
    config.mipmapping = parse_mip_strategy(*m);
    if (!config.mipmapping) throw UsageError("--mipmapping takes single-pass, blit or per-level, not '" + *m + "'");
  }
  GpuSession session = GpuSession::open(args);
  args.finish();
  if (!capture_dir) throw UsageError("verify needs --capture DIR (record one with `vsgl-bench record`)");

  const Capture capture = load_capture(*capture_dir);
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
    nlohmann::json out{{"capture", *capture_dir}, {"scene", capture.meta.scene},
                       {"device", to_json(session.device().info())}, {"checks", nlohmann::json::array()}};
    for (const auto& r : results) out["checks"].push_back(to_json(r));
    write_text_atomic(*json_path, out.dump(2) + "\n");
  }
  return session.finish(failed == 0 ? 0 : static_cast<int>(ExitCode::kFailure));
}

}  // namespace vsgl::cli
