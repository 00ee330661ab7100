// The overhead claim (harness/report/table_claims.cpp, `modified_overhead`) judged on the 95 %
// interval of the per-round differences, on synthetic tables (never on measured speeds): inside
// the bound it holds, wholly outside it does not, straddling it (or with too few rounds for the
// interval) it is inconclusive. Also the paired and bandwidth blocks of the table JSON built from
// the same synthetic table: their schema and their arithmetic.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>

#include "harness/core/json_schema_subset.hpp"
#include "harness/generators/fis/fis_traffic.hpp"
#include "harness/generators/generator_registry.hpp"
#include "harness/report/paper_tables.hpp"
#include "harness/report/table_claims.hpp"
#include "harness/report/table_json.hpp"
#include "harness/report/table_markdown.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

namespace fs = std::filesystem;

using test::kSource;

ReportContext synthetic_context() {
  ReportContext ctx;
  ctx.device.name = "synthetic GPU";
  ctx.device.type = VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU;  // verdicts, not informative ones
  ctx.paper_path = (kSource / "results/paper/paper_tables.json").string();
  ctx.paper = load_paper_tables(ctx.paper_path);
  for (const char* g : {"fis_tok15", "fis_modified"}) {
    ctx.lines[g] = count_generator_lines(generator_sources(g), kSource);
    ctx.shaders[g] = 3;
  }
  return ctx;
}

// Two FIS generators over `rounds` rounds. Each round both share a drift of up to +-0.3 ms in
// every pass (clocks, other load); fis_modified's filtered sampling costs `overhead_us` / 2 more
// per view, plus a per-round jitter of up to +-`jitter_us` / 2 per view.
MeasuredTable synthetic_measured_table(double overhead_us, double jitter_us, uint32_t rounds) {
  MeasuredTable t;
  t.number = 1;
  t.scene = "atrium";
  t.generators = {"fis_tok15", "fis_modified"};
  t.views = {{"camera_view", {1920, 1088}}, {"light_view", {512, 512}}};
  t.timing.repetitions = rounds;
  t.timing.stop_reason = "time_cap";
  t.copy_bandwidth.requested_bytes = t.copy_bandwidth.bytes = 256u << 20;
  t.copy_bandwidth.warmup = 2;
  t.copy_bandwidth.samples_ms = {1.0, 1.1, 0.9};
  t.copy_bandwidth.median_ms = 1.0;
  t.copy_bandwidth.bytes_per_s = 2.0 * (256u << 20) / 1e-3;
  for (const std::string g : {"fis_tok15", "fis_modified"})
    for (const std::string view : {"camera_view", "light_view"}) {
      CaseTiming c;
      c.generator = g;
      c.view = view;
      c.phases = {"additional", "mipmapping", "filtered_sampling"};
      c.phase_ms.resize(3);
      c.dispatch_count = 14;
      for (uint32_t i = 0; i < rounds; ++i) {
        const double drift = 0.3 * std::sin(1.7 * i + (view == "light_view" ? 1.0 : 0.0));
        const double jitter = 1e-3 * jitter_us / 2 * (static_cast<double>((i * 7 + 3) % 9) / 4.0 - 1.0);  // in [-1, 1] x
        const double extra = g == "fis_modified" ? 1e-3 * overhead_us / 2 + jitter : 0.0;
        const double ms[3] = {0.8 + drift, 0.4 + 0.5 * drift, 0.05 + 0.1 * drift + extra};
        double total = 0;
        for (int p = 0; p < 3; ++p) {
          c.phase_ms[p].push_back(ms[p]);
          total += ms[p];
        }
        c.total_ms.push_back(total);
      }
      t.timing.cases.push_back(c);
    }
  return t;
}

const nlohmann::ordered_json& overhead_claim(const nlohmann::ordered_json& claims) {
  for (const auto& c : claims)
    if (c["id"] == "modified_overhead") return c;
  throw std::logic_error("no modified_overhead claim");
}

