#pragma once
// `vsgl-bench sweep` as a library function (DESIGN.md §10.1): the tables' protocol (the same
// capture provisioning, uploads, recorded cases and interleaved timing, report/table_measurement.hpp)
// at every point of the product of one or more axes, then the growth fits, and OUT/sweep.json
// (validated against results/schema/sweep.schema.json), OUT/sweep.md and the SVG plots, written
// atomically once everything is complete. Before that, OUT/sweep.json is rewritten after each point
// with the points so far and "complete": false, so a run cut short keeps what it measured.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/report/tables_run.hpp"
#include "harness/sweep/measured_sweep.hpp"
#include "harness/sweep/pdf_independence.hpp"
#include "harness/sweep/sweep_axis.hpp"

namespace vsgl {

class Device;

inline constexpr const char* kSweepSchemaFile = "results/schema/sweep.schema.json";

struct SweepOptions {
  std::vector<SweepAxis> axes;
  // The input: a capture on disk, or a named scene recorded into `captures_dir` (needed by the
  // gbuffer and rsm axes, which record the capture again at each size).
  std::optional<std::filesystem::path> capture;
  std::string scene;
  SceneLibrary scenes;
  std::filesystem::path captures_dir = "captures/sweep";
  RecordSizes record_sizes;  // of the scene's capture; the gbuffer and rsm axes replace theirs
  // Everything else as in `tables`: generators, N, K, iterations, the timing protocol (its time cap
  // is replaced by the budget's share when there is a budget), run flags. Its out_dir is unused.
  TablesOptions tables;
  std::optional<double> time_budget_s;  // split evenly over the points
  std::filesystem::path out_dir;        // required
  std::optional<std::filesystem::path> schema;  // --schema; none: kSweepSchemaFile as built in
};

struct SweepEvent {
  std::string message;                       // a line for the log
  const TimingProgress* progress = nullptr;  // non-null during timing
  std::size_t point = 0, points = 0;
};

struct SweepOutcome {
  MeasuredSweep measured;
  std::vector<SweepFit> fits;
  std::vector<PdfIndependence> claims;  // on a pdf-sharpness axis
  nlohmann::ordered_json document;
  std::string markdown;
  std::vector<std::filesystem::path> written;
};

// The capture directory of a scene at some sizes under the cache root: "<scene>-g<W>x<H>-r<R>".
std::filesystem::path sweep_capture_dir(const std::filesystem::path& root, const std::string& scene,
                                        const RecordSizes& sizes);

// Throws UsageError for bad options (before any work: no axis, axes that conflict, neither or both
// of capture and scene, a gbuffer/rsm axis without a scene, an unknown generator, a budget that is
// not a positive number), InputError for a bad capture, scene or schema, DeviceError as `tables`.
SweepOutcome run_sweep(Device& device, const SweepOptions& options,
                       const std::function<void(const SweepEvent&)>& on_event = {});

}  // namespace vsgl
