#pragma once
// What explains a run's numbers besides the numbers (DESIGN.md §9): the build (git commit, compiler,
// vsgl-bench version) and the device (name, driver, API version, timestamp period).
#include <string>

#include <nlohmann/json_fwd.hpp>

namespace vsgl {

struct DeviceInfo;

// {"vsgl_bench_version", "git_commit", "git_dirty", "compiler", "assertions"}: the commit and its
// dirty state as the build found them (core/build_info.hpp), never read from git at run time.
nlohmann::json build_json();

// A lower-case file-name-safe slug of a device name ("NVIDIA GeForce GTX 970" -> "nvidia-geforce-gtx-970").
std::string device_slug(const std::string& device_name);

}  // namespace vsgl
