// The sweep JSON and its typed model (harness/formats/sweep_model.hpp): a synthetic sweep filled
// by sweep_document() and written by to_json() reads back as its device, build, run, scene, axes,
// points and fits; every committed sweep.json reads and writes back byte for byte; and a document
// that is not a sweep, of another version, with a key missing, a NaN or a fit that points nowhere
// is an InputError naming the file and the JSON pointer. No device.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

#include "harness/core/json_schema_subset.hpp"
#include "harness/core/statistics.hpp"
#include "harness/formats/sweep_model.hpp"
#include "input_error.hpp"
#include "synthetic_sweep.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

using ojson = nlohmann::ordered_json;

const SweepFitModel& model_fit(const SweepModel& m, const std::string& axis, const std::string& view,
                               const std::string& phase, const std::string& slice) {
  for (const SweepFitModel& f : m.fits)
    if (m.axes[f.axis].name == axis && f.view == view && f.phase == phase && sweep_slice_text(f.slice) == slice)
      return f;
  throw std::logic_error("no fit " + axis + " " + view + " " + phase + " " + slice);
}

TEST(SweepModel, ReadsBackWhatTheSweepWrote) {
  const std::vector<SweepAxis> axes{parse_axis_spec("vsgls=8:32:x2"), parse_axis_spec("K=1,2")};
  const MeasuredSweep s = test::synthetic_sweep(axes, {"fis_modified", "kmeans_3d"});
  const std::vector<SweepFit> fits = sweep_fits(s);
  const SweepModel m = read_sweep_model(
      to_json(sweep_document(s, fits, test::synthetic_sweep_context("GPU X", "2026-02-03T04:05:06Z"))), "mem");

  EXPECT_EQ(m.schema_version, 1);
  EXPECT_EQ(m.device.name, "GPU X");
  EXPECT_EQ(m.device.type, "cpu");
  EXPECT_EQ(m.build.git_commit, "0123456789abcdef");
  EXPECT_FALSE(m.build.git_dirty);
  EXPECT_EQ(m.run.started_utc, "2026-02-03T04:05:06Z");
  EXPECT_TRUE(m.run.quick);
  EXPECT_EQ(m.scene.name, "tiny");
  EXPECT_EQ(m.scene.kind, SceneKind::kProcedural);
  EXPECT_EQ(m.generators, (std::vector<std::string>{"fis_modified", "kmeans_3d"}));
  ASSERT_TRUE(m.time_budget_s.has_value());
  EXPECT_EQ(*m.time_budget_s, 12.0);

  ASSERT_EQ(m.axes.size(), 2u);
  EXPECT_EQ(m.axes[0].name, "vsgls");
  EXPECT_EQ(m.axes[0].spec, "vsgls=8:32:x2");
  EXPECT_EQ(m.axes[0].symbol, growth_symbol(SweepParameter::kVsgls));
  EXPECT_EQ(m.axes[0].growth_x_title, growth_x_title(SweepParameter::kVsgls));
  ASSERT_EQ(m.axes[0].values.size(), 3u);
  EXPECT_EQ(m.axes[0].values[1].text, "16");
  EXPECT_EQ(m.axes[0].values[1].value, 16.0);
  EXPECT_EQ(m.axes[0].values[1].growth_x, 16.0);
  EXPECT_EQ(m.axes[1].name, "K");

  ASSERT_EQ(m.points.size(), 6u);
  EXPECT_EQ(m.points[3].index, 3u);
  EXPECT_EQ(m.points[3].value_index, s.points[3].value_index);
  ASSERT_EQ(m.points[3].cases.size(), 4u);
  const SweepCase* c = m.points[3].find("fis_modified", "light_view");
  ASSERT_NE(c, nullptr);
  ASSERT_EQ(c->phases.size(), 3u);
  EXPECT_EQ(c->phases[2].name, "filtered_sampling");
  const SampleStats expected = summarize(s.points[3].timing.cases[1].phase_ms[2]);
  EXPECT_DOUBLE_EQ(c->phases[2].stats.median_ms, expected.median);
  EXPECT_DOUBLE_EQ(c->phases[2].stats.q1_ms, expected.q1);
  EXPECT_DOUBLE_EQ(c->phases[2].stats.q3_ms, expected.q3);
  EXPECT_EQ(c->phases[2].stats.samples_ms, s.points[3].timing.cases[1].phase_ms[2]);
  EXPECT_EQ(c->total.samples_ms, s.points[3].timing.cases[1].total_ms);
  EXPECT_EQ(c->find("total"), &c->total);
  EXPECT_EQ(c->find("sum"), nullptr);

  ASSERT_EQ(m.fits.size(), fits.size());
  const SweepFitModel& linear = model_fit(m, "vsgls", "camera_view", "filtered_sampling", "K=2");
  EXPECT_EQ(linear.generator, "fis_modified");
  EXPECT_EQ(linear.axis, 0u);
  EXPECT_EQ(linear.points.size(), 3u);
  EXPECT_EQ(linear.growth_x, (std::vector<double>{8, 16, 32}));
  ASSERT_TRUE(linear.growth.has_value());
  EXPECT_NEAR(linear.growth->slope, 1.0, 1e-6);
  EXPECT_LE(linear.growth->low, 1.0);
  EXPECT_GE(linear.growth->high, 1.0);
  EXPECT_EQ(linear.growth->text.rfind("cost \u221d N^1.00 [", 0), 0u) << linear.growth->text;
  ASSERT_TRUE(linear.expected.has_value());
  EXPECT_EQ(linear.expected->slope, 1.0);
  EXPECT_FALSE(linear.expected->why.empty());
  ASSERT_TRUE(linear.verdict.has_value());
  EXPECT_EQ(linear.verdict_word(), "consistent");
  EXPECT_FALSE(linear.flagged());
  const SweepFitModel& quadratic = model_fit(m, "vsgls", "light_view", "filtered_sampling", "K=1");
  ASSERT_TRUE(quadratic.verdict.has_value());
  EXPECT_EQ(quadratic.verdict->outcome, Outcome::kDoesNotHold);
  EXPECT_EQ(quadratic.verdict_word(), "faster");
  EXPECT_TRUE(quadratic.flagged());
  EXPECT_FALSE(quadratic.judgement.empty());
  const SweepFitModel& total = model_fit(m, "vsgls", "camera_view", "total", "K=1");
  EXPECT_FALSE(total.expected.has_value());
  EXPECT_FALSE(total.verdict.has_value());
  EXPECT_FALSE(m.claims.has_value());
}

