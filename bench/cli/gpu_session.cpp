#include "bench/cli/gpu_session.hpp"

#include <cstdio>

#include "harness/core/error.hpp"

namespace vsgl::cli {

GpuSession GpuSession::open(Args& args) {
  GpuContextOptions options;
  options.device = args.string("--device", "");
  options.instance.validation = args.flag("--validate");
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
    std::fprintf(stderr, "vsgl-bench: the Khronos validation layer reported %u error(s); the run is invalid\n",
                 errors);
    return static_cast<int>(ExitCode::kValidation);
  }
  return code;
}

}  // namespace vsgl::cli
