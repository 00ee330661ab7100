// Every generator (all of generator_names(), both views of the tiny scene) once under the Khronos
// validation layer's GPU-assisted mode (VK_VALIDATION_FEATURE_ENABLE_GPU_ASSISTED_EXT): the layer
// instruments every shader so that an out-of-bounds or uninitialized descriptor access on the
// device becomes a validation error (DESIGN.md §11). A positive control first provokes one, so that
// the test proves the mode works on this driver; where the layer cannot set GPU-assisted
// validation up on the driver, the test is skipped with the layer's own message.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "gpu_test.hpp"
#include "tiny_capture.hpp"
#include "harness/vk/buffer.hpp"
#include "kernels/include/interface/testing.h"
#include "harness/vk/command_stream.hpp"
#include "harness/vk/compute_pipeline.hpp"
#include "harness/vk/device.hpp"
#include "harness/generators/device_view.hpp"
#include "harness/generators/generator_registry.hpp"
#include "harness/generators/vsgl_generator.hpp"

namespace vsgl {
namespace {

using WorkloadPush = gpu::TestWorkloadPush;  // kernels/test_workload.comp

GpuContext& gpu_av_context() {
  static std::unique_ptr<GpuContext> ctx = [] {
    GpuContextOptions options;
    options.instance.validation = true;
    options.instance.gpu_assisted = true;
    options.instance.quiet_validation = true;  // the control's error is expected; all are checked below
    const char* env = std::getenv("VSGL_TEST_DEVICE");
    options.device = env != nullptr ? env : "llvmpipe";
    return std::make_unique<GpuContext>(options);
  }();
  return *ctx;
}

// The layer's messages that say GPU-assisted validation could not be set up (it then runs
// without it): "Setup Error", "GPU-Assisted Validation disabled", "... is not supported".
std::string setup_problem(const Instance& instance) {
  for (const std::string& m : instance.validation_messages())
    if (m.find("GPU-Assisted") != std::string::npos &&
        (m.find("Setup Error") != std::string::npos || m.find("disabled") != std::string::npos ||
         m.find("not supported") != std::string::npos || m.find("requires") != std::string::npos))
      return m;
  return {};
}

std::string all_messages(const Instance& instance) {
  std::string text;
  for (const std::string& m : instance.validation_messages()) text += m + "\n";
  return text;
}

TEST(GpuAssistedValidation, GeneratorsMakeNoOutOfBoundsAccess) {
  if (!test::test_validation()) GTEST_SKIP() << "VSGL_TEST_VALIDATION=off: no validation layer";
  GpuContext& ctx = gpu_av_context();
  Device& dev = ctx.device();
  Instance& instance = ctx.instance();
  if (const std::string problem = setup_problem(instance); !problem.empty())
    GTEST_SKIP() << "the validation layer cannot do GPU-assisted validation on " << dev.info().name << ": " << problem;

  // Positive control: a dispatch that writes 1024 values into a buffer of 64 values.
  {
    Buffer small(dev, 64 * sizeof(uint32_t), MemoryUsage::kDeviceLocal, "test.gpu_av.too_small");
    ComputePipeline pipeline(dev, {"test_workload.comp", 1, sizeof(WorkloadPush), {{0, 64}}});
    BindingSet set(dev, pipeline, {small}, "test.gpu_av.set");
    dev.submit_and_wait([&](VkCommandBuffer cmd) {
      CommandStream stream(cmd);
      stream.dispatch(pipeline, set, WorkloadPush{1024, 1}, 1024 / 64);
    });
  }
  if (const std::string problem = setup_problem(instance); !problem.empty())
    GTEST_SKIP() << "the validation layer cannot do GPU-assisted validation on " << dev.info().name << ": " << problem;
  if (instance.validation_errors() == 0)
    GTEST_SKIP() << "GPU-assisted validation is on but did not report the control's out-of-bounds write on "
                 << dev.info().name << " (the layer checks no buffer bounds on this driver); messages:\n"
                 << all_messages(instance);
  for (const std::string& m : instance.validation_messages())
    if (m.rfind("validation error", 0) == 0) {
      std::printf("positive control reported, as it must: %s\n", m.substr(0, 400).c_str());
      break;
    }
  instance.clear_validation_messages();

  const auto start = std::chrono::steady_clock::now();  // reported, never judged
  const Capture capture = test::record_tiny_with_flux_pdf(dev);
  for (const ViewKind kind : {ViewKind::kCamera, ViewKind::kLight}) {
    const DeviceView view = upload_view(dev, capture, kind);
    for (const std::string& name : generator_names()) {
      SCOPED_TRACE(name + (kind == ViewKind::kCamera ? " camera view" : " light view"));
      GeneratorConfig cfg;
      cfg.vsgl_count = kind == ViewKind::kCamera ? 48 : 24;
      const auto generator = make_generator(name, dev, view, cfg);
      run_untimed(dev, *generator);
      EXPECT_EQ(instance.validation_errors(), 0u) << all_messages(instance);
      instance.clear_validation_messages();
    }
  }
  std::printf("%zu generators x 2 views under GPU-assisted validation in %.1f s\n", generator_names().size(),
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
}

}  // namespace
}  // namespace vsgl
