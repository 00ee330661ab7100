// The PDF-independence claim judged on a pdf-sharpness sweep (harness/sweep/pdf_independence.hpp)
// and the paper's point on the sweep plots (sweep_plots.hpp), from synthetic samples: no device.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "harness/core/json_schema_subset.hpp"
#include "harness/report/paper_tables.hpp"
#include "harness/sweep/pdf_independence.hpp"
#include "harness/sweep/sweep_document.hpp"
#include "harness/sweep/sweep_markdown.hpp"
#include "harness/sweep/sweep_plots.hpp"
#include "synthetic_header.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

using test::kSource;

// Seven rounds around `ms`, ±1 %: noise for the bootstrap, far below the 10 % band.
std::vector<double> seven_rounds(double ms) {
  return {ms * 0.99, ms * 1.0, ms * 1.01, ms * 0.995, ms * 1.005, ms * 0.998, ms * 1.002};
}

// total(generator, view, x) in ms at each point of one axis, four generators on both views, the
// config at the paper's setup (1920x1088 G-buffer, 512 RSM, its N, K 1).
using TotalFn = std::function<double(const std::string& generator, const std::string& view, double x)>;

// The rounds of one case at one point around its total (default: `rounds`, ±1 %).
using RoundsFn = std::function<std::vector<double>(const std::string& generator, const std::string& view, double ms)>;

MeasuredSweep sweep_of(const std::string& spec, const TotalFn& total, const RoundsFn& spread = {}) {
  MeasuredSweep s;
  s.axes = {parse_axis_spec(spec)};
  s.generators = {"fis_tok15", "fis_modified", "kmeans_2d", "kmeans_3d"};
  s.scene = SceneIdentity{"tiny", SceneKind::kProcedural};
  for (std::size_t i = 0; i < s.axes[0].values.size(); ++i) {
    const AxisValue& v = s.axes[0].values[i];
    const bool gamma = s.axes[0].parameter == SweepParameter::kPdfSharpness;
    const bool n_axis = s.axes[0].parameter == SweepParameter::kVsgls;
    SweepPointResult p;
    p.value_index = {i};
    if (gamma) p.pdf_sharpness = v.value;
    const auto view_config = [&](uint32_t w, uint32_t h, uint32_t n) {
      return nlohmann::ordered_json{{"width", w}, {"height", h}, {"vsgl_count", n_axis ? v.value : n}};
    };
    p.config = nlohmann::ordered_json{
        {"views", {{"camera_view", view_config(1920, 1088, 2048)}, {"light_view", view_config(512, 512, 1024)}}},
        {"K", 1.0},
        {"kmeans_iterations", 4},
        {"timing", nlohmann::ordered_json::object()}};
    p.capture = nlohmann::ordered_json{{"hashes", nlohmann::ordered_json::object()},
                                       {"gbuffer", {{"width", 1920}, {"height", 1088}}},
                                       {"rsm", {{"width", 512}, {"height", 512}}},
                                       {"pdf_altered_in_memory", gamma}};
    for (const std::string& g : s.generators)
      for (const char* view : {"camera_view", "light_view"}) {
        CaseTiming c;
        c.generator = g;
        c.view = view;
        c.phases = {"only"};
        c.dispatch_count = 2;
        const double ms = total(g, view, v.value);
        c.total_ms = spread ? spread(g, view, ms) : seven_rounds(ms);
        c.phase_ms = {c.total_ms};
        p.timing.cases.push_back(c);
      }
    p.timing.repetitions = static_cast<uint32_t>(p.timing.cases.front().total_ms.size());
    p.time_cap_s = 2.0;
    p.timing.stop_reason = "max_repetitions";
    s.points.push_back(std::move(p));
  }
  return s;
}

bool is_fis(const std::string& g) { return g.rfind("fis", 0) == 0; }

