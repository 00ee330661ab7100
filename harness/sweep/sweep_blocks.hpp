#pragma once
// Repeated blocks (DESIGN.md §10.1): with 2 or more blocks, every block visits every point of the
// sweep once, in an order drawn afresh for each block from a recorded seed, and each visit times
// the point with the protocol of §9 (its own warm-up and rounds). A point's rounds are then pooled
// over its visits. Slow drift of the machine (clocks, heat, other load) thus falls on every point
// alike instead of on the points timed last, as it would when the points are timed one after the
// other in axis order; what remains of it shows as noise in the pooled rounds, not as a trend
// over the axis. One block is the plain pass in axis order.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "harness/sweep/measured_sweep.hpp"
#include "harness/sweep/sweep_point_timing.hpp"

namespace vsgl {

// One block: the points in axis order. More: each block a uniformly random permutation
// (Fisher-Yates with core/bootstrap.hpp's platform-independent draws, one engine for all blocks),
// so the same seed gives the same order everywhere. Throws std::invalid_argument for no points or
// no blocks.
SweepOrder sweep_visit_order(std::size_t points, uint32_t blocks, uint64_t seed);

// The sweep as its visits come in: each point's timed visits pooled, in axis order.
class PooledSweep {
 public:
  // `sweep`: what the sweep is of, no point yet; `points`: how many the axes' product has.
  // `record_blocks`: keep each visit's round count (block_rounds), as repeated blocks do.
  PooledSweep(MeasuredSweep sweep, std::size_t points, bool record_blocks);

  // A visit of point `point` (a position in the axes' product). The scene is the first capture's
  // had; what is beyond the device is kept from the point's first visit (the next visits meet the
  // same limits). Throws std::logic_error for a visit whose cases differ from the point's earlier
  // ones (the same setup times the same cases).
  void add(std::size_t point, SweepPointOutcome outcome);
  // The whole point was beyond the device at its first visit: the later visits are skipped.
  bool beyond_device(std::size_t point) const { return beyond_[point]; }
  // The points timed so far, pooled, in axis order.
  const MeasuredSweep& sweep() const { return sweep_; }
  MeasuredSweep take() { return std::move(sweep_); }

 private:
  MeasuredSweep sweep_;
  bool record_blocks_ = false;
  bool scene_known_ = false;
  std::vector<std::optional<SweepPointResult>> pooled_;
  std::vector<bool> visited_, beyond_;
};

}  // namespace vsgl