TEST(SweepModel, GammaZeroIsReadOffTheLogAxisAndClaimsAreRead) {
  const MeasuredSweep s = test::synthetic_sweep({parse_axis_spec("pdf-sharpness=0,1,2")});
  ojson doc = test::synthetic_sweep_json(s);
  doc["claims"] = ojson::array({test::synthetic_sweep_claim(nullptr, "inconclusive: too few rounds"),
                                test::synthetic_sweep_claim(true, "every change within the band"),
                                test::synthetic_sweep_claim(false, "k-means moves less"),
                                test::synthetic_sweep_claim(nullptr, "needs a FIS generator")});
  const SweepModel m = read_sweep_model(doc, "mem");
  EXPECT_EQ(m.axes[0].values[0].growth_x, 0.0);
  const SweepFitModel& f = model_fit(m, "pdf-sharpness", "camera_view", "filtered_sampling", "");
  EXPECT_EQ(f.growth_x.front(), 0.0);
  ASSERT_TRUE(f.growth.has_value());
  ASSERT_TRUE(m.claims.has_value());
  ASSERT_EQ(m.claims->size(), 4u);
  const SweepClaim& inconclusive = (*m.claims)[0];
  EXPECT_EQ(inconclusive.claim.id, "pdf_independence");
  ASSERT_TRUE(inconclusive.claim.verdict.has_value());
  EXPECT_EQ(inconclusive.claim.verdict->outcome, Outcome::kInconclusive);
  EXPECT_EQ(inconclusive.claim.verdict->reason, "inconclusive: too few rounds");
  EXPECT_EQ(inconclusive.claim.verdict->rule, inconclusive.claim.criterion);
  EXPECT_TRUE(inconclusive.claim.informative);
  EXPECT_EQ(inconclusive.band, 0.1);
  EXPECT_EQ(inconclusive.axis, "pdf-sharpness");
  // Each outcome, and none (a null "holds" whose note is not an inconclusive one).
  EXPECT_EQ(claim_verdict((*m.claims)[0].claim), "inconclusive");
  EXPECT_EQ(claim_verdict((*m.claims)[1].claim), "holds");
  EXPECT_EQ(claim_verdict((*m.claims)[2].claim), "does not hold");
  EXPECT_EQ(claim_note((*m.claims)[2].claim), "k-means moves less");
  EXPECT_EQ(claim_verdict((*m.claims)[3].claim), "not measured");
  EXPECT_EQ((*m.claims)[3].claim.note, "needs a FIS generator");
  EXPECT_NE((*m.claims)[1].claim.criterion.find("\u00b110 %"), std::string::npos);
}