// The one judgement of a single-axis sweep.
PdfIndependence only(const std::vector<PdfIndependence>& v) {
  EXPECT_EQ(v.size(), 1u);
  return v.at(0);
}

TEST(PdfIndependence, HoldsWhenFisStaysFlatAndKmeansMovesWithGamma) {
  const MeasuredSweep s = sweep_of("pdf-sharpness=0,0.5,1,2,4", [](const std::string& g, const std::string&, double y) {
    return is_fis(g) ? 2.0 : 10.0 * (1 + 0.25 * y);
  });
  const auto claims = judge_pdf_independence(s, sweep_fits(s));
  const PdfIndependence c = only(claims);
  EXPECT_EQ(c.reference_gamma, 1.0);
  ASSERT_EQ(c.spreads.size(), 8u);
  ASSERT_TRUE(c.verdict.has_value()) << c.note;
  EXPECT_EQ(c.verdict->outcome, Outcome::kHolds) << c.verdict->reason;
  EXPECT_EQ(c.alpha, 0.05);
  for (const PdfSpread& p : c.spreads) {
    ASSERT_EQ(p.changes.size(), 5u);
    EXPECT_EQ(p.changes[2].change, 0.0);  // the reference, γ = 1
    EXPECT_TRUE(p.changes[2].reference);
    // Every FIS case equivalent: ±1 % noise lies far inside ±10 %, so every bootstrap replicate
    // does and the TOST p-value is the smallest 2000 replicates give, 1/2001.
    ASSERT_EQ(p.equivalence.has_value(), p.fis);
    if (p.fis) {
      EXPECT_EQ(p.equivalence->verdict.outcome, Outcome::kHolds);
      EXPECT_DOUBLE_EQ(p.equivalence->p_equivalent, 1.0 / 2001);
    }
    if (!p.fis) {
      EXPECT_NEAR(p.spread, 2.0 / 1.25 - 1, 1e-9);  // γ = 4: 10 * 2 against 10 * 1.25
      EXPECT_LE(p.low, p.spread);
      EXPECT_GE(p.high, p.spread);
    }
  }
  // The JSON carries it as a claim, valid against the schema; the markdown gives its verdict.
  SweepContext ctx;
  ctx.device = test::synthetic_device();
  ctx.run = test::synthetic_run();
  ctx.build = test::synthetic_build();
  ctx.paper = load_paper_tables(kSource / "results/paper/paper_tables.json");
  ctx.informative = true;
  const SweepModel document = sweep_document(s, sweep_fits(s), ctx, claims);
  const auto doc = to_json(document);
  ASSERT_TRUE(doc.contains("claims"));
  EXPECT_EQ(doc["claims"][0]["id"], "pdf_independence");
  EXPECT_EQ(doc["claims"][0]["holds"], true);
  EXPECT_EQ(doc["claims"][0]["alpha"], 0.05);
  EXPECT_EQ(doc["claims"][0]["measured"][0]["equivalence"]["verdict"], "equivalent");
  EXPECT_FALSE(doc["claims"][0]["measured"][0]["changes"][2].contains("p_equivalent"));  // the reference
  EXPECT_TRUE(doc["claims"][0]["measured"][0]["changes"][0].contains("p_equivalent"));
  // The document reads back to the same JSON.
  EXPECT_EQ(to_json(read_sweep_model(doc, "the synthetic sweep")), doc);
  EXPECT_EQ(doc["claims"][0]["text"], ctx.paper["claims"][2]);
  const auto schema = nlohmann::ordered_json::parse(std::ifstream(kSource / "results/schema/sweep.schema.json"));
  const auto problems = validate_against_schema(doc, schema);
  EXPECT_TRUE(problems.empty()) << problems.front();
  EXPECT_NE(sweep_markdown(document).find("## PDF independence: holds"), std::string::npos);
  EXPECT_NE(sweep_markdown(document).find("| equivalent (p "), std::string::npos);
  // Without claims there is no "claims" key (the schema's minItems would refuse an empty one).
  EXPECT_FALSE(to_json(sweep_document(s, sweep_fits(s), ctx)).contains("claims"));
}

