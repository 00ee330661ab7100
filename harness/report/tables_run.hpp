#pragma once
// `vsgl-bench tables` as a library function (the CLI and the tests call it): provide the captures
// (record the paper's scenes when missing, else load and validate them), time every generator on
// both views of each table with the protocol of timing_runner.hpp, and write OUT/tableN.json
// (validated against results/schema/table.schema.json) and OUT/tableN.md, atomically, each table
// as soon as it is measured (a paper table written before the other one is rewritten with the
// Table 1 -> 2 change once the other is measured; DESIGN.md §10). With
// `captures` (--capture DIR ...) it times those captures instead, one table each: a capture of a
// paper table's scene is that table (tableN.*, the paper's numbers beside it), any other capture
// (a glTF file's, the tiny scene's) is OUT/<scene>.json and .md with "table": null.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/capture/capture.hpp"
#include "harness/scene/capture_recorder.hpp"
#include "harness/scene/capture_provisioning.hpp"
#include "harness/scene/named_scene.hpp"
#include "harness/generators/generator_registry.hpp"
#include "harness/timing/copy_bandwidth.hpp"
#include "harness/timing/timing_runner.hpp"

namespace vsgl {

class Device;

inline constexpr const char* kTableSchemaFile = "results/schema/table.schema.json";

struct TablesOptions {
  // Table N's capture is DIR/<its scene>: the preset that reproduces it (sponza, conference-room)
  // when `scenes` finds its model, else the procedural stand-in (atrium, conference).
  std::filesystem::path captures_dir = "captures";
  SceneLibrary scenes;  // none by default: the stand-ins; the CLI passes default_scene_library()
  std::filesystem::path out_dir;                     // required
  std::vector<int> tables{1, 2};
  std::vector<std::filesystem::path> captures;     // --capture: time these instead (never recorded here)
  std::vector<std::string> generators = generator_names();
  uint32_t camera_vsgls = kPaperCameraVsgls;  // N on the G-buffer (the paper's)
  uint32_t light_vsgls = kPaperLightVsgls;   // N on the RSM (the paper's)
  GeneratorConfig generator;     // K, iterations (vsgl_count is set per view)
  TimingOptions timing;
  CopyBandwidthOptions copy_bandwidth;  // the physical limit beside the passes (DESIGN.md §9), per table
  RecordSizes record_sizes;      // for captures recorded because they were missing
  // Inputs that are not measured; none: the copies built into the program (core/embedded_files.hpp),
  // so that a copied binary reads nothing from its checkout.
  std::optional<std::filesystem::path> source_dir;    // Table 3's lines of code (the tests: a checkout)
  std::optional<std::filesystem::path> paper_tables;  // --paper; built in: results/paper/paper_tables.json
  std::optional<std::filesystem::path> schema;        // --schema; built in: kTableSchemaFile
  bool json_only = false;       // no markdown file
  bool quick = false;           // recorded in the JSON: a CI preset, not the DESIGN.md §9 protocol
  bool validation = false;      // recorded in the JSON
  bool clocks_locked = false;   // the user claims locked clocks (recorded, not checked)
  // Applied to every generator once it is built, before it is recorded (empty: none). A wrapper
  // that alters what is timed (the test build's `--debug-slow`, tests/hooks/debug_slowdown.hpp,
  // slows generators so that `compare` can be tested) names those generators in
  // `altered_generators`: the run records them (run.altered_generators) and every report of it
  // says that their timings are not a measurement.
  GeneratorWrapper wrap_generator;
  std::vector<std::string> altered_generators;
};

// The docs section that says where the paper's scene models are looked for and where to get them;
// the stand-in note names it (tests/test_scene_presets.cpp checks that the heading exists).
inline constexpr const char* kPaperScenesSection = "docs/scenes.md#the-papers-scenes-presets";

// The scene of a paper table: the preset of `library` whose paper_table is `table`, when its model
// is found; else the procedural stand-in, with a note saying why, where the model is looked for and
// where to get it (kPaperScenesSection). Throws UsageError for a table other than 1, 2, and
// InputError for a broken preset. run_tables() prints the notes as warnings before anything is timed.
struct TableScene {
  std::string scene;
  bool paper = false;
  std::string note;  // one line for the log when the stand-in is used
};
TableScene table_scene(int table, const SceneLibrary& library = {});

// The paper table a capture is the input of: the paper_table of the preset it was recorded through
// (sponza 1, conference-room 2), 1 or 2 for the procedural stand-ins atrium and conference, 0 for
// any other (a user's file, the tiny scene).
int paper_table_of(const CaptureMeta& meta);

// The capture of `scene` in `dir`, recorded there when missing or stale (provide_capture); `say`
// hears the scene's note and what was recorded, and why.
ProvidedCapture provide_table_capture(Device& device, const TableScene& scene, const SceneLibrary& library,
                                      const std::filesystem::path& dir, const RecordSizes& sizes,
                                      const std::function<void(const std::string&)>& say);

// One table to produce: a capture and, for the paper's tables, its number.
struct TableInput {
  std::filesystem::path capture_dir;
  int paper_table = 0;             // 1, 2, or 0: not a paper table
  bool record_if_missing = false;  // the paper's captures under --captures only (also when stale)
  TableScene scene;                // the scene recorded when record_if_missing
};

// What run_tables() will measure, in order: the paper tables of `tables`, or one per `captures`
// entry (each loaded once to read its scene). Throws UsageError for two captures of one scene, and
// what load_capture() throws.
std::vector<TableInput> table_inputs(const TablesOptions& options);

// The file stem of a table's outputs: "tableN" for a paper table, else the scene's name.
std::string table_file_stem(int paper_table, const std::string& scene);

struct TablesEvent {
  std::string message;      // a line for the log ("recording captures/atrium ...")
  const TimingProgress* progress = nullptr;  // non-null during timing
  int table = 0;  // the paper table, 0 for another capture
};

struct TablesOutcome {
  std::vector<nlohmann::ordered_json> documents;  // one per table, in the order asked
  std::vector<std::string> markdown;
  std::vector<std::filesystem::path> written;  // each path once, in the order first written
};

// Throws UsageError for bad options, InputError for bad captures / paper file / schema,
// DeviceError for a device without timestamps or a zero interval.
TablesOutcome run_tables(Device& device, const TablesOptions& options,
                         const std::function<void(const TablesEvent&)>& on_event = {});

}  // namespace vsgl
