#pragma once
// Where a run's files go: a folder named after the device. What explains a run's numbers besides
// the numbers (the device, the build, the run) is formats/run_header.hpp.
#include <string>

namespace vsgl {

// A lower-case file-name-safe slug of a device name ("NVIDIA GeForce GTX 970" -> "nvidia-geforce-gtx-970").
std::string device_slug(const std::string& device_name);

}  // namespace vsgl
