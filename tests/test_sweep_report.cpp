// The sweep's fits and outputs from synthetic samples (harness/sweep/measured_sweep.hpp, the
// document of sweep_document.hpp and its renderers): slopes along each axis with the other held,
// the expectations and the flag when an interval excludes them, the JSON against
// results/schema/sweep.schema.json, the markdown and the plots; and the PDF-sharpness transform
// (pdf_sharpening.hpp). No device, no timing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <filesystem>

#include "harness/core/error.hpp"
#include "harness/core/json_schema_subset.hpp"
#include "harness/sweep/measured_sweep.hpp"
#include "harness/sweep/pdf_sharpening.hpp"
#include "harness/sweep/sweep_expectations.hpp"
#include "harness/sweep/sweep_document.hpp"
#include "harness/sweep/sweep_markdown.hpp"
#include "harness/sweep/sweep_plots.hpp"
#include "synthetic_header.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

const std::filesystem::path kSweepSchemaFile =
    std::filesystem::path(VSGL_SOURCE_DIR) / "results/schema/sweep.schema.json";

// Five rounds around `ms`, spread by ±1 % so the statistics and the bootstrap have noise to see.
std::vector<double> rounds_around(double ms) { return {ms * 0.99, ms * 1.0, ms * 1.01, ms * 0.995, ms * 1.005}; }

CaseTiming fis_case(const std::string& view, double n) {
  CaseTiming c;
  c.generator = "fis_modified";
  c.view = view;
  c.phases = {"additional", "mipmapping", "filtered_sampling"};
  // additional and mipmapping do not depend on N or K; filtered sampling is linear in N on the
  // camera view and (deliberately wrong) quadratic on the light view, which must be flagged.
  const double fs = view == "camera_view" ? 0.001 * n : 0.0001 * n * n;
  c.phase_ms = {rounds_around(0.5), rounds_around(0.25), rounds_around(fs)};
  c.total_ms = rounds_around(0.75 + fs);
  c.dispatch_count = 5;
  return c;
}

MeasuredSweep synthetic_sweep(const std::vector<SweepAxis>& axes) {
  MeasuredSweep s;
  s.axes = axes;
  s.generators = {"fis_modified"};
  s.scene = SceneIdentity{"tiny", SceneKind::kProcedural};
  s.time_budget_s = 12.0;
  for (const auto& index : axis_product(axes)) {
    SweepPointResult p;
    p.value_index = index;
    double n = 64, k = 1;
    for (std::size_t a = 0; a < axes.size(); ++a) {
      const double v = axes[a].values[index[a]].value;
      if (axes[a].parameter == SweepParameter::kVsgls) n = v;
      if (axes[a].parameter == SweepParameter::kK) k = v;
      if (axes[a].parameter == SweepParameter::kPdfSharpness) {
        p.pdf_sharpness = v;
        p.pdf_frequency["camera_view"] = PointPdfFrequency{0.5 * v, {0.1, 0.2}};
        p.pdf_frequency["light_view"] = PointPdfFrequency{v, {0.2, 0.3}};
      }
    }
    p.capture_dir = "captures/sweep/tiny-g96x64-r64";
    p.capture = nlohmann::ordered_json{{"hashes", nlohmann::ordered_json::object()},
                                       {"gbuffer", {{"width", 96}, {"height", 64}}},
                                       {"rsm", {{"width", 64}, {"height", 64}}},
                                       {"pdf_altered_in_memory", p.pdf_sharpness.has_value()}};
    p.config = nlohmann::ordered_json{{"views", nlohmann::ordered_json::object()},
                                      {"K", k},
                                      {"kmeans_iterations", 4},
                                      {"timing", nlohmann::ordered_json::object()}};
    p.time_cap_s = 12.0 / 6;
    p.timing.cases = {fis_case("camera_view", n), fis_case("light_view", n)};
    p.timing.repetitions = 5;
    p.timing.timed_seconds = 0.1;
    p.timing.stop_reason = "max_repetitions";
    p.timing.worst_noise = 0.01;
    s.points.push_back(std::move(p));
  }
  return s;
}

SweepContext synthetic_sweep_context() {
  SweepContext c;
  c.device = test::synthetic_device();
  c.build = test::synthetic_build();
  c.run = test::synthetic_run();
  return c;
}

