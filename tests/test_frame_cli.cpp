// `vsgl-bench frame` end to end on a small recorded capture (DESIGN.md §9.2): frame.json and
// frame.md with the five phases for each generator, every median positive and finite, and the
// frame of each round the sum of its phases; a capture without visibility geometry is refused with
// exit 3, naming --visibility-points, and nothing is written. No test looks at a measured speed.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "cli_runner.hpp"
#include "gpu_test.hpp"
#include "harness/core/json_schema_subset.hpp"
#include "harness/formats/frame_model.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

using test::run_cli;
using ojson = nlohmann::ordered_json;

std::string validate_flag() { return test::test_validation() ? " --validate" : ""; }  // DESIGN.md §13.1

TEST(FrameCli, TimesFivePhasesPerGeneratorAndTheFrameIsTheirSumPerRound) {
  const test::TempDir temp("cli_frame");
  const std::filesystem::path capture = temp.path() / "capture", out = temp.path() / "out";
  auto r = run_cli("record --scene tiny --gbuffer 96x64 --rsm 32 --visibility-points 16384 --out " + capture.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = run_cli("frame --capture " + capture.string() + " --vsgls 32 --ism-side 16 --ism-points-per-map 256 --quick" +
              validate_flag() + " --no-progress --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  if (test::test_validation()) {
    EXPECT_NE(r.output.find("validation on"), std::string::npos) << r.output;
  }
  const ojson doc = test::read_json(out / "frame.json");
  EXPECT_TRUE(validate_against_schema(doc, test::read_json(test::kSource / kFrameSchemaFile)).empty());
  const FrameModel m = frame_model_from_json(doc, "frame.json");  // also checks the per-round sums
  EXPECT_EQ(m.capture.scene, "tiny");
  EXPECT_EQ(m.config.light_vsgls, 32u);
  EXPECT_EQ(m.config.ism_side, 16u);
  EXPECT_FALSE(m.config.paper_sizes);
  EXPECT_EQ(m.run.quick, true);
  EXPECT_EQ(m.run.validation_layer, test::test_validation());
  EXPECT_EQ(m.timing.repetitions, 3u);
  // The default generators: the paper's four.
  ASSERT_EQ(m.generators.size(), 4u);
  const auto& jg = doc.at("generators");
  for (std::size_t g = 0; g < m.generators.size(); ++g) {
    SCOPED_TRACE(m.generators[g].name);
    ASSERT_EQ(m.generators[g].phases.size(), 5u);
    for (std::size_t p = 0; p < 5; ++p) {
      EXPECT_EQ(m.generators[g].phases[p].phase, frame_phase_names()[p]);
      const double median = m.generators[g].phases[p].stats.median_ms;
      EXPECT_TRUE(std::isfinite(median) && median > 0) << frame_phase_names()[p] << " " << median;
    }
    // Straight from the JSON: frame sample i = the sum of the phases' sample i.
    const ojson& frame = jg[g].at("frame").at("samples_ms");
    ASSERT_EQ(frame.size(), 3u);
    for (std::size_t i = 0; i < frame.size(); ++i) {
      double sum = 0;
      for (const auto& p : frame_phase_names()) sum += jg[g].at("phases").at(p).at("samples_ms").at(i).get<double>();
      EXPECT_NEAR(frame[i].get<double>(), sum, 1e-9 * sum) << "round " << i;
    }
    EXPECT_GT(m.generators[g].frame.median_ms, 0.0);
    EXPECT_GT(m.generators[g].dispatch_calls, 0u);
  }
  std::ifstream in(out / "frame.md", std::ios::binary);
  std::ostringstream md;
  md << in.rdbuf();
  EXPECT_EQ(md.str(), frame_markdown(m));
  EXPECT_NE(md.str().find("not the paper's RSM rendering"), std::string::npos);
}

TEST(FrameCli, CaptureWithoutVisibilityGeometryExitsThreeAndWritesNothing) {
  const test::TempDir temp("cli_frame_no_geometry");
  const std::filesystem::path capture = temp.path() / "capture", out = temp.path() / "out";
  auto r = run_cli("record --scene tiny --gbuffer 48x32 --rsm 16 --visibility-points 0 --out " + capture.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = run_cli("frame --capture " + capture.string() + " --quick --out " + out.string());
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("--visibility-points"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(out)) << "nothing is written";
}

}  // namespace
}  // namespace vsgl