// The committed sweeps (results/**/sweep.json) read into the model and write back as the same
// bytes: the model holds everything a file says, and to_json says it the same way.
TEST(SweepModel, EveryCommittedSweepRoundTripsByteForByte) {
  namespace fs = std::filesystem;
  std::size_t files = 0;
  for (const auto& e : fs::recursive_directory_iterator(fs::path(VSGL_SOURCE_DIR) / "results")) {
    if (!e.is_regular_file() || e.path().filename() != "sweep.json") continue;
    SCOPED_TRACE(e.path().string());
    ++files;
    const std::string text = test::read_text(e.path());
    const SweepModel m = read_sweep_file(e.path());
    const std::string written = to_json(m).dump(2) + "\n";
    EXPECT_EQ(written.size(), text.size());
    EXPECT_TRUE(written == text) << "first difference at byte "
                                 << std::distance(
                                        text.begin(),
                                        std::mismatch(text.begin(), text.end(), written.begin(), written.end()).first);
  }
  EXPECT_GE(files, 7u) << "the committed sweeps (results/lavapipe/sweep/*/sweep.json)";
}

// What the sweep fills reads back as the same document, claims included; and a change the writer
// drops would show (the reader keeps the optional keys as they were).
TEST(SweepModel, WhatTheSweepFillsReadsBackAsTheSameDocument) {
  MeasuredSweep s = test::synthetic_sweep({parse_axis_spec("gbuffer=96x64,192x128"), parse_axis_spec("K=1,2")});
  s.beyond_device.push_back(BeyondDevicePoint{{1, 1}, "fis_modified", "light_view", "too large"});
  ojson doc = test::synthetic_sweep_json(s);
  doc["claims"] = ojson::array({test::synthetic_sweep_claim(false, "moves")});
  const SweepModel m = read_sweep_model(doc, "mem");
  EXPECT_EQ(m.axes[0].values[1].width, std::optional<uint32_t>(192));
  EXPECT_FALSE(m.axes[1].values[0].width.has_value());
  EXPECT_EQ(m.points[2].timing.stop_reason, "max_repetitions");
  EXPECT_EQ(m.points[2].cases[0].dispatches, 5u);
  EXPECT_EQ(to_json(m).dump(), doc.dump());
  ojson older = doc;
  older.erase("complete");
  EXPECT_EQ(to_json(read_sweep_model(older, "mem")).dump(), older.dump());
}

