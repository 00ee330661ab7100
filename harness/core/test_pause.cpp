#include "harness/core/test_pause.hpp"

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>

#include "harness/core/platform_process.hpp"

namespace vsgl {

bool test_pause_wanted(std::string_view point, const std::filesystem::path& target) {
  const char* at = std::getenv("VSGL_TEST_PAUSE_AT");
  if (at == nullptr || *at == '\0') return false;
  const std::string_view spec(at);
  const std::size_t colon = spec.find(':');
  if (colon == std::string_view::npos) return false;
  return spec.substr(0, colon) == point && spec.substr(colon + 1) == target.filename().string();
}

void test_pause_point(std::string_view point, const std::filesystem::path& target) {
  if (!test_pause_wanted(point, target)) return;
  if (const char* notify = std::getenv("VSGL_TEST_PAUSE_NOTIFY"); notify != nullptr && *notify != '\0') {
    std::ofstream(std::filesystem::path(notify), std::ios::binary | std::ios::trunc) << current_process_id() << "\n";
  }
  for (;;) std::this_thread::sleep_for(std::chrono::hours(1));  // until the test kills this process
}

}  // namespace vsgl
