#pragma once
// The device part every GPU subcommand shares: --device and --validate, and the validation
// verdict at the end (any validation error makes the run fail, DESIGN.md §11).
#include <memory>

#include "bench/cli/args.hpp"
#include "harness/vk/device.hpp"

namespace vsgl::cli {

struct GpuSession {
  std::unique_ptr<GpuContext> context;
  static GpuSession open(Args& args);
  Device& device() { return context->device(); }
  // Exit code after the work: kValidation when the layer reported errors, else `code`.
  int finish(int code) const;
};

}  // namespace vsgl::cli
