#include "harness/core/test_pause.hpp"

#include <atomic>
#include <charconv>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>

#include "harness/core/platform_environment.hpp"
#include "harness/core/platform_path.hpp"
#include "harness/core/platform_process.hpp"

namespace vsgl {
namespace {

// The writes so far of the file VSGL_TEST_PAUSE_AT names (only that name is ever counted).
std::atomic<unsigned> g_writes{0};

struct PauseSpec {
  std::string_view point, name;
  unsigned write = 1;
};

// VSGL_TEST_PAUSE_AT as POINT:FILE_NAME[:N]; none when unset or malformed.
bool pause_spec(PauseSpec& out) {
  const char* at = std::getenv("VSGL_TEST_PAUSE_AT");
  if (at == nullptr || *at == '\0') return false;
  const std::string_view spec(at);
  const std::size_t colon = spec.find(':');
  if (colon == std::string_view::npos) return false;
  out.point = spec.substr(0, colon);
  out.name = spec.substr(colon + 1);
  // A last ":N" that is a whole number is the write's; anything else is part of the name.
  if (const std::size_t last = out.name.rfind(':'); last != std::string_view::npos) {
    const std::string_view n = out.name.substr(last + 1);
    unsigned write = 0;
    const auto [end, error] = std::from_chars(n.data(), n.data() + n.size(), write);
    if (error == std::errc() && end == n.data() + n.size() && !n.empty()) {
      if (write == 0) return false;
      out.write = write;
      out.name = out.name.substr(0, last);
    }
  }
  return true;
}

}  // namespace

void test_pause_count_write(const std::filesystem::path& target) {
  PauseSpec spec;
  if (pause_spec(spec) && spec.name == target.filename().string()) ++g_writes;
}

bool test_pause_wanted(std::string_view point, const std::filesystem::path& target) {
  PauseSpec spec;
  if (!pause_spec(spec)) return false;
  return spec.point == point && spec.name == target.filename().string() && g_writes.load() == spec.write;
}

void test_pause_point(std::string_view point, const std::filesystem::path& target) {
  if (!test_pause_wanted(point, target)) return;
  if (const auto notify = environment_variable("VSGL_TEST_PAUSE_NOTIFY"); notify && !notify->empty()) {
    std::ofstream(path_from_utf8(*notify), std::ios::binary | std::ios::trunc) << current_process_id() << "\n";
  }
  for (;;) std::this_thread::sleep_for(std::chrono::hours(1));  // until the test kills this process
}

}  // namespace vsgl
