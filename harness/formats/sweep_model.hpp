#pragma once
// The sweep JSON of DESIGN.md §10.1 (results/schema/sweep.schema.json) as one typed model, read
// (read_sweep_model) and written (to_json) through it alone: `vsgl-bench sweep` fills it from the
// measured sweep (sweep/sweep_document.hpp) and writes OUT/sweep.json from it; the dashboard's
// scaling section (compare/dashboard_scaling.hpp) reads it. Every committed sweep.json reads and
// writes back byte for byte. As table_model.hpp does for table JSON, the objects the harness
// writes from elsewhere (device, build, run, each point's capture and config) are kept whole.
//
// What the reader checks beyond types is what the page relies on: every fit's axis, points and
// case exist, each growth_x belongs to its point, and no time is zero, negative or not finite.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/formats/claim.hpp"
#include "harness/formats/run_header.hpp"
#include "harness/formats/scene_identity.hpp"
#include "harness/formats/timing_statistics.hpp"

namespace vsgl {

// The sweep schema version this build reads and writes.
inline constexpr int kSweepSchemaVersion = 1;

// One series' statistics at a point (ms), as written beside its samples.
struct SweepPhaseTiming {
  std::string name;
  TimingStatistics stats;
};

// One generator on one view at a point.
struct SweepCase {
  std::string generator;
  std::string view;  // "camera_view", "light_view"
  uint32_t dispatches = 0;
  std::vector<SweepPhaseTiming> phases;
  TimingStatistics total;

  // The phase's stats, or the total's for "total"; nullptr when the case has no such phase.
  const TimingStatistics* find(const std::string& phase) const;
};

struct SweepAxisValue {
  std::string text;                       // as given on the command line ("16", "96x64", "0.5")
  double value = 0;                       // the parameter
  double growth_x = 0;                    // what the fits use as x; 0: off the log axis (γ = 0)
  std::optional<uint32_t> width, height;  // a G-buffer size's
};

struct SweepAxisModel {
  std::string name;            // "vsgls", "K", "pdf-sharpness", ...
  std::string spec;            // "vsgls=256:16384:x2"
  std::string symbol;          // the growth text's symbol ("N")
  std::string growth_x_title;  // "N (VSGLs per view)"
  std::vector<SweepAxisValue> values;
};

// How the timing of a point stopped (timing/timing_runner.hpp TimingResult).
struct SweepPointTiming {
  double time_cap_s = 0;
  uint32_t repetitions = 0;
  double timed_seconds = 0;
  std::string stop_reason;
  double worst_noise = 0;
  // With repeated blocks, the rounds of each visit in block order (they sum to repetitions); empty:
  // one visit (absent from the file).
  std::vector<uint32_t> block_rounds;
};

// The visit order of repeated blocks ("order"; absent: one pass in axis order).
struct SweepOrderModel {
  uint32_t blocks = 0;
  uint64_t seed = 0;
  std::vector<std::vector<std::size_t>> visits;  // per block, positions in the axes' product
};

// How high-frequency a view's PDF is at a point of the pdf-sharpness axis: var(p) and the fine
// shares of its Haar spectrum (DESIGN.md §11a).
struct SweepPdfFrequency {
  double relative_variance = 0;
  std::vector<double> fine_share;
};

struct SweepPdfSharpness {
  double gamma = 0;
  std::string definition;                                            // of the transform, in words
  std::vector<std::pair<std::string, SweepPdfFrequency>> frequency;  // per view, in the file's order
};

struct SweepPoint {
  std::size_t index = 0;
  std::vector<std::size_t> value_index;  // per axis, into SweepAxisModel::values
  std::string capture_dir;
  nlohmann::ordered_json capture = nlohmann::ordered_json::object();  // hashes and sizes of the capture timed
  nlohmann::ordered_json config = nlohmann::ordered_json::object();   // the tables' config block
  SweepPointTiming timing;
  std::vector<SweepCase> cases;
  std::optional<SweepPdfSharpness> pdf_sharpness;  // on a pdf-sharpness axis

  // nullptr when the point did not time the generator on the view.
  const SweepCase* find(const std::string& generator, const std::string& view) const;
};

// A point the device could not hold, not timed ("beyond_device"; absent in older files: none).
struct SweepBeyondDevice {
  std::vector<std::size_t> value_index;  // per axis, into SweepAxisModel::values
  std::string generator, view;           // the case; both empty: the whole point
  std::string reason;
};

struct SweepGrowth {
  double slope = 0;
  double low = 0, high = 0;  // the bootstrap interval
  double confidence = 0;
  std::size_t resamples = 0;
  std::size_t points = 0;  // on the log axis
  std::string text;        // "cost ∝ N^0.98 [0.95, 1.01]"
};

struct SweepExpected {
  double slope = 0;
  double tolerance = 0;
  std::string why;
};

// One fit: a (generator, view, phase) along one axis, the other axes held at `slice`.
struct SweepFitModel {
  std::size_t axis = 0;                                    // into SweepModel::axes
  std::vector<std::pair<std::string, std::string>> slice;  // the other axes: name, value text
  std::string generator, view, phase;                      // phase: a phase name or "total"
  std::vector<std::size_t> points;                         // into SweepModel::points, by x
  std::vector<double> growth_x;                            // per point; 0: off the log axis
  std::optional<SweepGrowth> growth;                       // none: no fit, `note` says why
  std::string note;
  std::optional<SweepExpected> expected;
  // The growth's interval against the expected band (core/growth_fit.hpp's judge_growth); none:
  // no expectation. The file words it "consistent", "faster" or "slower" (verdict_word) and
  // "flagged"; read back, it is judged again from "growth" and "expected", which must agree.
  std::optional<ClaimVerdict> verdict;
  std::string judgement;  // the verdict in words; "" when none

