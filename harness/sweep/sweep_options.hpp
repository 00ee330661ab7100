#pragma once
// The options of `vsgl-bench sweep` (DESIGN.md §10.1) and their checks, made before any work.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "harness/report/tables_run.hpp"
#include "harness/sweep/sweep_axis.hpp"

namespace vsgl {

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
  std::optional<double> time_budget_s;          // split evenly over the points
  std::filesystem::path out_dir;                // required
  std::optional<std::filesystem::path> schema;  // --schema; none: kSweepSchemaFile as built in
};

// Throws UsageError for no output directory, no axis, axes that conflict, neither or both of
// capture and scene, a gbuffer/rsm axis without a scene, no generator, an unknown generator or one
// asked for twice, a budget that is not a positive number; InputError for N = 0; and what
// TimingOptions::check throws.
void check_sweep_options(const SweepOptions& options);

}  // namespace vsgl
