#include "harness/timing/run_provenance.hpp"

#include <array>
#include <cctype>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "harness/core/version.hpp"

namespace vsgl {
namespace {

// Output of a read-only command, or nullopt when it fails.
bool run_read_only(const std::string& command, std::string& out) {
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return false;
  std::array<char, 256> buffer{};
  out.clear();
  while (std::fgets(buffer.data(), static_cast<int>(buffer.size()), pipe) != nullptr) out += buffer.data();
  return pclose(pipe) == 0;
}

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace

SourceRevision source_revision(const std::filesystem::path& source_dir) {
  SourceRevision rev;
#ifdef VSGL_GIT_COMMIT
  rev.commit = VSGL_GIT_COMMIT;
  return rev;
#else
  std::error_code ec;
  if (!std::filesystem::exists(source_dir / ".git", ec)) return rev;
  const std::string git = "git --no-optional-locks -C " + shell_quote(source_dir.string()) + " ";
  std::string out;
  if (!run_read_only(git + "rev-parse HEAD 2>/dev/null", out)) return rev;
  while (!out.empty() && std::isspace(static_cast<unsigned char>(out.back()))) out.pop_back();
  if (out.size() != 40) return rev;
  rev.commit = out;
  // --no-optional-locks: status must not refresh (write) the index of someone's checkout.
  // The results tree is what runs write, so a run that regenerates committed results (the
  // second step of ci/lavapipe-results.sh, say) would otherwise call its own commit dirty; only
  // the results the tables read, the paper's numbers and the schema, count as inputs.
  const std::string status = git + "status --porcelain --untracked-files=no -- ";
  std::string inputs;
  if (run_read_only(status + "':(exclude)results' . 2>/dev/null", out) &&
      run_read_only(status + "results/paper results/schema 2>/dev/null", inputs)) {
    rev.dirty = !out.empty() || !inputs.empty();
  }
  return rev;
#endif
}

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

nlohmann::json build_json(const std::filesystem::path& source_dir) {
  const SourceRevision rev = source_revision(source_dir);
  return nlohmann::json{{"vsgl_bench_version", kVersionString},
                        {"git_commit", rev.commit},
                        {"git_dirty", rev.dirty},
                        {"compiler", compiler_description()},
#ifdef NDEBUG
                        {"assertions", false},
#else
                        {"assertions", true},
#endif
  };
}

std::string device_slug(const std::string& device_name) {
  std::string slug;
  for (char c : device_name) {
    const auto u = static_cast<unsigned char>(c);
    if (std::isalnum(u)) slug += static_cast<char>(std::tolower(u));
    else if (!slug.empty() && slug.back() != '-') slug += '-';
  }
  while (!slug.empty() && slug.back() == '-') slug.pop_back();
  return slug.empty() ? "device" : slug;
}

}  // namespace vsgl