TEST(PdfIndependence, DoesNotHoldWhenAFisTotalLeavesTheBand) {
  const MeasuredSweep s = sweep_of("pdf-sharpness=0,1,4", [](const std::string& g, const std::string& view, double y) {
    if (g == "fis_tok15" && view == std::string("light_view")) return 2.0 * (1 + 0.3 * y);
    return is_fis(g) ? 2.0 : 10.0 * (1 + 0.25 * y);
  });
  const PdfIndependence c = only(judge_pdf_independence(s, sweep_fits(s)));
  ASSERT_TRUE(c.verdict.has_value());
  EXPECT_EQ(c.verdict->outcome, Outcome::kDoesNotHold);
  EXPECT_NE(c.verdict->reason.find("fis_tok15 light_view is not within ±10%"), std::string::npos) << c.verdict->reason;
  // That case alone is not equivalent (γ = 0 moves it -23 %, γ = 4 +69 %); the other FIS cases are.
  for (const PdfSpread& p : c.spreads) {
    if (!p.fis) continue;
    ASSERT_TRUE(p.equivalence.has_value());
    const bool moved = p.generator == "fis_tok15" && p.view == "light_view";
    EXPECT_EQ(p.equivalence->verdict.outcome, moved ? Outcome::kDoesNotHold : Outcome::kHolds)
        << p.generator << " " << p.view;
    EXPECT_EQ(equivalence_text(p.equivalence->verdict.outcome), moved ? "not equivalent" : "equivalent");
  }
}

TEST(PdfIndependence, InconclusiveWhenFisNoiseSpansTheBand) {
  // The FIS totals do not move with γ, but their rounds scatter by ±20 %: the medians' bootstrap
  // intervals reach beyond ±10 %, so equivalence is not shown, nor is a change outside the band.
  const MeasuredSweep s = sweep_of(
      "pdf-sharpness=0,1,4",
      [](const std::string& g, const std::string&, double y) { return is_fis(g) ? 2.0 : 10.0 * (1 + y); },
      [](const std::string& g, const std::string&, double ms) {
        if (!is_fis(g)) return seven_rounds(ms);
        return std::vector<double>{ms * 0.8, ms * 1.2, ms * 0.9, ms * 1.1, ms, ms * 0.85, ms * 1.15};
      });
  const PdfIndependence c = only(judge_pdf_independence(s, sweep_fits(s)));
  ASSERT_TRUE(c.verdict.has_value()) << c.note;
  EXPECT_EQ(c.verdict->outcome, Outcome::kInconclusive);
  EXPECT_EQ(c.verdict->reason.rfind("inconclusive: ", 0), 0u) << c.verdict->reason;
  EXPECT_NE(c.verdict->reason.find("not shown within ±10%"), std::string::npos) << c.verdict->reason;
  for (const PdfSpread& p : c.spreads) {
    if (!p.fis) continue;
    ASSERT_TRUE(p.equivalence.has_value());
    EXPECT_EQ(p.equivalence->verdict.outcome, Outcome::kInconclusive);
    EXPECT_GT(p.equivalence->p_equivalent, p.equivalence->level_equivalent);
    EXPECT_GT(p.equivalence->p_outside, p.equivalence->level_outside);
  }
}

// FIS spreads whose TOST p-values are given, one per γ but the reference.
PdfSpread fis_case(const std::string& generator, const std::string& view, std::vector<double> p_equivalent) {
  PdfSpread p;
  p.generator = generator;
  p.view = view;
  p.fis = true;
  p.in_paper = true;
  GammaChange reference;
  reference.gamma = 1;
  reference.reference = true;
  p.changes.push_back(reference);
  for (std::size_t k = 0; k < p_equivalent.size(); ++k) {
    GammaChange c;
    c.gamma = 2.0 + static_cast<double>(k);
    c.p_equivalent = p_equivalent[k];
    c.p_outside = 1.0;
    p.changes.push_back(c);
  }
  return p;
}

