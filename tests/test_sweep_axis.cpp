// The axes of `vsgl-bench sweep` (harness/sweep/sweep_axis.hpp): each spec form, the refusals with
// the problem named, conflicting axes, and the product of two axes.
#include <gtest/gtest.h>

#include <string>

#include "harness/core/error.hpp"
#include "harness/sweep/sweep_axis.hpp"

namespace vsgl {
namespace {

std::vector<std::string> texts(const SweepAxis& a) {
  std::vector<std::string> out;
  for (const auto& v : a.values) out.push_back(v.text);
  return out;
}

// The UsageError's message, or "" when the spec is accepted.
std::string refusal(const std::string& spec) {
  try {
    (void)parse_axis_spec(spec);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(SweepAxis, GeometricRangeDoublesUpToTheEnd) {
  const SweepAxis a = parse_axis_spec("vsgls=256:16384:x2");
  EXPECT_EQ(a.parameter, SweepParameter::kVsgls);
  EXPECT_EQ(a.spec, "vsgls=256:16384:x2");
  EXPECT_EQ(texts(a), (std::vector<std::string>{"256", "512", "1024", "2048", "4096", "8192", "16384"}));
  EXPECT_EQ(a.values.back().value, 16384.0);
  // The end need not be reached exactly: the last value is the last one not above it.
  EXPECT_EQ(texts(parse_axis_spec("camera-vsgls=3:30:x3")), (std::vector<std::string>{"3", "9", "27"}));
}

TEST(SweepAxis, ArithmeticRangeAndListsParse) {
  EXPECT_EQ(texts(parse_axis_spec("K=1:4:+1")), (std::vector<std::string>{"1", "2", "3", "4"}));
  EXPECT_EQ(texts(parse_axis_spec("K=0.5:1.5:+0.25")), (std::vector<std::string>{"0.5", "0.75", "1", "1.25", "1.5"}));
  EXPECT_EQ(texts(parse_axis_spec("K=1,2,4")), (std::vector<std::string>{"1", "2", "4"}));
  EXPECT_EQ(texts(parse_axis_spec("kmeans-iterations=0:8:+4")), (std::vector<std::string>{"0", "4", "8"}));
  EXPECT_EQ(texts(parse_axis_spec("pdf-sharpness=0,0.5,1,2")), (std::vector<std::string>{"0", "0.5", "1", "2"}));
  EXPECT_EQ(texts(parse_axis_spec("rsm=64,128")), (std::vector<std::string>{"64", "128"}));
}

TEST(SweepAxis, GbufferTakesSizesAsAListOrAGeometricRange) {
  const SweepAxis list = parse_axis_spec("gbuffer=96x64,192x128");
  ASSERT_EQ(list.values.size(), 2u);
  EXPECT_EQ(list.values[1].width, 192u);
  EXPECT_EQ(list.values[1].height, 128u);
  EXPECT_EQ(list.values[1].value, 192.0 * 128.0);
  EXPECT_EQ(texts(parse_axis_spec("gbuffer=480x272:1920x1088:x2")),
            (std::vector<std::string>{"480x272", "960x544", "1920x1088"}));
}

TEST(SweepAxis, GrowthXIsWhatTheCostScalesWith) {
  EXPECT_EQ(growth_x(SweepParameter::kVsgls, parse_axis_spec("vsgls=8,16").values[1]), 16.0);
  EXPECT_EQ(growth_x(SweepParameter::kKmeansIterations, parse_axis_spec("kmeans-iterations=0,3").values[1]), 4.0);
  EXPECT_EQ(growth_x(SweepParameter::kRsm, parse_axis_spec("rsm=64,128").values[1]), 128.0 * 128.0);
  EXPECT_EQ(growth_x(SweepParameter::kPdfSharpness, parse_axis_spec("pdf-sharpness=0,1").values[0]), 0.0);
}

TEST(SweepAxis, BadSpecsAreRefusedNamingTheProblem) {
  const std::pair<const char*, const char*> cases[] = {
      {"vsgls", "expected NAME=VALUES"},
      {"lights=1,2", "unknown parameter 'lights'"},
      {"vsgls=", "no values"},
      {"vsgls=256:16384:x1", "needs F > 1"},
      {"vsgls=256:16384:x0.5", "needs F > 1"},
      {"vsgls=16384:256:x2", "starts above its end"},
      {"K=1:4:+0", "needs D > 0"},
      {"K=1:4:-1", "must be xF (geometric) or +D"},
      {"K=1:4", "expected a list"},
      {"K=1:2:3:4", "expected a list"},
      {"K=1,,2", "an empty item"},
      {"K=1,two", "'two' is not a number"},
      {"K=0,1", "out of range"},
      {"vsgls=0,4", "out of range"},
      {"vsgls=1.5,4", "not a whole number"},
      {"vsgls=3:30:x1.5", "not a whole number"},
      {"kmeans-iterations=-1,2", "out of range"},
      {"pdf-sharpness=-1,1", "out of range"},
      {"K=2", "only one value"},
      {"K=1,2,1", "given twice"},
      {"K=nan,1", "not a number"},
      {"K=inf,1", "not a number"},
      {"gbuffer=96,128", "not a size WxH"},
      {"gbuffer=96x64:384x256:+32", "must be geometric"},
      {"gbuffer=0x64,96x64", "out of range"},
      {"vsgls=1:1000000:+1", "more than 64 values"},
  };
  for (const auto& [spec, why] : cases) {
    const std::string msg = refusal(spec);
    EXPECT_NE(msg.find(why), std::string::npos) << spec << " -> '" << msg << "', expected '" << why << "'";
  }
}

TEST(SweepAxis, AxesThatSetOneParameterConflict) {
  const auto conflict = [](const char* a, const char* b) {
    try {
      check_axes({parse_axis_spec(a), parse_axis_spec(b)});
    } catch (const UsageError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(conflict("K=1,2", "K=3,4").find("both set K"), std::string::npos);
  EXPECT_NE(conflict("vsgls=8,16", "camera-vsgls=8,16").find("both set N"), std::string::npos);
  EXPECT_EQ(conflict("camera-vsgls=8,16", "light-vsgls=8,16"), "");
  EXPECT_EQ(conflict("vsgls=8,16", "K=1,2"), "");
  EXPECT_THROW(check_axes({}), UsageError);
}

TEST(SweepAxis, TwoAxesGiveTheirProductFirstAxisOutermost) {
  const std::vector<SweepAxis> axes{parse_axis_spec("vsgls=8,16,32"), parse_axis_spec("K=1,2")};
  const auto points = axis_product(axes);
  ASSERT_EQ(points.size(), 6u);
  const std::vector<std::vector<std::size_t>> expected{{0, 0}, {0, 1}, {1, 0}, {1, 1}, {2, 0}, {2, 1}};
  EXPECT_EQ(points, expected);
  EXPECT_EQ(axis_product({axes[0]}).size(), 3u);
}

}  // namespace
}  // namespace vsgl
