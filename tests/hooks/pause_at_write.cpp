#include "pause_at_write.hpp"

#include <atomic>
#include <charconv>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <string>
#include <string_view>
#include <thread>

#include "harness/core/platform_environment.hpp"
#include "harness/core/platform_path.hpp"
#include "harness/core/platform_process.hpp"

namespace vsgl::test {
namespace {

struct PauseSpec {
  std::string point, name;
  unsigned write = 1;
};

// VSGL_TEST_PAUSE_AT as POINT:FILE_NAME[:N]; none when unset or malformed.
bool pause_spec(PauseSpec& out) {
  const char* at = std::getenv("VSGL_TEST_PAUSE_AT");
  if (at == nullptr || *at == '\0') return false;
  const std::string_view spec(at);
  const std::size_t colon = spec.find(':');
  if (colon == std::string_view::npos) return false;
  out.point = std::string(spec.substr(0, colon));
  std::string_view name = spec.substr(colon + 1);
  // A last ":N" that is a whole number is the write's; anything else is part of the name.
  if (const std::size_t last = name.rfind(':'); last != std::string_view::npos) {
    const std::string_view n = name.substr(last + 1);
    unsigned write = 0;
    const auto [end, error] = std::from_chars(n.data(), n.data() + n.size(), write);
    if (error == std::errc() && end == n.data() + n.size() && !n.empty()) {
      if (write == 0) return false;
      out.write = write;
      name = name.substr(0, last);
    }
  }
  out.name = std::string(name);
  return true;
}

const char* point_name(AtomicWriteStage stage) {
  switch (stage) {
    case AtomicWriteStage::kPartial: return "partial";
    case AtomicWriteStage::kComplete: return "complete";
    case AtomicWriteStage::kRenamed: return "renamed";
  }
  return "";
}

class PauseAtWrite final : public AtomicWriteObserver {
 public:
  explicit PauseAtWrite(PauseSpec spec) : spec_(std::move(spec)) {}

  void write_begins(const std::filesystem::path& target) override {
    if (spec_.name == target.filename().string()) ++writes_;  // only that name is ever counted
  }

  bool wants_partial(const std::filesystem::path& target) override {
    return wanted(AtomicWriteStage::kPartial, target);
  }

  void reached(AtomicWriteStage stage, const std::filesystem::path& target) override {
    if (!wanted(stage, target)) return;
    if (const auto notify = environment_variable("VSGL_TEST_PAUSE_NOTIFY"); notify && !notify->empty()) {
      std::ofstream(path_from_utf8(*notify), std::ios::binary | std::ios::trunc) << current_process_id() << "\n";
    }
    for (;;) std::this_thread::sleep_for(std::chrono::hours(1));  // until the test kills this process
  }

 private:
  bool wanted(AtomicWriteStage stage, const std::filesystem::path& target) const {
    return spec_.point == point_name(stage) && spec_.name == target.filename().string() &&
           writes_.load() == spec_.write;
  }

  PauseSpec spec_;
  std::atomic<unsigned> writes_{0};
};

}  // namespace

bool install_pause_at_write_from_environment() {
  PauseSpec spec;
  if (!pause_spec(spec)) return false;
  static PauseAtWrite observer(std::move(spec));  // lives as long as the process
  set_atomic_write_observer(&observer);
  return true;
}

}  // namespace vsgl::test
