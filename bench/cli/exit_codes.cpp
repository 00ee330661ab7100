#include "bench/cli/exit_codes.hpp"

#include <cstdio>
#include <exception>

#include "harness/core/error.hpp"
#include "harness/vk/vk_check.hpp"

namespace vsgl::cli {

int run_reporting_errors(const char* program, const std::function<int()>& body) {
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
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: error: %s\n", program, e.what());
    return static_cast<int>(ExitCode::kFailure);
  }
}

}  // namespace vsgl::cli
