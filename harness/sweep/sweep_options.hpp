#pragma once
// The options of `vsgl-bench sweep` (DESIGN.md §10.1) and their checks, made before any work.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "harness/report/tables_run.hpp"
#include "harness/sweep/sweep_axis.hpp"

namespace vsgl {

inline constexpr const char* kSweepSchemaFile = "results/schema/sweep.schema.json";
// Repeated blocks (sweep_blocks.hpp): at most this many; on a pdf-sharpness axis this many when
// none are asked for (elsewhere 1, the plain pass in axis order); the seed of the visit order when
// none is given (any fixed value, "order"; recorded in the JSON).
inline constexpr uint32_t kMaxSweepBlocks = 100;
inline constexpr uint32_t kPdfSweepBlocks = 6;
inline constexpr uint64_t kSweepOrderSeed = 0x6f72646572ULL;

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
  std::optional<double> time_budget_s;  // split evenly over the points' visits
  // Repeated blocks (sweep_blocks.hpp): 1 times each point once, in axis order; more visit every
  // point once per block in an order drawn from order_seed, and pool each point's rounds.
  uint32_t blocks = 1;
  uint64_t order_seed = kSweepOrderSeed;
  std::filesystem::path out_dir;                // required
  std::optional<std::filesystem::path> schema;  // --schema; none: kSweepSchemaFile as built in
};

// Throws UsageError for no output directory, no axis, axes that conflict, neither or both of
// capture and scene, a gbuffer/rsm axis without a scene, no generator, an unknown generator or one
// asked for twice, a budget that is not a positive number, blocks outside 1..kMaxSweepBlocks;
// InputError for N = 0; and what
// TimingOptions::check throws.
void check_sweep_options(const SweepOptions& options);

}  // namespace vsgl