const SweepFit& measured_fit(const std::vector<SweepFit>& fits, std::size_t axis, const std::string& view,
                             const std::string& phase, const std::string& slice) {
  for (const SweepFit& f : fits)
    if (f.axis == axis && f.view == view && f.phase == phase && slice_text(f.slice) == slice) return f;
  throw std::logic_error("no fit " + view + " " + phase + " " + slice);
}

TEST(SweepReport, FitsEachAxisWithTheOthersHeldAndFlagsWhatTheAlgorithmExcludes) {
  const std::vector<SweepAxis> axes{parse_axis_spec("vsgls=8:32:x2"), parse_axis_spec("K=1,2")};
  const MeasuredSweep s = synthetic_sweep(axes);
  const std::vector<SweepFit> fits = sweep_fits(s);
  // vsgls: 2 slices (K=1, K=2); K: 3 slices (N=8, 16, 32); each 2 views x (3 phases + total).
  ASSERT_EQ(fits.size(), (2u + 3u) * 2u * 4u);
  const SweepFit& linear = measured_fit(fits, 0, "camera_view", "filtered_sampling", "K=2");
  ASSERT_TRUE(linear.fit.has_value()) << linear.note;
  EXPECT_NEAR(linear.fit->slope, 1.0, 1e-6);
  EXPECT_LE(linear.fit->low, 1.0);
  EXPECT_GE(linear.fit->high, 1.0);
  ASSERT_TRUE(linear.judgement.has_value());
  EXPECT_FALSE(linear.judgement->flagged());
  EXPECT_EQ(linear.points.size(), 3u);
  const SweepFit& quadratic = measured_fit(fits, 0, "light_view", "filtered_sampling", "K=1");
  ASSERT_TRUE(quadratic.fit && quadratic.judgement);
  EXPECT_NEAR(quadratic.fit->slope, 2.0, 1e-6);
  EXPECT_EQ(quadratic.judgement->verdict.outcome, Outcome::kDoesNotHold);
  EXPECT_STREQ(growth_verdict_name(quadratic.judgement->verdict, quadratic.expected->slope), "faster");
  const SweepFit& flat = measured_fit(fits, 0, "camera_view", "additional", "K=1");
  ASSERT_TRUE(flat.fit && flat.judgement);
  EXPECT_NEAR(flat.fit->slope, 0.0, 1e-6);
  EXPECT_FALSE(flat.judgement->flagged());
  // Along K, with N held at 32: nothing moves, and the FIS phases are expected not to.
  const SweepFit& along_k = measured_fit(fits, 1, "camera_view", "filtered_sampling", "vsgls=32");
  ASSERT_TRUE(along_k.fit && along_k.judgement);
  EXPECT_NEAR(along_k.fit->slope, 0.0, 1e-6);
  EXPECT_FALSE(along_k.judgement->flagged());
  // The total has no expectation along N (its phases grow differently).
  EXPECT_FALSE(measured_fit(fits, 0, "camera_view", "total", "K=1").expected.has_value());
}

TEST(SweepReport, JsonConformsToTheSchemaAndKeepsTheRawSamples) {
  const std::vector<SweepAxis> axes{parse_axis_spec("vsgls=8:32:x2"), parse_axis_spec("K=1,2")};
  const MeasuredSweep s = synthetic_sweep(axes);
  const auto fits = sweep_fits(s);
  const nlohmann::ordered_json doc = to_json(sweep_document(s, fits, synthetic_sweep_context()));
  const nlohmann::ordered_json schema = test::read_json(kSweepSchemaFile);
  ASSERT_TRUE(schema_subset_problems(schema).empty());
  const auto problems = validate_against_schema(doc, schema);
  EXPECT_TRUE(problems.empty()) << problems.front();
  ASSERT_EQ(doc["points"].size(), 6u);
  EXPECT_EQ(doc["points"][3]["values"]["vsgls"], "16");
  EXPECT_EQ(doc["points"][3]["values"]["K"], "2");
  EXPECT_EQ(doc["points"][0]["cases"][0]["phases"][2]["samples_ms"].size(), 5u);
  EXPECT_EQ(doc["points"][0]["timing"]["stop_reason"], "max_repetitions");
  EXPECT_EQ(doc["time_budget_s"], 12.0);
  EXPECT_EQ(doc["fits"].size(), fits.size());
  bool flagged = false;
  for (const auto& f : doc["fits"]) flagged = flagged || f["flagged"].get<bool>();
  EXPECT_TRUE(flagged);

  // The schema can fail: a point without samples, a fit without its verdict, an unknown axis.
  nlohmann::ordered_json broken = doc;
  broken["points"][0]["cases"][0]["phases"][0].erase("samples_ms");
  EXPECT_FALSE(validate_against_schema(broken, schema).empty());
  broken = doc;
  broken["fits"][0].erase("verdict");
  EXPECT_FALSE(validate_against_schema(broken, schema).empty());
  broken = doc;
  broken["axes"][0]["name"] = "lights";
  EXPECT_FALSE(validate_against_schema(broken, schema).empty());
}