TEST(PdfIndependence, HolmCorrectsAcrossTheFisCases) {
  // One FIS case alone whose worst γ has TOST p = 0.02: equivalent at α = 0.05.
  std::vector<PdfSpread> one{fis_case("fis_tok15", "camera_view", {0.001, 0.02})};
  judge_fis_equivalence(one, 0.05);
  EXPECT_EQ(one[0].equivalence->verdict.outcome, Outcome::kHolds);
  EXPECT_DOUBLE_EQ(one[0].equivalence->p_equivalent, 0.02);  // the largest over γ
  EXPECT_DOUBLE_EQ(one[0].equivalence->level_equivalent, 0.05);
  // Four such cases: Holm holds the smallest to 0.05 / 4 = 0.0125, which 0.02 misses, so none is
  // shown equivalent: each becomes inconclusive.
  std::vector<PdfSpread> four{
      fis_case("fis_tok15", "camera_view", {0.001, 0.02}), fis_case("fis_tok15", "light_view", {0.02}),
      fis_case("fis_modified", "camera_view", {0.02, 0.02}), fis_case("fis_modified", "light_view", {0.02})};
  judge_fis_equivalence(four, 0.05);
  for (const PdfSpread& p : four)
    EXPECT_EQ(p.equivalence->verdict.outcome, Outcome::kInconclusive) << p.generator << p.view;
  EXPECT_DOUBLE_EQ(four[0].equivalence->level_equivalent, 0.0125);
  // With one case at p = 0.001 the step-down goes one step further: 0.001 <= 0.0125, then 0.02 >
  // 0.05 / 3, and it stops.
  four[1] = fis_case("fis_tok15", "light_view", {0.001});
  judge_fis_equivalence(four, 0.05);
  EXPECT_EQ(four[1].equivalence->verdict.outcome, Outcome::kHolds);
  EXPECT_EQ(four[0].equivalence->verdict.outcome, Outcome::kInconclusive);
  // A k-means spread is left alone.
  std::vector<PdfSpread> mixed{fis_case("fis_tok15", "camera_view", {0.001})};
  mixed.push_back(PdfSpread{"kmeans_2d", "camera_view", false, true, {}, 0, 0, 0, {}});
  judge_fis_equivalence(mixed, 0.05);
  EXPECT_FALSE(mixed[1].equivalence.has_value());
  // "Not equivalent" from the outside p-values: the smallest over γ times their number, Holm-corrected.
  std::vector<PdfSpread> out{fis_case("fis_tok15", "camera_view", {1.0, 1.0})};
  out[0].changes[1].p_outside = 0.004;  // times 2 γ: 0.008 <= 0.05
  judge_fis_equivalence(out, 0.05);
  EXPECT_EQ(out[0].equivalence->verdict.outcome, Outcome::kDoesNotHold);
  EXPECT_DOUBLE_EQ(out[0].equivalence->p_outside, 0.008);
}

TEST(PdfIndependence, DoesNotHoldWhenKmeansMovesLessThanFis) {
  const MeasuredSweep s = sweep_of("pdf-sharpness=0.5,1,2", [](const std::string& g, const std::string&, double y) {
    return is_fis(g) ? 2.0 * (1 + 0.04 * y) : 10.0;
  });
  const PdfIndependence c = only(judge_pdf_independence(s, sweep_fits(s)));
  ASSERT_TRUE(c.verdict.has_value()) << c.note;
  EXPECT_EQ(c.verdict->outcome, Outcome::kDoesNotHold);
  EXPECT_NE(c.verdict->reason.find("k-means moves less"), std::string::npos) << c.verdict->reason;
}

