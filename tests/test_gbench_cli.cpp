// vsgl-gbench reads vsgl-bench's options (--vsgl_name=V is `tables --name V`) and exits with its
// codes: 2 for a bad command line, 4 for a device problem.
#include <gtest/gtest.h>

#include "cli_runner.hpp"

#ifdef VSGL_GBENCH_EXE
namespace vsgl {
namespace {

test::CliResult run_gbench(const std::string& arguments) { return test::run_program(VSGL_GBENCH_EXE, arguments); }

TEST(GbenchCli, UnknownOptionsAndBadValuesAreUsageErrors) {
  const auto unknown = run_gbench("--vsgl_no_such_option=1");
  EXPECT_EQ(unknown.exit_code, 2) << unknown.output;
  EXPECT_NE(unknown.output.find("--no-such-option"), std::string::npos) << unknown.output;
  const auto foreign = run_gbench("--not_ours");
  EXPECT_EQ(foreign.exit_code, 2) << foreign.output;
  EXPECT_NE(foreign.output.find("--vsgl_"), std::string::npos) << foreign.output;
  const auto zero = run_gbench("--vsgl_camera_vsgls=0");
  EXPECT_EQ(zero.exit_code, 2) << zero.output;
  const auto table = run_gbench("--vsgl_tables=3");
  EXPECT_EQ(table.exit_code, 2) << table.output;
  const auto k = run_gbench("--vsgl_K=-1");
  EXPECT_EQ(k.exit_code, 2) << k.output;
}

TEST(GbenchCli, UnknownDeviceIsADeviceError) {
  const auto r = run_gbench("--vsgl_device=no-such-gpu-anywhere");
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_NE(r.output.find("no-such-gpu-anywhere"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace vsgl
#endif
