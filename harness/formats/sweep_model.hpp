#pragma once
// The sweep JSON of DESIGN.md §10.1 (results/schema/sweep.schema.json, written by
// sweep/sweep_report.cpp sweep_json) as a typed model for its readers: the dashboard's scaling
// section (compare/dashboard_scaling.hpp). As table_model.hpp does for table JSON, the objects the
// harness writes from elsewhere (device, build, run, each claim) are kept whole as JSON beside the
// few fields a reader needs.
//
// Read only: the sweep writes its document from the measured sweep, never from this model. What
// the reader checks beyond types is what the page relies on: every fit's axis, points and case
// exist, each growth_x belongs to its point, and no time is zero, negative or not finite.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/formats/scene_identity.hpp"

namespace vsgl {

// The sweep schema version this reader knows (sweep/sweep_report.hpp kSweepSchemaVersion; a test
// keeps the two equal).
inline constexpr int kReadableSweepSchemaVersion = 1;

// One series' statistics at a point (ms), from the file.
struct SweepTimingStats {
  double median_ms = 0;
  double q1_ms = 0;  // q1 <= median <= q3
  double q3_ms = 0;
  std::vector<double> samples_ms;  // per round, positive
};

struct SweepPhaseTiming {
  std::string name;
  SweepTimingStats stats;
};

// One generator on one view at a point.
struct SweepCase {
  std::string generator;
  std::string view;  // "camera_view", "light_view"
  std::vector<SweepPhaseTiming> phases;
  SweepTimingStats total;

  // The phase's stats, or the total's for "total"; nullptr when the case has no such phase.
  const SweepTimingStats* find(const std::string& phase) const;
};

struct SweepAxisValue {
  std::string text;     // as given on the command line ("16", "96x64", "0.5")
  double value = 0;     // the parameter
  double growth_x = 0;  // what the fits use as x; 0: off the log axis (γ = 0)
};

struct SweepAxisModel {
  std::string name;            // "vsgls", "K", "pdf-sharpness", ...
  std::string spec;            // "vsgls=256:16384:x2"
  std::string symbol;          // the growth text's symbol ("N")
  std::string growth_x_title;  // "N (VSGLs per view)"
  std::vector<SweepAxisValue> values;
};

struct SweepPoint {
  std::size_t index = 0;
  std::vector<std::size_t> value_index;  // per axis, into SweepAxisModel::values
  std::vector<SweepCase> cases;

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
  std::string text;          // "cost ∝ N^0.98 [0.95, 1.01]"
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
  std::optional<std::string> verdict;  // "consistent", "faster", "slower"; none: no expectation
  bool flagged = false;                // the interval excludes the expectation
  std::string judgement;               // the verdict in words; "" when none
};

// One of the paper's claims judged on the sweep (the PDF-independence claim on a pdf-sharpness
// axis). `fields` is the whole object, as written.
struct SweepClaim {
  std::string id;
  std::string text;
  std::string criterion;
  std::optional<bool> holds;  // none: inconclusive
  std::string note;
  bool informative = false;                                // a CPU device's: says nothing of a GPU
  std::vector<std::pair<std::string, std::string>> slice;  // the other axes held; empty when none
  nlohmann::ordered_json fields = nlohmann::ordered_json::object();
};

struct SweepModel {
  int schema_version = kReadableSweepSchemaVersion;
  // "complete" (absent in files written before it: true). False: the sweep.json of a run that
  // stopped, or is still running, after some points (DESIGN.md §10.1): the points so far, the fits
  // over them, no claims. A complete sweep has at least 2 points.
  bool complete = true;
  nlohmann::ordered_json device = nlohmann::ordered_json::object();
  std::string device_name;
  nlohmann::ordered_json build = nlohmann::ordered_json::object();
  std::optional<std::string> git_commit;
  bool git_dirty = false;
  nlohmann::ordered_json run = nlohmann::ordered_json::object();
  std::string started_utc;
  bool quick = false;
  SceneIdentity scene;
  std::vector<std::string> generators;
  std::vector<SweepAxisModel> axes;
  std::optional<double> time_budget_s;
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

}  // namespace vsgl
