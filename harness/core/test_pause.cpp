#include "harness/core/test_pause.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

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
    const std::string pid = std::to_string(::getpid()) + "\n";
    const int fd = ::open(notify, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd >= 0) {
      (void)!::write(fd, pid.data(), pid.size());
      ::close(fd);
    }
  }
  for (;;) ::pause();
}

}  // namespace vsgl