TEST(PdfIndependence, InconclusiveWhenNothingMovesAndWithoutKmeans) {
  const MeasuredSweep flat = sweep_of(
      "pdf-sharpness=0,1,2", [](const std::string& g, const std::string&, double) { return is_fis(g) ? 2.0 : 10.0; });
  const PdfIndependence c = only(judge_pdf_independence(flat, sweep_fits(flat)));
  ASSERT_TRUE(c.verdict.has_value()) << c.note;
  EXPECT_EQ(c.verdict->outcome, Outcome::kInconclusive);
  EXPECT_EQ(c.verdict->reason.rfind("inconclusive: ", 0), 0u) << c.verdict->reason;
  EXPECT_NE(c.verdict->reason.find("overlap"), std::string::npos) << c.verdict->reason;

  MeasuredSweep fis_only = flat;
  for (SweepPointResult& p : fis_only.points)
    std::erase_if(p.timing.cases, [](const CaseTiming& t) { return !is_fis(t.generator); });
  const PdfIndependence d = only(judge_pdf_independence(fis_only, sweep_fits(fis_only)));
  EXPECT_FALSE(d.verdict.has_value());  // not measured: no verdict
  EXPECT_NE(d.note.find("needs"), std::string::npos) << d.note;
  // Another axis: no judgement at all.
  const MeasuredSweep n = sweep_of("vsgls=64,128", [](const std::string&, const std::string&, double x) { return x; });
  EXPECT_TRUE(judge_pdf_independence(n, sweep_fits(n)).empty());
}

TEST(SweepPaperReference, PlotsMarkThePaperAtItsSetupForAPaperScene) {
  const nlohmann::ordered_json paper = load_paper_tables(kSource / "results/paper/paper_tables.json");
  EXPECT_EQ(paper_reference_x(paper, SweepParameter::kVsgls, "camera_view"), 2048.0);
  EXPECT_EQ(paper_reference_x(paper, SweepParameter::kVsgls, "light_view"), 1024.0);
  EXPECT_EQ(paper_reference_x(paper, SweepParameter::kGbuffer, "camera_view"), 1920.0 * 1088.0);
  EXPECT_FALSE(paper_reference_x(paper, SweepParameter::kGbuffer, "light_view").has_value());
  EXPECT_EQ(paper_reference_x(paper, SweepParameter::kRsm, "light_view"), 512.0 * 512.0);
  EXPECT_FALSE(paper_reference_x(paper, SweepParameter::kKmeansIterations, "camera_view").has_value());

  MeasuredSweep s = sweep_of("vsgls=256:4096:x4", [](const std::string&, const std::string&, double x) { return x; });
  const auto fits = sweep_fits(s);
  const auto count_references = [&](const MeasuredSweep& m) {
    std::size_t n = 0;
    for (const auto& [name, svg] : sweep_plots(sweep_document(m, fits, SweepContext{}), &paper, m.paper_table))
      for (std::size_t at = svg.find("class=\"reference"); at != std::string::npos;
           at = svg.find("class=\"reference", at + 1))
        ++n;
    return n;
  };
  EXPECT_EQ(count_references(s), 0u);  // the tiny scene is no paper table's input
  s.paper_table = 1;
  // Table 1 gives every generator's view total and phases, but "only" is no phase of the paper's:
  // the total plot alone carries the marks, one per generator and view.
  EXPECT_GE(count_references(s), 8u);
  const auto plots = sweep_plots(sweep_document(s, fits, SweepContext{}), &paper, s.paper_table);
  bool total_marked = false;
  for (const auto& [name, svg] : plots)
    if (name == "sweep_vsgls_total.svg") total_marked = svg.find("paper, Table 1") != std::string::npos;
  EXPECT_TRUE(total_marked);
  // Not at the paper's setup (K = 2): no mark.
  for (SweepPointResult& p : s.points) p.config["K"] = 2.0;
  EXPECT_EQ(count_references(s), 0u);
}

}  // namespace
}  // namespace vsgl
