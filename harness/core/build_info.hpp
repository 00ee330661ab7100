#pragma once
// What the program was built from, fixed at build time (cmake/BuildInfo.cmake): the commit of the
// source tree, whether tracked files differed from it, and the compiler. Nothing is asked of git
// at run time, so a binary copied to another machine still names its commit (DESIGN.md §9).
#include <string>

namespace vsgl {

namespace detail {
extern const char* const kGitCommit;  // generated
extern const bool kGitDirty;
extern const char* const kGitNote;
}  // namespace detail

struct BuildInfo {
  std::string git_commit;  // the full commit id, or "unknown"
  bool git_dirty = false;  // tracked sources or results/paper, results/schema differed from it
  std::string git_note;    // why the commit is unknown (or how it was given); empty when git told
};
BuildInfo build_info();

// "GCC 12.2.0", "Clang 16.0.6", ... from the compiler's predefined macros.
std::string compiler_description();

// The build's part of the `--version` text (bench/cli/program_version.hpp adds the Vulkan headers
// and the licence): "<program> 0.1.0", "commit <id>[ (dirty)]" with the reason when the commit is
// unknown, "compiler <compiler>", one a line.
std::string version_text(const std::string& program);

}  // namespace vsgl
