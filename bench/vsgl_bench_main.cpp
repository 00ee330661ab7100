// vsgl-bench: reproduce the timing tables of Tokuyoshi 2016 (Modified FIS for VSGLs) on any
// Vulkan device. Subcommands live in bench/cli/; this file maps errors to exit codes.
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "bench/cli/commands.hpp"
#include "bench/cli/exit_codes.hpp"
#include "harness/core/error.hpp"
#include "harness/core/version.hpp"

namespace {

constexpr const char* kUsage = R"(vsgl-bench — GPU timing of VSGL generators (Tokuyoshi 2016, Tables 1-3)

usage: vsgl-bench <command> [options]

commands:
  devices [--json]            list Vulkan devices: type, driver, API version, timestamp support,
                              and the default (first discrete GPU, else integrated, virtual, CPU)
  record  [options]           rasterize a scene into a capture (EXR + JSON sidecar), with its BRSM PDF
      --scene NAME[,NAME]     atrium (Table 1), conference (Table 2), tiny (tests)   [atrium]
      --gltf FILE             a glTF 2.0 file (.gltf or .glb) instead: its default scene, materials,
                              textures and normal maps (README "Your own scenes")
      --camera NAME|INDEX     glTF: the file's camera        [the file's first, else framing]
      --eye X,Y,Z --look-at X,Y,Z --fov DEG   glTF: a camera given here
      --light-pos X,Y,Z --light-dir X,Y,Z --cone DEG --intensity W|R,G,B
                              glTF: the spot light (replaces those values of the file's first
                              KHR_lights_punctual spot, else of a spot placed above the bounds)
      --ground                glTF: add a grey floor under the model (a lone convex model has no
                              indirect light: its BRSM PDF is zero)
      --out DIR               capture directory                  [captures/NAME; glTF: file stem]
      --gbuffer WxH           G-buffer size                                   [1920x1088]
      --rsm N                 RSM size N x N                                  [512]
      --frames F              animated sequence of F frames (DIR/frame_0000 ...)  [1]

  tables  [options]           time every generator on the paper's inputs: Tables 1 and 2 (+ Table 3
                              analog) as OUT/tableN.json + OUT/tableN.md, beside the paper's numbers
      --tables 1,2            which tables (1: captures/atrium, 2: captures/conference)  [1,2]
      --capture DIR           time this capture instead (repeatable): a glTF scene's capture gives
                              OUT/<scene>.json + .md ("table": null, no paper columns); a capture of
                              atrium/conference gives that paper table
      --captures DIR          capture root; missing captures are recorded first   [captures]
      --gbuffer WxH, --rsm N  sizes of captures recorded because missing      [1920x1088, 512]
      --generators G[,G]      fis_tok15, fis_modified, kmeans_2d, kmeans_3d, kmeans_2d_segsum,
                              kmeans_3d_segsum                                     [all]
      --out DIR               output directory                   [results/<device slug>]
      --warmup W              discarded warm-up runs (>= 2)                        [2]
      --repetitions R         minimum repetitions                                  [10]
      --noise-target X        stop once every total has IQR/median <= X            [0.02]
      --time-cap S            ... or after S s of timing   [60; 20 on a CPU device such as lavapipe]
      --max-repetitions M     ... or after M repetitions                           [1000]
      --quick                 3 repetitions, no noise target (CI smoke runs; marked in the JSON)
      --cold                  overwrite a 256 MiB buffer before every sample (cold caches)
      --copy-mib M            buffers of the copy-bandwidth measurement (less only if memory is short) [256]
      --camera-vsgls N, --light-vsgls N, --K K, --iterations I   [2048, 1024, 1, 12]
      --kmeans-iterations I   Lloyd iterations of the k-means generators            [4]
      --pyramid P             FIS pyramid: texture (sampled images, hardware trilinear, the
                              paper's GPU path) or buffer (storage buffer, software filter)  [texture]
      --mipmapping M          FIS texture path's mip chain: single-pass, blit or per-level
                              [the device kind's default, recorded in the JSON]
      --json-only             write no markdown file (the console still shows the tables)
      --clocks-locked         record that you locked the GPU clocks (Vulkan cannot)
      --paper FILE, --schema FILE   [results/paper/paper_tables.json, results/schema/table.schema.json]
      --no-progress           no progress line (it is off anyway when stderr is not a terminal)
      --debug-slow G[,G]      TEST-ONLY: extra work in G's last phase (to test `compare`; marked in the JSON)

  verify  --capture DIR        check every FIS pass against its CPU reference on this device
                              (DESIGN.md §11): one line per check, measured error <= tolerance
      --json FILE             also write the checks as JSON
      --camera-vsgls N, --light-vsgls N, --K K    [2048, 1024, 1]
      --pyramid P[,P]         FIS pyramid paths to check: texture, buffer        [texture,buffer]
      --mipmapping M          texture path's strategy for the generator checks (the pyramid
                              check covers all three)                  [the device kind's default]

  shade   --capture DIR       render the camera view lit by the light-view VSGLs of each generator,
                              without visibility (indirect light only), as OUT/shade_<scene>_<gen>.png
      --generators G[,G]      fis_tok15, fis_modified                 [fis_tok15,fis_modified]
      --vsgls N               light-view VSGLs per generator          [1024]
      --stride K              shade every K-th G-buffer pixel (K > 1: a quick preview)  [1]
      --exposure E            linear scale before the sRGB curve   [auto: 99th pct. -> 0.8]
      --pyramid P, --mipmapping M   FIS pyramid path and mip strategy (see tables)  [texture]
      --out DIR               output directory                        [.]

  quality --capture DIR       the paper's quality claims as numbers (Fig. 1, 5, 6): kernel gaps and
                              overlaps, too-bright VSGLs, power, flicker, K sweep, error against a VPL
                              reference; writes OUT/<scene>/quality.json, quality.md and PNGs
      --frames F              static-scene frames (only the lattice offset changes)  [32]
      --sequence DIR          also the flicker over a recorded sequence (record --frames F)  [none]
      --generators G[,G]      [fis_tok15,fis_modified,kmeans_2d,kmeans_3d]
      --k-sweep K[,K]         K values of the Fig. 6 sweep (FIS generators)          [1,2,4,8]
      --error-stride K        G-buffer stride of the reference comparison            [4]
      --flicker-width W       width of the flicker images (G-buffer stride W_gbuf/W) [120]
      --reference-rsm R       reference RSM side (every lit texel a VPL)              [128]
      --sequence-reference-rsm R   the same for each sequence frame                  [64]
      --light-vsgls N, --camera-vsgls N, --K K, --kmeans-iterations I   [1024, 2048, 1, 4]
      --pyramid P, --mipmapping M   FIS pyramid path and mip strategy (see tables)  [texture]
      --out DIR               output root                                [results/quality]

  compare BASE NEW            a verdict per row (phase, view and generator totals): FASTER, SLOWER, SAME or
                              AMBIGUOUS from the raw samples (Mann-Whitney U test + minimum change), as a
                              markdown report; BASE/NEW: table JSON, a directory of table*.json, or
                              vsgl-gbench JSON made with --benchmark_repetitions=R (R >= 5)
      --alpha A               significance level of the U test                     [0.05]
      --min-change X          smallest relevant change of the median (0.02 or 2%)  [2%]
      --min-samples S         fewer samples on a side: AMBIGUOUS                   [5]
      --fail-on V[,V]         exit 1 when a row is slower / ambiguous / faster     [none]
      --allow-mismatch        compare runs on different captures or configs (labelled)
      --out FILE              also write the report
      exit: 0 ok · 1 a verdict in --fail-on (regression) · 2 error (input, mismatch, usage)

  export  --format gab|bmf RUN [RUN...] --out FILE   medians and quartiles for dashboards:
                              github-action-benchmark customSmallerIsBetter, or Bencher Metric Format

  dashboard RESULTS_DIR --out DIR   DIR/index.html: self-contained page with inline SVG charts of
                              every table JSON under RESULTS_DIR beside the paper's numbers
      --paper FILE            [results/paper/paper_tables.json]

options of every GPU command:
  --device D                  device index or case-insensitive name substring (see `devices`)
  --validate                  enable the Khronos validation layer with synchronization
                              validation; any validation error fails the run

exit codes: 0 ok · 1 a check failed · 2 bad command line · 3 bad input (capture, parameter)
            4 device problem (none usable, no timestamps, out of memory, device lost)
            5 validation errors
)";

int dispatch(int argc, char** argv) {
  if (argc < 2 || std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0 ||
      std::strcmp(argv[1], "help") == 0) {
    std::fputs(kUsage, stdout);
    return argc < 2 ? static_cast<int>(vsgl::ExitCode::kUsage) : 0;
  }
  const std::string command = argv[1];
  if (command == "--version") {
    std::printf("vsgl-bench %s\n", vsgl::kVersionString);
    return 0;
  }
  vsgl::cli::Args args(argc, argv, 2);
  if (args.flag("--help") || args.flag("-h")) {
    std::fputs(kUsage, stdout);
    return 0;
  }
  const std::vector<std::string> tokens(argv + 2, argv + argc);
  if (command == "compare") return vsgl::cli::run_compare(tokens);
  if (command == "export") return vsgl::cli::run_export(tokens);
  if (command == "dashboard") return vsgl::cli::run_dashboard(tokens);
  if (command == "devices") return vsgl::cli::run_devices(args);
  if (command == "record") return vsgl::cli::run_record(args);
  if (command == "tables") return vsgl::cli::run_tables(args);
  if (command == "verify") return vsgl::cli::run_verify(args);
  if (command == "shade") return vsgl::cli::run_shade(args);
  if (command == "quality") return vsgl::cli::run_quality(args);
  throw vsgl::UsageError("unknown command '" + command + "'");
}

}  // namespace

int main(int argc, char** argv) {
  return vsgl::cli::run_reporting_errors("vsgl-bench", [&] { return dispatch(argc, argv); });
}