TEST(SweepReport, MarkdownHasATablePerAxisAndSliceWithTheFits) {
  const std::vector<SweepAxis> axes{parse_axis_spec("vsgls=8:32:x2"), parse_axis_spec("K=1,2")};
  const MeasuredSweep s = synthetic_sweep(axes);
  const std::string md = sweep_markdown(sweep_document(s, sweep_fits(s), synthetic_sweep_context()));
  EXPECT_NE(md.find("## Axis vsgls (`vsgls=8:32:x2`)"), std::string::npos) << md;
  EXPECT_NE(md.find("## Axis K (`K=1,2`)"), std::string::npos) << md;
  EXPECT_NE(md.find("### K=2"), std::string::npos) << md;
  EXPECT_NE(md.find("### vsgls=32"), std::string::npos) << md;
  EXPECT_NE(md.find("cost \u221d N^1.00"), std::string::npos) << md;
  EXPECT_NE(md.find("**faster**"), std::string::npos) << md;
  EXPECT_NE(md.find("vsgls=16 |"), std::string::npos) << md;
}

// Each committed sweep.md is what the markdown renderer makes of the sweep.json beside it: the
// renderer needs nothing but the document.
TEST(SweepReport, EveryCommittedMarkdownIsItsDocumentRendered) {
  std::size_t files = 0;
  for (const auto& e :
       std::filesystem::recursive_directory_iterator(std::filesystem::path(VSGL_SOURCE_DIR) / "results")) {
    if (!e.is_regular_file() || e.path().filename() != "sweep.json") continue;
    SCOPED_TRACE(e.path().string());
    ++files;
    EXPECT_EQ(sweep_markdown(read_sweep_file(e.path())), test::read_text(e.path().parent_path() / "sweep.md"));
  }
  EXPECT_GE(files, 7u);
}

TEST(SweepReport, OnePlotPerAxisAndPhase) {
  const std::vector<SweepAxis> axes{parse_axis_spec("vsgls=8:32:x2"), parse_axis_spec("K=1,2")};
  const MeasuredSweep s = synthetic_sweep(axes);
  const auto plots = sweep_plots(sweep_document(s, sweep_fits(s), synthetic_sweep_context()));
  ASSERT_EQ(plots.size(), 2u * 4u);
  EXPECT_EQ(plots[0].first, "sweep_vsgls_additional.svg");
  EXPECT_EQ(plots[2].first, "sweep_vsgls_filtered_sampling.svg");
  EXPECT_EQ(plots[7].first, "sweep_K_total.svg");
  for (const auto& [name, svg] : plots) {
    EXPECT_EQ(svg.rfind("<svg", 0), 0u) << name;
    EXPECT_NE(svg.find("class=\"band\""), std::string::npos) << name;  // IQR bands: 2+ points per series
  }
}

TEST(SweepReport, GammaZeroStaysOffTheLogAxis) {
  const MeasuredSweep two = synthetic_sweep({parse_axis_spec("pdf-sharpness=0,1")});
  for (const SweepFit& f : sweep_fits(two)) {
    EXPECT_FALSE(f.fit.has_value());
    EXPECT_NE(f.note.find("fewer than 2 points on a log axis"), std::string::npos) << f.note;
  }
  const MeasuredSweep three = synthetic_sweep({parse_axis_spec("pdf-sharpness=0,1,2")});
  const auto fits = sweep_fits(three);
  const SweepFit& f = measured_fit(fits, 0, "camera_view", "filtered_sampling", "");
  ASSERT_TRUE(f.fit.has_value()) << f.note;
  EXPECT_EQ(f.fit->points, 2u);
  ASSERT_TRUE(f.judgement.has_value());  // FIS is expected not to depend on the PDF
  EXPECT_EQ(f.expected->slope, 0.0);
  const SweepModel document = sweep_document(three, fits, synthetic_sweep_context());
  const auto doc = to_json(document);
  EXPECT_TRUE(validate_against_schema(doc, test::read_json(kSweepSchemaFile)).empty());
  EXPECT_EQ(doc["points"][2]["pdf_sharpness"]["pdf_frequency"]["light_view"]["relative_variance"], 2.0);
  EXPECT_NE(sweep_markdown(document).find("## PDF frequency at each"), std::string::npos);
}