TEST(OverheadClaim, RuleOnTheInterval) {
  const auto outcome = [](double low, double high, bool nominal = true) {
    return judge_overhead(low, high, 10, nominal).outcome;
  };
  EXPECT_EQ(outcome(-3, 9.9), Outcome::kHolds);
  EXPECT_EQ(outcome(10.1, 40), Outcome::kDoesNotHold);
  EXPECT_EQ(outcome(-40, -10.1), Outcome::kDoesNotHold);
  // The edge convention (core/claim_verdict.hpp): an interval touching +-bound is on neither side.
  EXPECT_EQ(outcome(-10, 10), Outcome::kInconclusive);
  EXPECT_EQ(outcome(-3, 10), Outcome::kInconclusive);    // touches +bound from inside
  EXPECT_EQ(outcome(-10, 3), Outcome::kInconclusive);    // touches -bound from inside
  EXPECT_EQ(outcome(10, 40), Outcome::kInconclusive);    // touches +bound from outside
  EXPECT_EQ(outcome(-40, -10), Outcome::kInconclusive);  // touches -bound from outside
  const ClaimVerdict straddle = judge_overhead(5, 15, 10, true);
  EXPECT_TRUE(straddle.inconclusive());
  EXPECT_EQ(straddle.reason, kInconclusiveNote);
  ASSERT_TRUE(straddle.interval.has_value());
  EXPECT_EQ(straddle.interval->low, 5);
  EXPECT_EQ(straddle.interval->high, 15);
  EXPECT_EQ(straddle.rule, "interval within (-10, 10)");
  const ClaimVerdict short_of_confidence = judge_overhead(-1, 1, 10, false);
  EXPECT_TRUE(short_of_confidence.inconclusive());
  EXPECT_EQ(short_of_confidence.reason.rfind(kInconclusivePrefix, 0), 0u);
  EXPECT_EQ(outcome(20, 30, false), Outcome::kInconclusive);
  EXPECT_THROW(judge_overhead(2, 1, 10, true), std::invalid_argument);
  EXPECT_THROW(judge_overhead(1, 2, 0, true), std::invalid_argument);
}

TEST(OverheadClaim, ThreeOutcomesOnSyntheticTables) {
  const ReportContext ctx = synthetic_context();
  // Bound: max(10 us, 1 % of the ~2.6 ms Tok15 total) = ~26 us.
  {
    // 5 us more with +-1 us jitter, under a +-300 us drift shared by both generators.
    const auto c = overhead_claim(claims_json(synthetic_measured_table(5.0, 2.0, 12), nullptr, ctx));
    SCOPED_TRACE(c.dump());
    EXPECT_EQ(c["holds"], true);
    EXPECT_NEAR(c["measured"]["overhead_us"].get<double>(), 5.0, 1.0);
    EXPECT_LE(c["measured"]["ci_low_us"].get<double>(), 5.0);
    EXPECT_GE(c["measured"]["ci_high_us"].get<double>(), 5.0);
    EXPECT_GE(c["measured"]["confidence"].get<double>(), 0.95);
    EXPECT_DOUBLE_EQ(c["measured"]["bound_us"].get<double>(), 10.0 * c["measured"]["tok15_total_ms"].get<double>());
    EXPECT_TRUE(c["measured"].contains("difference_of_medians_us"));  // the old number, still reported
  }
  {
    const auto c = overhead_claim(claims_json(synthetic_measured_table(200.0, 2.0, 12), nullptr, ctx));
    SCOPED_TRACE(c.dump());
    EXPECT_EQ(c["holds"], false);
    EXPECT_GT(c["measured"]["ci_low_us"].get<double>(), c["measured"]["bound_us"].get<double>());
  }
  {
    // Centred on the bound with a +-30 us jitter: the interval straddles it.
    const auto c = overhead_claim(claims_json(synthetic_measured_table(26.0, 60.0, 12), nullptr, ctx));
    SCOPED_TRACE(c.dump());
    EXPECT_TRUE(c["holds"].is_null());
    EXPECT_EQ(c["note"], kInconclusiveNote);
    EXPECT_LT(c["measured"]["ci_low_us"].get<double>(), c["measured"]["bound_us"].get<double>());
    EXPECT_GT(c["measured"]["ci_high_us"].get<double>(), c["measured"]["bound_us"].get<double>());
  }
  {
    // Three rounds cannot give a 95 % interval: inconclusive whatever the numbers.
    const auto c = overhead_claim(claims_json(synthetic_measured_table(5.0, 0.0, 3), nullptr, ctx));
    SCOPED_TRACE(c.dump());
    EXPECT_TRUE(c["holds"].is_null());
    EXPECT_EQ(c["note"].get<std::string>().rfind(kInconclusivePrefix, 0), 0u);
    EXPECT_NE(c["note"].get<std::string>().find("3 rounds"), std::string::npos);
  }
}

