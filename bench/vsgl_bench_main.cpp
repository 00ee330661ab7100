// vsgl-bench: reproduce the timing tables of Tokuyoshi 2016 (Modified FIS for VSGLs) on any
// Vulkan device. Subcommands live in bench/cli/; this file maps errors to exit codes.
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

#include "bench/cli/commands.hpp"
#include "harness/error.hpp"
#include "harness/version.hpp"
#include "harness/vk_check.hpp"

namespace {

constexpr const char* kUsage = R"(vsgl-bench — GPU timing of VSGL generators (Tokuyoshi 2016, Tables 1-3)

usage: vsgl-bench <command> [options]

commands:
  devices [--json]            list Vulkan devices: type, driver, API version, timestamp support,
                              and the default (first discrete GPU, else integrated, virtual, CPU)
  record  [options]           rasterize a procedural scene into a capture (EXR + JSON sidecar), with its BRSM PDF
      --scene NAME[,NAME]     atrium (Table 1), conference (Table 2), tiny (tests)   [atrium]
      --out DIR               capture directory                              [captures/NAME]
      --gbuffer WxH           G-buffer size                                   [1920x1088]
      --rsm N                 RSM size N x N                                  [512]
      --frames F              animated sequence of F frames (DIR/frame_0000 ...)  [1]

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
  if (command == "devices") return vsgl::cli::run_devices(args);
  if (command == "record") return vsgl::cli::run_record(args);
  throw vsgl::UsageError("unknown command '" + command + "'");
}

}  // namespace

int main(int argc, char** argv) {
  using vsgl::ExitCode;
  try {
    return dispatch(argc, argv);
  } catch (const vsgl::UsageError& e) {
    std::fprintf(stderr, "vsgl-bench: %s (see vsgl-bench --help)\n", e.what());
    return static_cast<int>(ExitCode::kUsage);
  } catch (const vsgl::InputError& e) {
    std::fprintf(stderr, "vsgl-bench: bad input: %s\n", e.what());
    return static_cast<int>(ExitCode::kBadInput);
  } catch (const vsgl::DeviceError& e) {
    std::fprintf(stderr, "vsgl-bench: device: %s\n", e.what());
    return static_cast<int>(ExitCode::kDevice);
  } catch (const vsgl::VulkanError& e) {
    std::fprintf(stderr, "vsgl-bench: Vulkan: %s\n", e.what());
    return static_cast<int>(ExitCode::kDevice);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vsgl-bench: error: %s\n", e.what());
    return static_cast<int>(ExitCode::kFailure);
  }
}
