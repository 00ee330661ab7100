#include "harness/sweep/sweep_blocks.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

#include "harness/core/bootstrap.hpp"
#include "harness/core/statistics.hpp"

namespace vsgl {
namespace {

// How strongly a visit's stop says the point was cut short: the pooled point's reason is its
// visits' strongest (a time cap over the round limit over the noise target met).
int stop_strength(const std::string& reason) {
  if (reason == "time_cap") return 2;
  if (reason == "max_repetitions") return 1;
  return 0;
}

// The visit's rounds appended to the pooled point's, case by case, phase by phase.
void pool_visit(SweepPointResult& into, SweepPointResult&& visit) {
  TimingResult& a = into.timing;
  TimingResult& b = visit.timing;
  if (a.cases.size() != b.cases.size())
    throw std::logic_error("sweep: a later visit of a point timed " + std::to_string(b.cases.size()) +
                           " cases, the first " + std::to_string(a.cases.size()));
  for (std::size_t c = 0; c < a.cases.size(); ++c) {
    CaseTiming& x = a.cases[c];
    CaseTiming& y = b.cases[c];
    if (x.generator != y.generator || x.view != y.view || x.phases != y.phases)
      throw std::logic_error("sweep: a later visit of a point timed " + y.generator + " " + y.view +
                             " where the first timed " + x.generator + " " + x.view);
    for (std::size_t p = 0; p < x.phase_ms.size(); ++p)
      x.phase_ms[p].insert(x.phase_ms[p].end(), y.phase_ms[p].begin(), y.phase_ms[p].end());
    x.total_ms.insert(x.total_ms.end(), y.total_ms.begin(), y.total_ms.end());
  }
  a.repetitions += b.repetitions;
  a.timed_seconds += b.timed_seconds;
  if (stop_strength(b.stop_reason) > stop_strength(a.stop_reason)) a.stop_reason = b.stop_reason;
  // The noise of the pooled rounds, as §9 defines it for one run: the largest IQR/median of a total.
  a.worst_noise = 0;
  for (const CaseTiming& c : a.cases) a.worst_noise = std::max(a.worst_noise, relative_iqr(summarize(c.total_ms)));
  into.time_cap_s += visit.time_cap_s;  // the point's share of the budget, over its visits
  into.block_rounds.push_back(b.repetitions);
}

}  // namespace

SweepOrder sweep_visit_order(std::size_t points, uint32_t blocks, uint64_t seed) {
  if (points == 0) throw std::invalid_argument("a sweep has no point to visit");
  if (blocks == 0) throw std::invalid_argument("a sweep needs at least one block");
  SweepOrder order;
  order.blocks = blocks;
  order.seed = seed;
  BootstrapSampler draw(seed);
  for (uint32_t b = 0; b < blocks; ++b) {
    std::vector<std::size_t> visit(points);
    std::iota(visit.begin(), visit.end(), std::size_t{0});
    if (blocks > 1)
      for (std::size_t i = points - 1; i > 0; --i) std::swap(visit[i], visit[draw.index(i + 1)]);
    order.visits.push_back(std::move(visit));
  }
  return order;
}

PooledSweep::PooledSweep(MeasuredSweep sweep, std::size_t points, bool record_blocks)
    : sweep_(std::move(sweep)),
      record_blocks_(record_blocks),
      pooled_(points),
      visited_(points, false),
      beyond_(points, false) {}

void PooledSweep::add(std::size_t point, SweepPointOutcome outcome) {
  if (!scene_known_ && outcome.scene) {
    sweep_.scene = std::move(*outcome.scene);
    sweep_.paper_table = outcome.paper_table;
    scene_known_ = true;
  }
  if (!visited_[point])
    for (BeyondDevicePoint& b : outcome.beyond_device) sweep_.beyond_device.push_back(std::move(b));
  visited_[point] = true;
  if (!outcome.timed) {
    beyond_[point] = true;
    return;
  }
  if (pooled_[point]) {
    pool_visit(*pooled_[point], std::move(*outcome.timed));
  } else {
    pooled_[point] = std::move(*outcome.timed);
    if (record_blocks_) pooled_[point]->block_rounds = {pooled_[point]->timing.repetitions};
  }
  sweep_.points.clear();
  for (const std::optional<SweepPointResult>& p : pooled_)
    if (p) sweep_.points.push_back(*p);
}

}  // namespace vsgl
