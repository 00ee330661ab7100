#pragma once
// What explains a run's numbers besides the numbers (DESIGN.md §9): the build (git commit, compiler,
// vsgl-bench version) and the device (name, driver, API version, timestamp period).
#include <filesystem>
#include <string>

#include <nlohmann/json_fwd.hpp>

namespace vsgl {

struct DeviceInfo;

// The commit of the source tree: VSGL_GIT_COMMIT when the build defined it, else
// `git rev-parse HEAD` in `source_dir` when that is a checkout (read-only git commands only),
// else "unknown". `dirty` is true when tracked files differ from the commit, outside results/
// (which runs write) or in results/paper and results/schema (which the tables read).
struct SourceRevision {
  std::string commit = "unknown";
  bool dirty = false;
  bool known() const { return commit != "unknown"; }
};
SourceRevision source_revision(const std::filesystem::path& source_dir);

// "GCC 12.2.0", "Clang 16.0.6", ... from the compiler's predefined macros.
std::string compiler_description();

// {"vsgl_bench_version", "git_commit", "git_dirty", "compiler", "assertions"}
nlohmann::json build_json(const std::filesystem::path& source_dir);

// A lower-case file-name-safe slug of a device name ("NVIDIA GeForce GTX 970" -> "nvidia-geforce-gtx-970").
std::string device_slug(const std::string& device_name);

}  // namespace vsgl