TEST(SweepExpectations, WhatEachAlgorithmPredicts) {
  const auto e = [](SweepParameter p, GeneratorFamily f, const char* view, const char* phase) {
    return expected_growth(p, f, view, phase);
  };
  EXPECT_EQ(e(SweepParameter::kVsgls, GeneratorFamily::kFis, "camera_view", "filtered_sampling")->slope, 1.0);
  EXPECT_EQ(e(SweepParameter::kVsgls, GeneratorFamily::kFis, "light_view", "additional")->slope, 0.0);
  EXPECT_EQ(e(SweepParameter::kGbuffer, GeneratorFamily::kFis, "camera_view", "additional")->slope, 1.0);
  EXPECT_EQ(e(SweepParameter::kGbuffer, GeneratorFamily::kFis, "light_view", "additional")->slope, 0.0);
  EXPECT_EQ(e(SweepParameter::kRsm, GeneratorFamily::kKmeans, "light_view", "sort")->slope, 1.0);
  EXPECT_EQ(e(SweepParameter::kKmeansIterations, GeneratorFamily::kKmeans, "camera_view", "cluster_assignment")->slope,
            1.0);
  EXPECT_EQ(e(SweepParameter::kK, GeneratorFamily::kKmeans, "camera_view", "total")->slope, 0.0);
  EXPECT_EQ(e(SweepParameter::kCameraVsgls, GeneratorFamily::kKmeans, "light_view", "sum")->slope, 0.0);
  EXPECT_FALSE(e(SweepParameter::kVsgls, GeneratorFamily::kKmeans, "camera_view", "cluster_assignment").has_value());
  EXPECT_FALSE(e(SweepParameter::kPdfSharpness, GeneratorFamily::kKmeans, "camera_view", "sum").has_value());
}

ViewImage small_view() {
  ViewImage v;
  v.resize(ViewKind::kLight, 2, 2);
  v.has_pdf = true;
  const float pdf[] = {4, 2, 1, 8};
  const float valid[] = {1, 1, 0, 1};
  for (int i = 0; i < 4; ++i) {
    v.planes[kPdf][static_cast<std::size_t>(i)] = pdf[i];
    v.planes[kValid][static_cast<std::size_t>(i)] = valid[i];
  }
  return v;
}

TEST(SweepPdfSharpness, RaisesThePdfToGammaOnItsSupport) {
  const ViewImage v = small_view();
  const ViewImage g0 = sharpened_pdf_view(v, 0);
  EXPECT_EQ(g0.planes[kPdf], (std::vector<float>{1, 1, 0, 1}));  // uniform; the invalid texel stays out
  const ViewImage g1 = sharpened_pdf_view(v, 1);
  EXPECT_EQ(g1.planes[kPdf], (std::vector<float>{0.5f, 0.25f, 0, 1}));  // the same density, scaled
  const ViewImage g2 = sharpened_pdf_view(v, 2);
  EXPECT_EQ(g2.planes[kPdf], (std::vector<float>{0.25f, 0.0625f, 0, 1}));
  EXPECT_EQ(g2.planes[kPX], v.planes[kPX]);  // nothing else changes
  EXPECT_THROW(sharpened_pdf_view(v, -1), InputError);
  ViewImage zero = v;
  std::fill(zero.planes[kPdf].begin(), zero.planes[kPdf].end(), 0.0f);
  EXPECT_THROW(sharpened_pdf_view(zero, 1), InputError);
  Capture c;
  c.gbuffer = v;
  c.gbuffer.kind = ViewKind::kCamera;
  c.rsm = v;
  const Capture s = sharpened_pdf_capture(c, 2);
  EXPECT_EQ(s.meta.rsm_hashes[kPdf], plane_hash(g2.planes[kPdf]));
}

}  // namespace
}  // namespace vsgl
