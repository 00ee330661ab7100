#pragma once
// A measured sweep (DESIGN.md §10.1): every point's parameters and timing, and the growth fits read
// off them. The report (sweep_report.hpp) is built from this alone, so tests can feed it synthetic
// samples.
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/core/growth_fit.hpp"
#include "harness/formats/scene_identity.hpp"
#include "harness/sweep/sweep_axis.hpp"
#include "harness/timing/timing_runner.hpp"

namespace vsgl {

// How high-frequency a view's PDF is at a point of the pdf-sharpness axis (quality_metrics.hpp
// pdf_frequency): var(p) and the fine shares of its Haar spectrum.
struct PointPdfFrequency {
  double relative_variance = 0;
  std::vector<double> fine_share;
};

struct SweepPointResult {
  std::vector<std::size_t> value_index;  // one per axis
  std::string capture_dir;
  nlohmann::ordered_json capture;  // hashes and sizes of the capture timed (altered in memory for gamma)
  nlohmann::ordered_json config;   // the tables' config block for this point (report/run_context.hpp)
  double time_cap_s = 0;
  std::optional<double> pdf_sharpness;
  std::map<std::string, PointPdfFrequency> pdf_frequency;  // per view, on the pdf-sharpness axis
  TimingResult timing;                 // with repeated blocks, the rounds of every visit, block after block
  std::vector<uint32_t> block_rounds;  // with repeated blocks, the rounds of each visit; else empty
};

// The order the points were timed in with repeated blocks (sweep_blocks.hpp, DESIGN.md §10.1):
// every block visits every point of the axes' product once, in an order drawn from the seed.
struct SweepOrder {
  uint32_t blocks = 1;
  uint64_t seed = 0;
  std::vector<std::vector<std::size_t>> visits;  // per block, positions in the axes' product
};

// A point, or one case of it, the device cannot hold (a DeviceLimitError while recording it or
// building a generator): kept with the reason so the sweep says where it stops, instead of losing
// every other point and case.
struct BeyondDevicePoint {
  std::vector<std::size_t> value_index;  // one per axis
  std::string generator, view;           // the case; both empty: the whole point
  std::string reason;
};

struct MeasuredSweep {
  std::vector<SweepAxis> axes;
  std::vector<std::string> generators;
  SceneIdentity scene;
  int paper_table = 0;  // the paper table whose input the scene is (report/tables_run.hpp paper_table_of); 0: none
  std::optional<double> time_budget_s;
  std::vector<SweepPointResult> points;          // the points timed
  std::vector<BeyondDevicePoint> beyond_device;  // the points and cases the device cannot hold, in sweep order
  std::optional<SweepOrder> order;               // with repeated blocks (2 or more); none: one pass in axis order
  // Every point of the axes' product was reached (timed or beyond the device). False in the
  // sweep.json written after each point while the sweep runs (DESIGN.md §10.1).
  bool complete = true;
};

// One fit: a (generator, view, phase) along one axis, the other axes held at `slice`.
struct SweepFit {
  std::size_t axis = 0;
  std::vector<std::pair<std::string, std::string>> slice;  // the other axes: name, value text
  std::string generator, view, phase;                      // phase: a phase name or "total"
  std::vector<std::size_t> points;  // indices into MeasuredSweep::points that time the case, by x
  std::vector<double> x;            // growth_x of each point (0: off the log axis)
  std::optional<GrowthFit> fit;
  std::string note;  // why there is no fit (fewer than 2 points on the log axis, too few rounds)
  std::optional<GrowthExpectation> expected;
  std::optional<GrowthJudgement> judgement;
};

// "K=2, rsm=64"; "" for no other axis.
std::string slice_text(const std::vector<std::pair<std::string, std::string>>& slice);

// "gbuffer=3840x2176, K=2": each axis's value at a point.
std::string point_values_text(const std::vector<SweepAxis>& axes, const std::vector<std::size_t>& value_index);

// The samples (ms) of a case's phase or total at a point, or nullptr where the point has no such
// case (it was beyond the device there).
const std::vector<double>* find_point_samples(const SweepPointResult& point, const std::string& generator,
                                              const std::string& view, const std::string& phase);

// The samples (ms) of a case's phase or total at a point. Throws std::logic_error when absent.
const std::vector<double>& point_samples(const SweepPointResult& point, const std::string& generator,
                                         const std::string& view, const std::string& phase);

// Every fit of the sweep, axis by axis, slice by slice, case by case, phases then "total". The
// phases are those of each case as timed.
std::vector<SweepFit> sweep_fits(const MeasuredSweep& sweep, const GrowthFitOptions& options = {});

}  // namespace vsgl