// Table `number` with each generator's total per view constant over 6 rounds, at `total_ms`.
MeasuredTable constant_table(int number, const std::map<std::string, double>& total_ms) {
  MeasuredTable t;
  t.number = number;
  t.scene = number == 1 ? "atrium" : "conference";
  t.views = {{"camera_view", {64, 64}}, {"light_view", {32, 32}}};
  t.timing.repetitions = 6;
  for (const auto& [g, ms] : total_ms) {
    t.generators.push_back(g);
    for (const std::string view : {"camera_view", "light_view"}) {
      CaseTiming c;
      c.generator = g;
      c.view = view;
      c.phases = {"one"};
      c.phase_ms = {std::vector<double>(6, ms / 2)};
      c.total_ms = std::vector<double>(6, ms / 2);
      t.timing.cases.push_back(c);
    }
  }
  return t;
}

const Claim& claim_with_id(const std::vector<Claim>& claims, const std::string& id) {
  for (const Claim& c : claims)
    if (c.id == id) return c;
  throw std::logic_error("no claim " + id);
}

// Claims 2, 3 and 6 are rules on point values (ratios, relative changes), not on an interval, so
// they hold or do not hold; without the generators they compare they have no verdict at all.
TEST(TableClaims, PointValueClaimsHoldFailOrAreNotMeasured) {
  ReportContext ctx = synthetic_context();
  const auto claims = [&](const MeasuredTable& t, const MeasuredTable* other) { return table_claims(t, other, ctx); };
  const auto verdict = [](const Claim& c) { return claim_verdict(c); };
  const std::map<std::string, double> fast_fis{
      {"fis_tok15", 1.0}, {"fis_modified", 1.0}, {"kmeans_2d", 8.0}, {"kmeans_3d", 9.0}};
  const std::map<std::string, double> slow_fis{
      {"fis_tok15", 1.0}, {"fis_modified", 2.0}, {"kmeans_2d", 8.0}, {"kmeans_3d", 9.0}};
  const std::map<std::string, double> fis_only{{"fis_tok15", 1.0}, {"fis_modified", 1.0}};

  // Claim 2: each paper k-means total at least 7 times the modified FIS's.
  EXPECT_EQ(verdict(claim_with_id(claims(constant_table(1, fast_fis), nullptr), "modified_vs_kmeans_speed")), "holds");
  EXPECT_EQ(verdict(claim_with_id(claims(constant_table(1, slow_fis), nullptr), "modified_vs_kmeans_speed")),
            "does not hold");
  const std::vector<Claim> fis_only_claims = claims(constant_table(1, fis_only), nullptr);
  const Claim& no_kmeans = claim_with_id(fis_only_claims, "modified_vs_kmeans_speed");
  EXPECT_EQ(verdict(no_kmeans), "not measured");
  EXPECT_NE(no_kmeans.note.find("needs"), std::string::npos);

  // Claim 3: from Table 1 to Table 2 FIS moves at most 10 %, each paper k-means more than FIS.
  std::map<std::string, double> moved = fast_fis;
  moved["kmeans_2d"] *= 1.5;
  moved["kmeans_3d"] *= 1.5;
  const MeasuredTable t1 = constant_table(1, fast_fis), t2 = constant_table(2, moved);
  EXPECT_EQ(verdict(claim_with_id(claims(t1, &t2), "pdf_independence")), "holds");
  moved["fis_modified"] *= 1.2;  // FIS moves 20 %
  const MeasuredTable t2_fis_moves = constant_table(2, moved);
  EXPECT_EQ(verdict(claim_with_id(claims(t1, &t2_fis_moves), "pdf_independence")), "does not hold");
  EXPECT_EQ(verdict(claim_with_id(claims(t1, nullptr), "pdf_independence")), "not measured");

  // Claim 6: each paper k-means generator at least 4 times the lines of the modified FIS.
  ctx.lines["fis_modified"].total = 100;
  ctx.lines["kmeans_2d"].total = 450;
  ctx.lines["kmeans_3d"].total = 500;
  EXPECT_EQ(verdict(claim_with_id(claims(t1, nullptr), "lines_of_code")), "holds");
  ctx.lines["kmeans_2d"].total = 350;
  EXPECT_EQ(verdict(claim_with_id(claims(t1, nullptr), "lines_of_code")), "does not hold");
  ctx.lines.erase("kmeans_2d");
  ctx.lines.erase("kmeans_3d");
  EXPECT_EQ(verdict(claim_with_id(claims(t1, nullptr), "lines_of_code")), "not measured");
}