  // The interval excludes the expectation.
  bool flagged() const { return verdict && verdict->fails(); }
  // "consistent", "faster", "slower"; "" when there is no verdict.
  std::string verdict_word() const;
};

// A case's change of its median total from the reference γ, with its bootstrap interval.
struct SweepClaimChange {
  double gamma = 0;
  std::size_t point = 0;  // into SweepModel::points
  double change = 0;
  double low = 0, high = 0;
  // A FIS case's TOST p-values at the band (absent at the reference γ, for k-means, and in files
  // written before the equivalence test).
  std::optional<double> p_equivalent, p_outside;
};

// The rule of a FIS case's equivalence verdict (sweep/pdf_independence.hpp): the TOST's p-values
// across γ against their Holm levels.
inline constexpr const char* kEquivalenceRule =
    "TOST across γ, Holm-corrected: equivalent when p_equivalent <= its level, not equivalent when p_outside <= "
    "its level";

// A FIS case's equivalence verdict across γ, Holm-corrected across the FIS cases. The file words
// its outcome "equivalent" (holds), "not equivalent" (does not hold) or "inconclusive".
struct SweepClaimEquivalence {
  double p_equivalent = 1, p_outside = 1;
  double level_equivalent = 0, level_outside = 0;
  ClaimVerdict verdict;  // rule: kEquivalenceRule; no interval
};
// "equivalent", "not equivalent", "inconclusive".
std::string equivalence_text(Outcome outcome);

struct SweepClaimMeasure {
  std::string generator, view;
  std::string family;  // "fis", "kmeans"
  bool in_paper = false;
  double spread = 0;  // max |change| over γ
  double spread_low = 0, spread_high = 0;
  std::vector<SweepClaimChange> changes;
  std::optional<SweepClaimEquivalence> equivalence;  // FIS cases; absent in files written before it
};

// One of the paper's claims judged on the sweep: the PDF-independence claim on a pdf-sharpness
// axis, one per slice (sweep/pdf_independence.hpp). What every document's claim says (id, text,
// criterion, holds, note, informative) is the shared Claim; the rest is the sweep's own. Its numbers
// stay typed in `measures` (the file's "measured"), so `claim.measured` and `claim.source` are unused.
struct SweepClaim {
  Claim claim;       // id "pdf_independence"; holds none: inconclusive; informative: a CPU device's
  std::string axis;  // "pdf-sharpness"
  std::vector<std::pair<std::string, std::string>> slice;  // the other axes held; empty when none
  double reference_gamma = 1;
  double band = 0;
  std::optional<double> alpha;  // of the equivalence tests; absent in files written before them
  std::vector<SweepClaimMeasure> measures;
};

struct SweepModel {
  int schema_version = kSweepSchemaVersion;
  // "complete" (absent in files written before it: true). False: the sweep.json of a run that
  // stopped, or is still running, after some points (DESIGN.md §10.1): the points so far, the fits
  // over them, no claims. A complete sweep has at least 2 points.
  bool complete = true;
  bool complete_stated = true;  // whether the file says so (to_json writes the key only then)
  // The header every document shares (formats/run_header.hpp).
  DeviceRecord device;
  BuildRecord build;
  RunRecord run;
  SceneIdentity scene;
  std::vector<std::string> generators;
  std::vector<SweepAxisModel> axes;
  std::optional<double> time_budget_s;
  std::string time_budget_rule;  // how the budget is split, in words
  std::string fit_method;        // how the fits are made, in words
  std::optional<SweepOrderModel> order;
  std::vector<SweepPoint> points;  // points[i].index == i
  std::vector<SweepBeyondDevice> beyond_device;
  std::vector<SweepFitModel> fits;
  std::optional<std::vector<SweepClaim>> claims;  // none: the file has no "claims"

  // The points of the axes' product, and those the run reached: timed, or wholly beyond the device.
  std::size_t planned_points() const;
  std::size_t reached_points() const;
};

// "K=2, rsm=64"; "" for no other axis.
std::string sweep_slice_text(const std::vector<std::pair<std::string, std::string>>& slice);

// Reads a sweep document; `what` names it in messages. Throws InputError naming the JSON pointer and
// the problem for a document that is not a sweep (kind), of another schema version, with a key
// missing or mistyped, a number not finite, a time not positive, or a reference that points nowhere.
SweepModel read_sweep_model(const nlohmann::ordered_json& doc, const std::string& what);
// The file at `path` (named by its path in messages).
SweepModel read_sweep_file(const std::filesystem::path& path);

// The document, key for key as read_sweep_model reads it: read_sweep_model(to_json(m)) gives m back,
// and to_json of a file read gives the file back (dump(2) and a newline, as the sweep writes it).
nlohmann::ordered_json to_json(const SweepModel& model);

}  // namespace vsgl
