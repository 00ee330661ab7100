#include "harness/core/build_info.hpp"

#include "harness/core/version.hpp"

namespace vsgl {

BuildInfo build_info() { return BuildInfo{detail::kGitCommit, detail::kGitDirty, detail::kGitNote}; }

std::string compiler_description() {
#if defined(__clang__)
  return "Clang " + std::to_string(__clang_major__) + "." + std::to_string(__clang_minor__) + "." +
         std::to_string(__clang_patchlevel__);
#elif defined(__GNUC__)
  return "GCC " + std::to_string(__GNUC__) + "." + std::to_string(__GNUC_MINOR__) + "." +
         std::to_string(__GNUC_PATCHLEVEL__);
#elif defined(_MSC_VER)
  return "MSVC " + std::to_string(_MSC_FULL_VER);
#else
  return "unknown compiler";
#endif
}

std::string version_text(const std::string& program) {
  const BuildInfo b = build_info();
  std::string text = program + " " + kVersionString + "\ncommit " + b.git_commit + (b.git_dirty ? " (dirty)" : "");
  if (!b.git_note.empty()) text += " (" + b.git_note + ")";
  return text + "\ncompiler " + compiler_description();
}

}  // namespace vsgl
