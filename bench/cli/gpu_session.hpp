#pragma once
// The device part every GPU command shares: the --device and --validate options (declared once,
// here), opening the device after the whole command line has been parsed, and the validation
// verdict at the end (any validation error makes the run fail, DESIGN.md §11).
#include <memory>
#include <string>

#include <CLI/CLI.hpp>

#include "bench/cli/option_types.hpp"
#include "harness/vk/device.hpp"

namespace vsgl::cli {

struct DeviceOptions {
  std::string device;     // index or name substring; empty: the default device
  bool validate = false;  // Khronos validation layer + synchronization validation
};

// --device D and --validate, as the "device" group of `app`.
void add_device_options(CLI::App& app, DeviceOptions& options, const OptionNames& names = {});

struct GpuSession {
  std::unique_ptr<GpuContext> context;
  static GpuSession open(const DeviceOptions& options);
  Device& device() { return context->device(); }
  // Exit code after the work: kValidation when the layer reported errors, else `code`.
  int finish(int code) const;
};

}  // namespace vsgl::cli
