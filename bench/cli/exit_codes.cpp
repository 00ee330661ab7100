#include "bench/cli/exit_codes.hpp"

#include <array>
#include <cstdio>
#include <exception>
#include <filesystem>

#include "harness/core/program_name.hpp"
#include "harness/vk/vk_check.hpp"

namespace vsgl::cli {

namespace {
constexpr std::array kExitCodes{
    ExitCodeMeaning{ExitCode::kOk, "ok"},
    ExitCodeMeaning{ExitCode::kFailure, "a check failed (verify; compare: a verdict listed in --fail-on)"},
    ExitCodeMeaning{ExitCode::kUsage, "bad command line"},
    ExitCodeMeaning{ExitCode::kBadInput, "bad input (capture, run JSON, glTF file, parameter; incomparable runs)"},
    ExitCodeMeaning{ExitCode::kDevice, "device problem (none usable, no timestamps, out of memory, device lost)"},
    ExitCodeMeaning{ExitCode::kValidation, "validation errors (the Khronos validation layer, --validate)"},
    ExitCodeMeaning{ExitCode::kInternal, "internal error: a bug; please report it with the command line"},
};
}  // namespace

std::span<const ExitCodeMeaning> exit_code_table() { return kExitCodes; }

std::string exit_codes_help() {
  std::string out = "exit codes:\n";
  for (const auto& e : kExitCodes) {
    char line[160];
    std::snprintf(line, sizeof line, "  %-3d %s\n", static_cast<int>(e.code), e.meaning);
    out += line;
  }
  return out;
}

int run_reporting_errors(const std::function<int()>& body) {
  const char* program = program_name().c_str();
  try {
    return body();
  } catch (const UsageError& e) {
    std::fprintf(stderr, "%s: %s (see %s --help)\n", program, e.what(), program);
    return static_cast<int>(ExitCode::kUsage);
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s: bad input: %s\n", program, e.what());
    return static_cast<int>(ExitCode::kBadInput);
  } catch (const DeviceError& e) {
    std::fprintf(stderr, "%s: device: %s\n", program, e.what());
    return static_cast<int>(ExitCode::kDevice);
  } catch (const VulkanError& e) {
    std::fprintf(stderr, "%s: Vulkan: %s\n", program, e.what());
    return static_cast<int>(ExitCode::kDevice);
  } catch (const std::filesystem::filesystem_error& e) {  // a path the user gave: unreadable, unwritable
    std::fprintf(stderr, "%s: bad input: %s\n", program, e.what());
    return static_cast<int>(ExitCode::kBadInput);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: internal error: %s; please report it with the command line\n", program, e.what());
    return static_cast<int>(ExitCode::kInternal);
  }
}

}  // namespace vsgl::cli
