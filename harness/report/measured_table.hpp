#pragma once
// A measured paper table and the context of its run, with the accessors the table JSON and the
// claim checks share (medians of totals, the paper's numbers beside them).
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/core/source_lines.hpp"
#include "harness/core/statistics.hpp"
#include "harness/formats/table_model.hpp"
#include "harness/timing/copy_bandwidth.hpp"
#include "harness/timing/timing_runner.hpp"
#include "harness/vk/device_info.hpp"

namespace vsgl {

struct ViewExtent {
  uint32_t width = 0;
  uint32_t height = 0;
};

// One measured table: a paper table (1: atrium, 2: conference) or another capture (number 0).
struct MeasuredTable {
  int number = 1;  // 0: not a paper table (no paper numbers beside it)
  std::string scene;
  SceneIdentity identity;  // the scene's kind and model (formats/scene_identity.hpp)
  std::string capture_dir;
  bool recorded_now = false;
  nlohmann::ordered_json capture;  // {"hashes": ..., sizes, ...}
  std::vector<std::string> generators;  // in column order
  std::map<std::string, ViewExtent> views;  // "camera_view" / "light_view": the capture's sizes
  TimingResult timing;
  CopyBandwidth copy_bandwidth;  // measured in the same run, just before the timing
};

// Everything of a run that is not a measurement.
struct ReportContext {
  DeviceInfo device;
  nlohmann::ordered_json paper;  // results/paper/paper_tables.json
  std::string paper_path;
  nlohmann::ordered_json config;    // views, N, K, iterations, timing options
  BuildRecord build;                // this_build()
  RunRecord run;                    // started, validation, quick, ... (run_record)
  std::map<std::string, GeneratorLines> lines;   // per generator
  std::map<std::string, uint32_t> shaders;       // per generator: kernels (pipelines) it dispatches
};

inline const char* const kTableViews[] = {"camera_view", "light_view"};

bool has_generator(const MeasuredTable& t, const std::string& g);
// Throws std::logic_error when the table has no timing of the case.
const CaseTiming& need_case(const MeasuredTable& t, const std::string& generator, const std::string& view);
// The case's dispatches split into its iterations (CommandStream::begin_iteration) and the rest.
// Throws std::logic_error when the iterations recorded different counts (one number could not say it).
IterationDispatches iteration_dispatches(const CaseTiming& c);
// Per-round sums of the camera- and light-view totals.
std::vector<double> generator_totals(const MeasuredTable& t, const std::string& g);
double median_total(const MeasuredTable& t, const std::string& g);
double median_view(const MeasuredTable& t, const std::string& g, const std::string& view);
// Per-round samples (ms) of one case's phase, or of its total for phase "total".
// Throws std::logic_error when the table lacks the case or the phase.
const std::vector<double>& case_samples(const MeasuredTable& t, const std::string& g, const std::string& view,
                                        const std::string& phase);

// The paper's overhead, per round (DESIGN.md §9): fis_modified − fis_tok15 of the same round (the
// pairing guarantee of timing_runner.hpp), in ms, as a Hodges-Lehmann estimate with its 95 %
// interval. `view` empty: the generator totals (both views of the round); else that view's
// `phase` ("total" or a phase name).
inline constexpr double kPairedConfidence = 0.95;
PairedInterval paired_overhead(const MeasuredTable& t, const std::string& view = "", const std::string& phase = "total");

}  // namespace vsgl
