#include "bench/cli/gpu_session.hpp"

#include <cstdio>

#include "harness/core/error.hpp"
#include "harness/core/program_name.hpp"

namespace vsgl::cli {

void add_device_options(CLI::App& app, DeviceOptions& options, const OptionNames& names) {
  CLI::App* group = app.add_option_group("device", "device selection");
  group->add_option(names("device"), options.device,
                    "device index or case-insensitive name substring (see `vsgl-bench devices`)")
      ->default_str("first discrete GPU, else integrated, virtual, CPU");
  group->add_flag(names("validate"), options.validate,
                  "Khronos validation layer with synchronization validation; any validation error fails the run "
                  "(exit 5)");
}

GpuSession GpuSession::open(const DeviceOptions& device_options) {
  GpuContextOptions options;
  options.device = device_options.device;
  options.instance.validation = device_options.validate;
  GpuSession s;
  s.context = std::make_unique<GpuContext>(options);
  const auto& info = s.context->device().info();
  std::fprintf(stderr, "device: [%u] %s (%s)%s\n", info.index, info.name.c_str(), info.driver_name.c_str(),
               options.instance.validation ? ", validation on" : "");
  return s;
}

int GpuSession::finish(int code) const {
  const uint32_t errors = context->instance().validation_errors();
  if (errors > 0) {
    std::fprintf(stderr, "%s: the Khronos validation layer reported %u error(s); the run is invalid\n",
                 program_name().c_str(), errors);
    return static_cast<int>(ExitCode::kValidation);
  }
  return code;
}

}  // namespace vsgl::cli