TEST(OverheadClaim, TableJsonCarriesThePairedAndBandwidthBlocks) {
  const ReportContext ctx = synthetic_context();
  const MeasuredTable t = synthetic_measured_table(25.0, 30.0, 12);
  const nlohmann::ordered_json doc = table_json(t, nullptr, ctx);
  nlohmann::ordered_json schema;
  std::ifstream(kSource / "results/schema/table.schema.json") >> schema;
  const auto sub = [&](const nlohmann::ordered_json& part) {
    nlohmann::ordered_json s = part;
    s["$defs"] = schema["$defs"];
    return s;
  };
  const nlohmann::ordered_json ratios = doc["ratios"];
  const nlohmann::ordered_json bandwidth = doc["bandwidth"];
  const auto p1 = validate_against_schema(ratios, sub(schema["properties"]["ratios"]));
  EXPECT_TRUE(p1.empty()) << p1.front();
  const auto p2 = validate_against_schema(bandwidth, sub(schema["properties"]["bandwidth"]));
  EXPECT_TRUE(p2.empty()) << p2.front();

  // Paired: per view, its total and filtered sampling; the generator total; the paper beside them.
  const auto& paired = doc["ratios"]["paired_modified_minus_tok15"];
  for (const char* view : {"camera_view", "light_view"}) {
    const auto& fs = paired[view]["filtered_sampling"];
    EXPECT_NEAR(fs["hodges_lehmann_us"].get<double>(), 12.5, 4.0) << view;
    EXPECT_LE(fs["ci_low_us"].get<double>(), fs["hodges_lehmann_us"].get<double>());
    EXPECT_GE(fs["ci_high_us"].get<double>(), fs["hodges_lehmann_us"].get<double>());
    EXPECT_EQ(fs["rounds"], 12);
    EXPECT_TRUE(fs["paper_us"].is_number());
  }
  EXPECT_TRUE(paired["total"]["paper_us"].is_number());
  EXPECT_NEAR(paired["total"]["paper_us"].get<double>(),
              1e3 * (*paper_total(ctx.paper, 1, "fis_modified") - *paper_total(ctx.paper, 1, "fis_tok15")), 1e-9);
  EXPECT_TRUE(doc["ratios"]["modified_minus_tok15_us"]["total"]["measured"].is_number());  // kept

  // Bandwidth: fraction = achieved / copy, achieved = least bytes / median time.
  const double copy = doc["bandwidth"]["copy"]["bytes_per_s"].get<double>();
  for (const char* g : {"fis_tok15", "fis_modified"})
    for (const char* view : {"camera_view", "light_view"})
      for (const char* pass : {"additional", "mipmapping"}) {
        SCOPED_TRACE(std::string(g) + " " + view + " " + pass);
        const auto& v = doc["bandwidth"]["passes"][g][view][pass];
        EXPECT_EQ(v["min_bytes"].get<uint64_t>(), v["min_bytes_read"].get<uint64_t>() + v["min_bytes_written"].get<uint64_t>());
        EXPECT_DOUBLE_EQ(v["achieved_bytes_per_s"].get<double>(),
                         v["min_bytes"].get<double>() / (v["median_ms"].get<double>() * 1e-3));
        EXPECT_DOUBLE_EQ(v["fraction_of_copy"].get<double>(), v["achieved_bytes_per_s"].get<double>() / copy);
        EXPECT_DOUBLE_EQ(v["median_ms"].get<double>(), doc["generators"][g]["views"][view]["phases"][pass]["median_ms"].get<double>());
      }
  const FisPassBytes camera = fis_minimum_bytes(1920, 1088);
  EXPECT_EQ(doc["bandwidth"]["passes"]["fis_tok15"]["camera_view"]["additional"]["min_bytes"].get<uint64_t>(),
            camera.additional.total());
  EXPECT_EQ(doc["bandwidth"]["passes"]["fis_tok15"]["camera_view"]["mipmapping"]["level_by_level_bytes"].get<uint64_t>(),
            camera.mipmapping_level_by_level.total());

  // The claim reads "inconclusive" in the markdown, never "holds" or "does not hold".
  nlohmann::ordered_json with_config = doc;
  with_config["config"] = {{"views", {{"camera_view", {{"vsgl_count", 2048}}}, {"light_view", {{"vsgl_count", 1024}}}}}};
  const std::string md = table_markdown(with_config);
  EXPECT_NE(md.find("**inconclusive**"), std::string::npos) << md;
  EXPECT_NE(md.find("Overhead of the modified FIS, paired by round"), std::string::npos);
  EXPECT_NE(md.find("of copy bandwidth"), std::string::npos);
}

}  // namespace
}  // namespace vsgl
