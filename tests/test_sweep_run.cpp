// run_sweep (harness/sweep/sweep_run.hpp) where the device cannot hold everything: a case or a whole
// point that throws DeviceLimitError is recorded as beyond the device with its reason, the rest
// is timed and fitted, and the JSON, markdown and the dashboard's reader all keep the record. The
// limit is simulated by a generator wrapper, so the test needs no large buffer.
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>

#include "gpu_test.hpp"
#include "test_support.hpp"
#include "harness/core/error.hpp"
#include "harness/core/json_schema_subset.hpp"
#include "harness/formats/sweep_model.hpp"
#include "harness/generators/vsgl_generator.hpp"
#include "harness/scene/named_scene.hpp"
#include "harness/sweep/sweep_blocks.hpp"
#include "harness/sweep/sweep_run.hpp"

namespace vsgl {
namespace {

namespace fs = std::filesystem;

class SweepRunTest : public test::GpuTest {};

SweepOptions tiny_sweep(const fs::path& root, const std::string& axis) {
  SweepOptions o;
  o.axes = {parse_axis_spec(axis)};
  o.scene = "tiny";
  o.scenes = default_scene_library({});
  o.captures_dir = root / "captures";
  o.record_sizes = RecordSizes{96, 64, 64};
  o.out_dir = root / "out";
  o.tables.generators = {"fis_tok15", "fis_modified"};
  o.tables.quick = true;
  o.tables.timing.warmup = 2;
  o.tables.timing.min_repetitions = 3;
  o.tables.timing.max_repetitions = 3;
  return o;
}

TEST_F(SweepRunTest, CasesAndPointsBeyondTheDeviceAreRecordedAndTheRestIsTimed) {
  const test::TempDir temp("sweep_beyond");
  SweepOptions o = tiny_sweep(temp.path(), "vsgls=8,16,32");
  // As a device with too small a storage range would: fis_tok15 does not fit at N = 16, nothing at 32.
  o.tables.wrap_generator = [](Device&, std::unique_ptr<VsglGenerator> g) {
    if (g->vsgl_count() == 32 || (g->vsgl_count() == 16 && g->name() == "fis_tok15"))
      throw DeviceLimitError("simulated: " + g->name() + " needs more than maxStorageBufferRange");
    return g;
  };
  std::string log;
  const SweepOutcome out =
      run_sweep(test::shared_context().device(), o, [&](const SweepEvent& e) { log += e.message + "\n"; });

  ASSERT_EQ(out.measured.points.size(), 2u);  // N = 8 whole, N = 16 without fis_tok15
  EXPECT_EQ(out.measured.points[1].timing.cases.size(), 2u);
  const nlohmann::ordered_json document = to_json(out.document);
  const auto& beyond = document["beyond_device"];
  ASSERT_EQ(beyond.size(), 3u) << beyond.dump();
  EXPECT_EQ(beyond[0]["values"]["vsgls"], "16");
  EXPECT_EQ(beyond[0]["generator"], "fis_tok15");
  EXPECT_EQ(beyond[0]["view"], "camera_view");
  EXPECT_EQ(beyond[1]["view"], "light_view");
  EXPECT_EQ(beyond[2]["values"]["vsgls"], "32");
  EXPECT_FALSE(beyond[2].contains("generator")) << "the whole point";
  EXPECT_NE(beyond[2]["reason"].get<std::string>().find("maxStorageBufferRange"), std::string::npos);
  EXPECT_NE(log.find("vsgls=16, fis_tok15 camera_view is beyond the device: simulated"), std::string::npos) << log;
  EXPECT_NE(log.find("point 3/3: vsgls=32 is beyond the device"), std::string::npos) << log;

  // fis_modified is fitted over both points, fis_tok15 has one point and no fit.
  for (const SweepFit& f : out.fits) {
    SCOPED_TRACE(f.generator + " " + f.view + " " + f.phase);
    if (f.generator == "fis_modified") {
      EXPECT_EQ(f.points, (std::vector<std::size_t>{0, 1}));
      EXPECT_TRUE(f.fit.has_value()) << f.note;
    } else {
      EXPECT_EQ(f.points, (std::vector<std::size_t>{0}));
      EXPECT_FALSE(f.fit.has_value());
    }
  }
  EXPECT_NE(out.markdown.find("- vsgls=16, fis_tok15 camera_view: simulated"), std::string::npos) << out.markdown;
  EXPECT_NE(out.markdown.find("- vsgls=32: "), std::string::npos);
  EXPECT_NE(out.markdown.find("| fis_tok15 | camera_view | total |"), std::string::npos);
  EXPECT_NE(out.markdown.find(" beyond |"), std::string::npos) << "the missing cell is said, the columns stay aligned";

  const fs::path file = o.out_dir / "sweep.json";
  const auto problems =
      validate_against_schema(test::read_json(file), test::read_json(fs::path(VSGL_SOURCE_DIR) / kSweepSchemaFile));
  EXPECT_TRUE(problems.empty()) << problems.front();
  const SweepModel model = read_sweep_file(file);
  EXPECT_TRUE(model.complete);
  EXPECT_EQ(document["complete"], true);
  EXPECT_EQ(test::read_text(file), document.dump(2) + "\n") << "sweep.json is the document the outcome holds";
  ASSERT_EQ(model.beyond_device.size(), 3u);
  EXPECT_EQ(model.beyond_device[0].generator, "fis_tok15");
  EXPECT_TRUE(model.beyond_device[2].generator.empty());
}

// Repeated blocks (DESIGN.md §10.1): every point timed once per block, in the drawn order, its
// rounds pooled; the order and each visit's rounds are in sweep.json, which the schema accepts.
TEST_F(SweepRunTest, RepeatedBlocksTimeEveryPointInEveryBlockAndPoolTheRounds) {
  const test::TempDir temp("sweep_blocks");
  SweepOptions o = tiny_sweep(temp.path(), "pdf-sharpness=0,1,2");
  o.blocks = 3;
  o.order_seed = 5;
  std::string log;
  const SweepOutcome out =
      run_sweep(test::shared_context().device(), o, [&](const SweepEvent& e) { log += e.message + "\n"; });
  ASSERT_TRUE(out.measured.order.has_value());
  EXPECT_EQ(out.measured.order->visits, sweep_visit_order(3, 3, 5).visits);
  ASSERT_EQ(out.measured.points.size(), 3u);
  for (const SweepPointResult& p : out.measured.points) {
    EXPECT_EQ(p.block_rounds, (std::vector<uint32_t>{3, 3, 3}));
    EXPECT_EQ(p.timing.repetitions, 9u);
    for (const CaseTiming& c : p.timing.cases) EXPECT_EQ(c.total_ms.size(), 9u);
  }
  const fs::path file = o.out_dir / "sweep.json";
  const auto problems =
      validate_against_schema(test::read_json(file), test::read_json(fs::path(VSGL_SOURCE_DIR) / kSweepSchemaFile));
  EXPECT_TRUE(problems.empty()) << problems.front();
  const SweepModel model = read_sweep_file(file);
  ASSERT_TRUE(model.order.has_value());
  EXPECT_EQ(model.order->blocks, 3u);
  EXPECT_EQ(model.points[0].timing.block_rounds.size(), 3u);
  // The PDF-independence claim is judged on the pooled rounds (without k-means it is undecided).
  ASSERT_TRUE(model.claims.has_value());
  EXPECT_TRUE(model.claims->at(0).alpha.has_value());
  for (const SweepClaimMeasure& m : model.claims->at(0).measures) EXPECT_TRUE(m.equivalence.has_value());
}

// The error stays; sweep.json keeps the one point timed, marked incomplete (DESIGN.md §10.1), and
// nothing of a complete sweep (sweep.md, plots) is written.
TEST_F(SweepRunTest, ASweepWithFewerThanTwoPointsOnTheDeviceIsADeviceErrorAndStaysIncomplete) {
  const test::TempDir temp("sweep_beyond_all");
  SweepOptions o = tiny_sweep(temp.path(), "vsgls=8,16");
  o.tables.wrap_generator = [](Device&, std::unique_ptr<VsglGenerator> g) -> std::unique_ptr<VsglGenerator> {
    if (g->vsgl_count() == 16) throw DeviceLimitError("simulated: too large");
    return g;
  };
  try {
    (void)run_sweep(test::shared_context().device(), o);
    FAIL() << "no DeviceError";
  } catch (const DeviceError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("only 1 of 2 points fit"), std::string::npos) << m;
    EXPECT_NE(m.find("simulated: too large"), std::string::npos) << m;
    EXPECT_NE(m.find("sweep.json keeps the point timed, marked \"complete\": false"), std::string::npos) << m;
  }
  const fs::path file = o.out_dir / "sweep.json";
  const auto problems =
      validate_against_schema(test::read_json(file), test::read_json(fs::path(VSGL_SOURCE_DIR) / kSweepSchemaFile));
  EXPECT_TRUE(problems.empty()) << problems.front();
  const SweepModel model = read_sweep_file(file);
  EXPECT_FALSE(model.complete);
  EXPECT_EQ(model.points.size(), 1u);
  EXPECT_EQ(model.reached_points(), 2u);
  EXPECT_FALSE(fs::exists(o.out_dir / "sweep.md"));
}

}  // namespace
}  // namespace vsgl