TEST(SweepModel, RefusesWhatIsNotASweepOfThisVersion) {
  const MeasuredSweep s = test::synthetic_sweep({parse_axis_spec("vsgls=8:32:x2")});
  const ojson good = test::synthetic_sweep_json(s);
  const auto message = [](const ojson& doc) {
    return test::input_error([&] { read_sweep_model(doc, "runs/sweep.json"); });
  };

  ojson doc = good;
  doc["kind"] = "table";
  std::string m = message(doc);
  EXPECT_NE(m.find("runs/sweep.json: /kind"), std::string::npos) << m;
  EXPECT_NE(m.find("not a sweep"), std::string::npos) << m;
  EXPECT_NE(message(ojson{{"schema_version", 3}, {"table", 1}}).find("/kind: missing field"), std::string::npos);
  EXPECT_NE(message(ojson::array()).find("not a JSON object"), std::string::npos);

  doc = good;
  doc["schema_version"] = 2;
  m = message(doc);
  EXPECT_NE(m.find("/schema_version"), std::string::npos) << m;
  EXPECT_NE(m.find("reads sweep schema version 1"), std::string::npos) << m;

  doc = good;
  doc["fits"][0].erase("flagged");
  m = message(doc);
  EXPECT_NE(m.find("runs/sweep.json: /fits/0/flagged: missing field"), std::string::npos) << m;
  doc = good;
  doc["points"][1]["cases"][0]["total"].erase("samples_ms");
  EXPECT_NE(message(doc).find("/points/1/cases/0/total/samples_ms: missing field"), std::string::npos);
  doc = good;
  doc.erase("scene");
  EXPECT_NE(message(doc).find("/scene: missing field"), std::string::npos);

  doc = good;
  doc["points"][0]["cases"][1]["phases"][2]["stats"]["median"] = std::numeric_limits<double>::quiet_NaN();
  m = message(doc);
  EXPECT_NE(m.find("/points/0/cases/1/phases/2/stats/median"), std::string::npos) << m;
  EXPECT_NE(m.find("not a finite number"), std::string::npos) << m;
  doc = good;
  doc["fits"][0]["growth"]["slope"] = std::numeric_limits<double>::infinity();
  EXPECT_NE(message(doc).find("/fits/0/growth/slope: is not a finite number"), std::string::npos);
  doc = good;
  doc["points"][0]["cases"][0]["total"]["samples_ms"][0] = -1.0;
  EXPECT_NE(message(doc).find("/points/0/cases/0/total/samples_ms/0: is not a positive time"), std::string::npos);

  // References that point nowhere: the page would otherwise draw from nothing.
  doc = good;
  doc["fits"][0]["points"][1] = 99;
  EXPECT_NE(message(doc).find("/fits/0/points/1: is 99, past the last point"), std::string::npos);
  doc = good;
  doc["fits"][0]["axis"] = "K";
  EXPECT_NE(message(doc).find("/fits/0/axis"), std::string::npos);
  doc = good;
  doc["fits"][0]["growth_x"][0] = 1000.0;
  EXPECT_NE(message(doc).find("/fits/0/growth_x/0"), std::string::npos);
  doc = good;
  doc["fits"][0]["phase"] = "no_such_phase";
  EXPECT_NE(message(doc).find("/fits/0/points/0"), std::string::npos);
  doc = good;
  doc["points"][2]["values"]["vsgls"] = "17";
  EXPECT_NE(message(doc).find("/points/2/values/vsgls: is \"17\", not a value of axis vsgls"), std::string::npos);

  // A growth verdict is judged again from the fit's interval and expectation: words that disagree
  // with them are refused, as is a verdict without an expectation to judge against.
  std::size_t judged = good["fits"].size();
  for (std::size_t i = 0; i < good["fits"].size(); ++i)
    if (good["fits"][i]["verdict"].is_string()) judged = i;
  ASSERT_LT(judged, good["fits"].size());
  const std::string fp = "/fits/" + std::to_string(judged);
  const std::string word = good["fits"][judged]["verdict"].get<std::string>();
  doc = good;
  doc["fits"][judged]["verdict"] = word == "consistent" ? "faster" : "consistent";
  m = message(doc);
  EXPECT_NE(m.find(fp + "/verdict: is \""), std::string::npos) << m;
  EXPECT_NE(m.find("the growth interval against the expected band says \"" + word + "\""), std::string::npos) << m;
  doc = good;
  doc["fits"][judged]["flagged"] = !good["fits"][judged]["flagged"].get<bool>();
  EXPECT_NE(message(doc).find(fp + "/flagged"), std::string::npos);
  doc = good;
  doc["fits"][judged]["expected"] = nullptr;
  EXPECT_NE(message(doc).find(fp + "/verdict: is set, but the fit has no growth or no expectation"), std::string::npos);
  doc = good;
  doc["fits"][judged]["verdict"] = "equivalent";
  EXPECT_NE(message(doc).find(fp + "/verdict: is \"equivalent\", not consistent, faster, slower or null"),
            std::string::npos);
}

