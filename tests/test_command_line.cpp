// The command line without a device: per-command help, the usage errors CLI11's validators catch
// before any Vulkan instance exists (exit 2 even where no driver is installed), the documented
// options accepted, and the exit-code mapping of the front ends.
#include <gtest/gtest.h>

#include <cstdio>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/cli/command_summaries.hpp"
#include "bench/cli/exit_codes.hpp"
#include "cli_runner.hpp"
#include "harness/core/error.hpp"
#include "harness/math/fis_params.hpp"

namespace vsgl {
namespace {

using test::kNoVulkanDriver;
using test::run_cli;
using test::run_cli_without_vulkan;
using test::run_program;

bool mentions(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(CliUsage, TopLevelHelpListsEveryCommandAndTheExitCodeTable) {
  const auto r = run_cli_without_vulkan("--help");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* command : {"devices", "record", "verify", "shade", "quality", "tables", "frame", "sweep", "compare",
                              "export", "dashboard"})
    EXPECT_TRUE(mentions(r.output, command)) << command << "\n" << r.output;
  for (const auto& e : cli::exit_code_table())
    EXPECT_TRUE(mentions(r.output, e.meaning)) << e.meaning << "\n" << r.output;
  EXPECT_TRUE(mentions(r.output, "70")) << r.output;
  EXPECT_FALSE(mentions(r.output, "--copy-mib")) << "command options belong to the command's help\n" << r.output;
  const auto help = run_cli_without_vulkan("help");
  EXPECT_EQ(help.exit_code, 0) << help.output;
  EXPECT_EQ(help.output, r.output);
}

// Like git and cargo: the top-level help lists each command in one line, its summary; the
// command's own help keeps the whole description.
TEST(CliUsage, TopLevelHelpListsEachCommandInOneLine) {
  const auto r = run_cli_without_vulkan("--help");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::istringstream in(r.output);
  std::string line;
  while (std::getline(in, line) && line != "Commands:") {}
  ASSERT_FALSE(in.eof()) << "no Commands section\n" << r.output;
  std::vector<std::string> listed;
  const std::regex command_line("^  ([a-z]+) +(.+)$");
  while (std::getline(in, line) && !line.empty()) {
    std::smatch m;
    ASSERT_TRUE(std::regex_match(line, m, command_line)) << "not one command in one line: '" << line << "'";
    EXPECT_FALSE(cli::command_summary(m[1].str()).empty()) << m[1];
    EXPECT_EQ(m[2].str(), cli::command_summary(m[1].str()));
    EXPECT_LE(line.size(), 110u) << line;
    listed.push_back(m[1]);
  }
  EXPECT_EQ(listed, (std::vector<std::string>{"devices", "record", "verify", "shade", "quality", "tables", "frame",
                                              "sweep", "compare", "export", "dashboard"}));
  EXPECT_FALSE(mentions(r.output, "geometric-mean summary")) << "the whole description is the command's\n" << r.output;
  const auto compare = run_cli_without_vulkan("compare --help");
  ASSERT_EQ(compare.exit_code, 0) << compare.output;
  EXPECT_TRUE(mentions(compare.output, "geometric-mean summary")) << compare.output;
}

TEST(CliUsage, EachCommandsHelpShowsOnlyItsOwnOptions) {
  const auto quality = run_cli_without_vulkan("quality --help");
  ASSERT_EQ(quality.exit_code, 0) << quality.output;
  for (const char* own : {"--capture", "--k-sweep", "--flicker-width", "--light-vsgls", "--pyramid", "--device", "--validate"})
    EXPECT_TRUE(mentions(quality.output, own)) << own << "\n" << quality.output;
  for (const char* other : {"--copy-mib", "--gltf", "--allow-mismatch", "--repetitions", "--stride"})
    EXPECT_FALSE(mentions(quality.output, other)) << other << "\n" << quality.output;

  const auto tables = run_cli_without_vulkan("tables --help");
  ASSERT_EQ(tables.exit_code, 0) << tables.output;
  for (const char* own : {"--copy-mib", "--quick", "--capture", "--captures", "--kmeans-iterations", "--iterations"})
    EXPECT_TRUE(mentions(tables.output, own)) << own << "\n" << tables.output;
  EXPECT_FALSE(mentions(tables.output, "--k-sweep")) << tables.output;
  // The paper's N, shown as the defaults from the one place they are defined.
  EXPECT_TRUE(mentions(tables.output, std::to_string(kPaperCameraVsgls))) << tables.output;
  EXPECT_TRUE(mentions(tables.output, std::to_string(kPaperLightVsgls))) << tables.output;

  const auto verify = run_cli_without_vulkan("verify --help");
  ASSERT_EQ(verify.exit_code, 0) << verify.output;
  EXPECT_TRUE(mentions(verify.output, "k-means")) << "verify checks the k-means generators too\n" << verify.output;
  EXPECT_FALSE(mentions(verify.output, "--generators")) << verify.output;

  const auto compare = run_cli_without_vulkan("compare --help");
  ASSERT_EQ(compare.exit_code, 0) << compare.output;
  EXPECT_TRUE(mentions(compare.output, "--noise-factor")) << compare.output;
  EXPECT_TRUE(mentions(compare.output, "relative IQR")) << "--noise-factor is described\n" << compare.output;
  EXPECT_FALSE(mentions(compare.output, "--device")) << compare.output;
}

TEST(CliUsage, ControlWithoutADriverAnyCommandReachingTheDeviceExitsFour) {
  // Proves the environment really hides every driver, so the 2s below are decided before Vulkan.
  EXPECT_EQ(run_cli_without_vulkan("devices").exit_code, 4);
  EXPECT_EQ(run_cli_without_vulkan("verify --capture /nonexistent/vsgl_capture").exit_code, 4);
}

TEST(CliUsage, BadCommandLinesExitTwoBeforeVulkanNamingTheOption) {
  struct Case {
    std::string args, expect;
  };
  for (const Case& c : {
           Case{"verify --capture x --frobnicate", "--frobnicate"},
           Case{"frobnicate", "frobnicate"},
           Case{"", "command"},
           Case{"verify", "--capture"},
           Case{"tables --camera-vsgls 0", "--camera-vsgls"},
           Case{"tables --light-vsgls many", "--light-vsgls"},
           Case{"tables --K 0", "--K"},
           Case{"tables --K -1", "--K"},
           Case{"tables --warmup 1", "--warmup"},
           Case{"tables --repetitions 1", "--repetitions"},
           Case{"tables --noise-target 0", "--noise-target"},
           Case{"tables --time-cap -3", "--time-cap"},
           Case{"tables --copy-mib 0", "--copy-mib"},
           Case{"tables --tables 1,3", "--tables"},
           Case{"tables --gbuffer 1920", "--gbuffer"},
           Case{"tables --pyramid cardboard", "texture or buffer"},
           Case{"tables --mipmapping magic", "single-pass, blit or per-level"},
           Case{"tables --capture a --tables 1", "--capture"},
           Case{"record --gbuffer 0x5", "--gbuffer"},
           Case{"record --gbuffer 10y5", "--gbuffer"},
           Case{"record --rsm many", "--rsm"},
           Case{"record --frames 0", "--frames"},
           Case{"record --scene tiny,atrium --out /tmp/vsgl_never_written", "captures/NAME"},
           Case{"record --eye 0,0,0", "--gltf"},
           Case{"record --scene tiny --gltf " VSGL_SOURCE_DIR "/CMakeLists.txt", "--gltf"},
           Case{"shade --capture x --stride 0", "--stride"},
           Case{"frame", "--capture"},
           Case{"frame --capture x --stride 0", "--stride"},
           Case{"frame --capture x --ism-side 48", "--ism-side"},
           Case{"frame --capture x --vsgls 0", "--vsgls"},
           Case{"frame --capture x --warmup 1", "--warmup"},
           Case{"shade --capture x --generators fis_nope", "fis_nope"},
           Case{"quality --capture x --k-sweep 1,zero", "--k-sweep"},
           Case{"quality --capture x --frames 1", "--frames"},
           Case{"verify --capture x --pyramid texture,cardboard", "--pyramid"},
           Case{"compare a.json", "NEW"},
           Case{"compare a.json b.json --min-change 150%", "--min-change"},
           Case{"compare a.json b.json --fail-on everything", "--fail-on"},
           Case{"export --format csv run --out x", "--format"},
           Case{"dashboard results", "--out"},
       }) {
    SCOPED_TRACE(c.args);
    const auto r = run_cli_without_vulkan(c.args);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_TRUE(mentions(r.output, c.expect)) << r.output;
  }
}

TEST(CliUsage, DocumentedOptionsAreAccepted) {
  // Valid command lines parse and go on to open the device: exit 4 without a driver, not 2.
  for (const std::string& args : std::vector<std::string>{
           "devices --json",
           "record --scene atrium --out /tmp/vsgl_never_written --gbuffer 1920x1088 --rsm 512 --frames 2 --validate",
           "record --scene atrium,conference --device 0",
           "record --gltf " VSGL_SOURCE_DIR "/CMakeLists.txt --camera 0 --eye -10,2,0 --look-at 10,3,0 --fov 60 "
           "--light-pos 0,14,0 --light-dir 0.3,-1,0 --cone 40 --intensity 2000 --ground",
           "record --gltf=" VSGL_SOURCE_DIR "/CMakeLists.txt --intensity 1,2,3",
           "verify --capture x --json out.json --camera-vsgls 64 --light-vsgls 32 --K 2 --pyramid texture,buffer "
           "--mipmapping blit",
           "shade --capture x --generators fis_tok15,fis_modified --vsgls 64 --stride 2 --exposure 0.5 --pyramid "
           "buffer "
           "--mipmapping per-level --out /tmp/vsgl_never_written",
           "quality --capture x --frames 4 --generators fis_modified --k-sweep 1,2 --error-stride 8 "
           "--flicker-width 60 --reference-rsm 32 --sequence-reference-rsm 16 --light-vsgls 8 --camera-vsgls 8 --K 1 "
           "--kmeans-iterations 2 --pyramid texture --mipmapping single-pass --out /tmp/vsgl_never_written",
           "tables --tables 1 --captures caps --gbuffer 96x64 --rsm 32 --generators fis_tok15,kmeans_2d --out o "
           "--warmup 2 --repetitions 3 --noise-target 0.05 --time-cap 0 --max-repetitions 5 --quick --cold "
           "--copy-mib 1 --camera-vsgls 64 --light-vsgls 32 --K 1 --iterations 12 --kmeans-iterations 4 "
           "--pyramid buffer --mipmapping blit --json-only --clocks-locked --no-progress",
           "tables --capture a --capture b --out=o",
           "sweep --scene tiny --axis vsgls=256:16384:x2 --axis K=1:4:+1 --gbuffer 96x64 --rsm 32 --captures caps "
           "--out o --generators fis_modified --quick --time-budget 60 --camera-vsgls 64 --warmup 2 --repetitions 3 "
           "--noise-target 0.05 --max-repetitions 5 --clocks-locked --no-progress",
           "sweep --capture x --axis pdf-sharpness=0,0.5,1,2 --axis kmeans-iterations=0,4 --time-cap 5",
       }) {
    SCOPED_TRACE(args);
    const auto r = run_cli_without_vulkan(args);
    EXPECT_EQ(r.exit_code, 4) << r.output;
  }
  // --sequence is accepted and checked before the device (a missing sequence is bad input).
  const auto sequence = run_cli_without_vulkan("quality --capture x --sequence /nonexistent/vsgl_sequence");
  EXPECT_EQ(sequence.exit_code, 3) << sequence.output;
  EXPECT_TRUE(mentions(sequence.output, "/nonexistent/vsgl_sequence")) << sequence.output;
}

// --debug-slow is a hook of the tests (tests/hooks/): the test build of vsgl-bench takes it, the
// shipped program refuses it as an unknown option and does not list it.
TEST(CliUsage, DebugSlowIsAnOptionOfTheTestBuildOnly) {
  const std::string args = "tables --tables 1 --generators fis_tok15 --debug-slow fis_tok15";
  const auto shipped = run_cli_without_vulkan(args);
  EXPECT_EQ(shipped.exit_code, 2) << shipped.output;
  EXPECT_TRUE(mentions(shipped.output, "--debug-slow")) << shipped.output;
  EXPECT_FALSE(mentions(run_cli("tables --help").output, "debug-slow")) << "the shipped help lists a test hook";
  const auto test_build = run_program(VSGL_BENCH_TEST_BUILD_EXE, args, kNoVulkanDriver);
  EXPECT_EQ(test_build.exit_code, 4) << "parsed, then no driver:\n" << test_build.output;
  EXPECT_TRUE(mentions(run_program(VSGL_BENCH_TEST_BUILD_EXE, "tables --help").output, "--debug-slow"));
}

TEST(CliUsage, AMissingInputFileIsBadInputBeforeVulkan) {
  // A file that is not there is bad input (3, as for a file that fails to load), not a typo (2).
  for (const char* args : {"record --gltf /nonexistent/vsgl_scene.gltf", "tables --paper /nonexistent/vsgl_paper.json",
                           "tables --schema /nonexistent/vsgl_schema.json",
                           "dashboard results --out /tmp/vsgl_unused --paper /nonexistent/vsgl_paper.json"}) {
    SCOPED_TRACE(args);
    const auto r = run_cli_without_vulkan(args);
    EXPECT_EQ(r.exit_code, 3) << r.output;
    EXPECT_TRUE(mentions(r.output, "/nonexistent/vsgl_")) << r.output;
    EXPECT_TRUE(mentions(r.output, "no such file")) << r.output;
  }
}

TEST(ExitCodes, EachExceptionMapsToItsCode) {
  EXPECT_EQ(cli::run_reporting_errors([] { return 7; }), 7);
  EXPECT_EQ(cli::run_reporting_errors([]() -> int { throw UsageError("u"); }), 2);
  EXPECT_EQ(cli::run_reporting_errors([]() -> int { throw InputError("i"); }), 3);
  EXPECT_EQ(cli::run_reporting_errors([]() -> int { throw DeviceError("d"); }), 4);
}

TEST(ExitCodes, AnUnexpectedExceptionIsAnInternalErrorNotAFailedCheck) {
  testing::internal::CaptureStderr();
  const int code = cli::run_reporting_errors([]() -> int { throw std::logic_error("index out of range"); });
  const std::string message = testing::internal::GetCapturedStderr();
  EXPECT_EQ(code, static_cast<int>(ExitCode::kInternal));
  EXPECT_EQ(code, 70);
  EXPECT_NE(code, static_cast<int>(ExitCode::kFailure));
  EXPECT_TRUE(mentions(message, "internal error: index out of range; please report it with the command line"))
      << message;
}

TEST(ExitCodes, TheHelpFooterIsTheTable) {
  const std::string help = cli::exit_codes_help();
  for (const auto& e : cli::exit_code_table()) {
    EXPECT_TRUE(mentions(help, std::to_string(static_cast<int>(e.code)) + " ")) << help;
    EXPECT_TRUE(mentions(help, e.meaning)) << help;
  }
}

}  // namespace
}  // namespace vsgl
