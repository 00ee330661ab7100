// `vsgl-bench devices [--json]`: every Vulkan device, its driver, API version and timestamp
// support, and which one a run would use by default.
#include <cstdio>
#include <memory>
#include <string>

#include "bench/cli/commands.hpp"
#include "harness/generators/device_support.hpp"
#include "harness/vk/device_info.hpp"
#include "harness/core/error.hpp"
#include "harness/formats/devices_model.hpp"
#include "harness/vk/instance.hpp"

namespace vsgl::cli {

namespace {

int run_devices(bool json) {
  Instance instance;
  const auto devices = enumerate_devices(instance.get());
  int default_index = -1;
  try {
    default_index = static_cast<int>(select_device(devices, "").index);
  } catch (const DeviceError&) {
    default_index = -1;
  }
  if (json) {
    // Each device as every document records it, and per generator and mip strategy whether it runs there.
    DevicesDocument doc{default_index, {}};
    for (const auto& d : devices) doc.devices.push_back({device_record(d), device_support(d)});
    std::fputs(devices_file_text(doc).c_str(), stdout);
  } else {
    std::printf("%zu Vulkan device(s):\n%s", devices.size(), describe_devices_text(devices).c_str());
    if (default_index >= 0)
      std::printf("default device: [%d] (discrete GPU first, then integrated, virtual, CPU); choose another "
                  "with --device INDEX or --device NAME-SUBSTRING\n",
                  default_index);
    else
      std::printf("no usable device\n");
  }
  return default_index >= 0 ? 0 : static_cast<int>(ExitCode::kDevice);
}

}  // namespace

Command add_devices_command(CLI::App& parent) {
  CLI::App* app = parent.add_subcommand(
      "devices", "every Vulkan device: type, driver, API version, timestamp valid bits and period, subgroup size, why "
                 "a device is unusable; and the default (first discrete GPU, else integrated, virtual, CPU)");
  auto json = std::make_shared<bool>(false);
  app->add_flag("--json", *json, "print JSON instead of text");
  return {app, [json] { return run_devices(*json); }};
}

}  // namespace vsgl::cli