// The sweep.json written after each point (DESIGN.md §10.1): "complete": false, the points so far
// (one is enough), the fits over them; it conforms to the schema and reads back as incomplete. A
// file without the mark (written before it existed) is complete, and a complete sweep needs 2 points.
TEST(SweepModel, AnIncompleteSweepReadsBackWithThePointsItHas) {
  MeasuredSweep s = test::synthetic_sweep({parse_axis_spec("vsgls=8:32:x2"), parse_axis_spec("K=1,2")});
  ASSERT_EQ(s.points.size(), 6u);
  s.points.resize(1);
  s.beyond_device.push_back(BeyondDevicePoint{{0, 1}, "", "", "too large"});
  s.complete = false;
  const ojson doc = test::synthetic_sweep_json(s);
  EXPECT_EQ(doc["complete"], false);
  const nlohmann::ordered_json schema =
      test::read_json(std::filesystem::path(VSGL_SOURCE_DIR) / "results/schema/sweep.schema.json");
  const auto problems = validate_against_schema(doc, schema);
  EXPECT_TRUE(problems.empty()) << problems.front();
  const SweepModel m = read_sweep_model(doc, "mem");
  EXPECT_FALSE(m.complete);
  EXPECT_EQ(m.points.size(), 1u);
  EXPECT_EQ(m.planned_points(), 6u);
  EXPECT_EQ(m.reached_points(), 2u);  // the point timed and the one beyond the device
  ASSERT_FALSE(m.fits.empty());
  for (const SweepFitModel& f : m.fits) {
    EXPECT_EQ(f.points, std::vector<std::size_t>{0});
    EXPECT_FALSE(f.growth.has_value());
    EXPECT_EQ(f.note, "fewer than 2 points on a log axis") << "no point was left off the axis";
  }

  const ojson complete = test::synthetic_sweep_json(test::synthetic_sweep({parse_axis_spec("vsgls=8:32:x2")}));
  EXPECT_EQ(complete["complete"], true);
  EXPECT_TRUE(read_sweep_model(complete, "mem").complete);
  ojson older = complete;
  older.erase("complete");
  EXPECT_TRUE(validate_against_schema(older, schema).empty());
  const SweepModel o = read_sweep_model(older, "mem");
  EXPECT_TRUE(o.complete);
  EXPECT_EQ(o.reached_points(), o.planned_points());

  ojson wrong = doc;
  wrong["complete"] = true;
  std::string msg = test::input_error([&] { read_sweep_model(wrong, "runs/sweep.json"); });
  EXPECT_NE(msg.find("runs/sweep.json: /points: has 1 point, and a complete sweep has at least 2"), std::string::npos)
      << msg;
  wrong["complete"] = "no";
  msg = test::input_error([&] { read_sweep_model(wrong, "runs/sweep.json"); });
  EXPECT_NE(msg.find("/complete"), std::string::npos) << msg;
  EXPECT_FALSE(validate_against_schema(wrong, schema).empty());
}

TEST(SweepModel, ReadsAFileAndNamesItWhenItCannot) {
  const test::TempDir dir("sweep_model");
  const MeasuredSweep s = test::synthetic_sweep({parse_axis_spec("vsgls=8:32:x2")});
  std::ofstream(dir / "sweep.json") << test::synthetic_sweep_json(s).dump(2);
  EXPECT_EQ(read_sweep_file(dir / "sweep.json").points.size(), 3u);
  std::ofstream(dir / "broken.json") << "{\"kind\": \"sweep\", ";
  const std::string m = test::input_error([&] { read_sweep_file(dir / "broken.json"); });
  EXPECT_NE(m.find((dir / "broken.json").generic_string()), std::string::npos) << m;
  EXPECT_NE(m.find("not valid JSON"), std::string::npos) << m;
}

}  // namespace
}  // namespace vsgl
