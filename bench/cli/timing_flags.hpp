#pragma once
// The timing protocol's command-line overrides (--quick, --warmup, --repetitions,
// --max-repetitions, --noise-target, --time-cap), applied the same way by `tables` and `sweep`
// over the device kind's defaults (DESIGN.md §9).
#include <algorithm>

#include "harness/timing/timing_runner.hpp"

namespace vsgl::cli {

// `Flags` is a command's options struct with those members. --quick first (3 repetitions: the
// protocol's shape for CI, not its statistics), then each flag given replaces its default;
// --repetitions raises the maximum to at least itself.
template <typename Flags>
void apply_timing_flags(const Flags& c, TimingOptions& t) {
  if (c.quick) {
    t.min_repetitions = 3;
    t.max_repetitions = 3;
  }
  if (c.warmup) t.warmup = *c.warmup;
  if (c.repetitions) {
    t.min_repetitions = *c.repetitions;
    t.max_repetitions = std::max(t.max_repetitions, t.min_repetitions);
  }
  if (c.max_repetitions) t.max_repetitions = *c.max_repetitions;
  if (c.noise_target) t.noise_target = *c.noise_target;
  if (c.time_cap) t.time_cap_s = *c.time_cap;
}

}  // namespace vsgl::cli
