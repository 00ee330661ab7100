#pragma once
// What `vsgl-bench sweep` says while it runs (DESIGN.md §10.1): a line for the log, or the timing's
// progress, each with the point it is about.
#include <cstddef>
#include <functional>
#include <string>
#include <utility>

#include "harness/timing/timing_runner.hpp"

namespace vsgl {

struct SweepEvent {
  std::string message;                       // a line for the log
  const TimingProgress* progress = nullptr;  // non-null during timing
  std::size_t point = 0, points = 0;
};

// The run's listener (none: nothing is said) and the number of points, for every step that speaks.
class SweepLog {
 public:
  SweepLog(std::function<void(const SweepEvent&)> on_event, std::size_t points)
      : on_event_(std::move(on_event)), points_(points) {}

  void say(const std::string& message, std::size_t point = 0) const {
    if (on_event_) on_event_(SweepEvent{message, nullptr, point, points_});
  }
  void progress(const TimingProgress& p, std::size_t point) const {
    if (on_event_) on_event_(SweepEvent{"", &p, point, points_});
  }
  // "point 2/3: " for point 1.
  std::string point_prefix(std::size_t point) const {
    return "point " + std::to_string(point + 1) + "/" + std::to_string(points_) + ": ";
  }

 private:
  std::function<void(const SweepEvent&)> on_event_;
  std::size_t points_;
};

}  // namespace vsgl
