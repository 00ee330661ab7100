// `vsgl-bench compare` on synthetic runs built as table JSON documents (identical -> SAME,
// +10 % -> SLOWER, heavy overlap -> AMBIGUOUS), its refusals (other captures, other configs,
// malformed, truncated or incomplete JSON: exit 2 with a message naming the problem), the CI-gate
// exit codes, Google Benchmark JSON with and without repetitions, and the committed results.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <random>

#include "cli_runner.hpp"
#include "harness/core/error.hpp"
#include "harness/compare/regression_compare.hpp"
#include "harness/compare/regression_run.hpp"
#include "harness/core/statistics.hpp"
#include "synthetic_header.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

namespace fs = std::filesystem;
using ojson = nlohmann::ordered_json;
using test::run_cli;

// Samples of one row: (generator, view, phase) -> samples. Totals are summed from the phases.
using SampleSource = std::function<std::vector<double>(const std::string&, const std::string&, const std::string&)>;

ojson stats(const std::vector<double>& samples) {
  const SampleStats s = summarize(samples);
  return ojson{{"median_ms", s.median}, {"paper_ms", nullptr}, {"q1_ms", s.q1}, {"q3_ms", s.q3}, {"samples_ms", samples}};
}

// A table JSON with only what `compare` reads (the rest of the schema is not needed for it).
ojson synthetic_table_json(int table, const SampleSource& source, const std::string& device = "Test GPU",
                           const std::string& hash = "fnv1a64:0000000000000001", int K = 1) {
  ojson gens = ojson::object();
  for (const std::string g : {"fis_tok15", "fis_modified"}) {
    ojson views = ojson::object();
    std::vector<double> gen_total;
    for (const std::string view : {"camera_view", "light_view"}) {
      ojson phases = ojson::object();
      std::vector<double> total;
      for (const std::string phase : {"additional", "mipmapping", "filtered_sampling"}) {
        const std::vector<double> s = source(g, view, phase);
        phases[phase] = stats(s);
        total = total.empty() ? s : add_samples(total, s);
      }
      views[view] = ojson{{"phases", phases}, {"total", stats(total)}, {"dispatch_calls", 3}};
      gen_total = gen_total.empty() ? total : add_samples(gen_total, total);
    }
    gens[g] = ojson{{"label", g}, {"in_paper", true}, {"views", views}, {"total", stats(gen_total)}};
  }
  return ojson{
      {"schema_version", 1},
      {"table", table},
      {"device", to_json(test::synthetic_device(device, "discrete"))},
      {"build", to_json(test::synthetic_build("abc1234"))},
      {"run", to_json(test::synthetic_run("2026-01-02T03:04:05Z", false))},
      {"config", ojson{{"views", ojson{{"camera_view", ojson{{"width", 96}}}, {"light_view", ojson{{"width", 64}}}}},
                       {"K", K},
                       {"timing", ojson{{"min_repetitions", 20}}},
                       {"generators", {"fis_tok15", "fis_modified"}}}},
      {"capture", ojson{{"hashes", ojson{{"gbuffer", ojson{{"P.X", hash}}}, {"rsm", ojson{{"P.X", hash}}}}}}},
      {"generators", gens}};
}

// n samples around `median` with relative noise `noise`, reproducible per row.
SampleSource noisy_source(double scale, double noise, std::size_t n = 20, unsigned seed = 1) {
  return [=](const std::string& g, const std::string& view, const std::string& phase) {
    std::mt19937 rng(seed + static_cast<unsigned>(std::hash<std::string>{}(g + view + phase) % 1000));
    std::uniform_real_distribution<double> u(-noise, noise);
    const double base = 0.1 + static_cast<double>(phase.size()) * 0.01;  // rows differ
    std::vector<double> s(n);
    for (auto& v : s) v = scale * base * (1.0 + u(rng));
    return s;
  };
}

BenchRun run_of(const ojson& doc) { return parse_bench_run(doc, "synthetic.json"); }

struct TempDir {
  explicit TempDir(const std::string& name) : temp("compare_" + name), path(temp.path()) {}
  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(path / name) << text;
    return path / name;
  }
  test::TempDir temp;
  fs::path path;
};

TEST(CompareRuns, RefusesTheTableOfAUserCaptureClearly) {
  ojson doc = synthetic_table_json(1, noisy_source(1.0, 0.01));
  doc["table"] = nullptr;
  doc["scene"] = "Sponza";
  try {
    run_of(doc);
    FAIL() << "a table of a user capture was read as a paper table";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is null"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("scene 'Sponza'"), std::string::npos) << e.what();
  }
}

TEST(CompareRuns, IdenticalRunsAreSameEverywhere) {
  const ojson doc = synthetic_table_json(1, noisy_source(1.0, 0.01));
  const RunComparison c = compare_runs(run_of(doc), run_of(doc), {});
  // 2 generators x (2 views x (3 phases + total) + total)
  ASSERT_EQ(c.rows.size(), 18u);
  EXPECT_EQ(c.count(Verdict::kSame), 18u);
  EXPECT_DOUBLE_EQ(c.geomean_ratio, 1.0);
  EXPECT_TRUE(c.only_in_base.empty());
}

TEST(CompareRuns, TenPercentShiftIsSlowerEverywhere) {
  const RunComparison c = compare_runs(run_of(synthetic_table_json(1, noisy_source(1.0, 0.01))),
                                       run_of(synthetic_table_json(1, noisy_source(1.10, 0.01, 20, 7))), {});
  EXPECT_EQ(c.count(Verdict::kSlower), c.rows.size());
  EXPECT_NEAR(c.geomean_ratio, 1.10, 0.01);
  EXPECT_NEAR(c.geomean_ratio_totals, 1.10, 0.01);
  // And the other way round.
  const RunComparison back = compare_runs(run_of(synthetic_table_json(1, noisy_source(1.10, 0.01, 20, 7))),
                                          run_of(synthetic_table_json(1, noisy_source(1.0, 0.01))), {});
  EXPECT_EQ(back.count(Verdict::kFaster), back.rows.size());
}

TEST(CompareRuns, HeavyOverlapIsAmbiguous) {
  // Medians 4.8 % apart, samples spread over 40 %: the medians moved, the test cannot tell.
  const auto spread = [](double shift) {
    return [shift](const std::string&, const std::string&, const std::string&) {
      std::vector<double> s;
      for (int k = 0; k < 10; ++k) s.push_back(1.0 + 0.5 * k / 9.0 + shift);
      return s;
    };
  };
  const RunComparison c =
      compare_runs(run_of(synthetic_table_json(1, spread(0.0))), run_of(synthetic_table_json(1, spread(0.06))), {});
  for (const auto& r : c.rows) {
    if (r.name.find("/total") != std::string::npos) continue;  // totals add up the shift of three phases
    EXPECT_EQ(r.result.verdict, Verdict::kAmbiguous) << r.name << " p = " << r.result.p_value;
  }
  EXPECT_GT(c.count(Verdict::kAmbiguous), 0u);
  EXPECT_EQ(c.count(Verdict::kSame), 0u);
}

TEST(CompareRuns, TooFewSamplesAreAmbiguous) {
  const RunComparison c = compare_runs(run_of(synthetic_table_json(1, noisy_source(1.0, 0.01, 3))),
                                       run_of(synthetic_table_json(1, noisy_source(2.0, 0.01, 3))), {});
  EXPECT_EQ(c.count(Verdict::kAmbiguous), c.rows.size());
  EXPECT_NE(c.rows[0].result.reason.find("too few samples"), std::string::npos);
}

TEST(CompareRuns, RefusesOtherCapturesAndConfigsUnlessAllowed) {
  const BenchRun base = run_of(synthetic_table_json(1, noisy_source(1.0, 0.01)));
  const BenchRun other_capture =
      run_of(synthetic_table_json(1, noisy_source(1.0, 0.01), "Test GPU", "fnv1a64:0000000000000002"));
  const BenchRun other_config =
      run_of(synthetic_table_json(1, noisy_source(1.0, 0.01), "Test GPU", "fnv1a64:0000000000000001", 4));
  try {
    compare_runs(base, other_capture, {});
    ADD_FAILURE() << "different captures were compared";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("different captures"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("--allow-mismatch"), std::string::npos) << e.what();
  }
  try {
    compare_runs(base, other_config, {});
    ADD_FAILURE() << "different configs were compared";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("different configs"), std::string::npos) << e.what();
  }
  CompareOptions allow;
  allow.allow_mismatch = true;
  const RunComparison c = compare_runs(base, other_capture, allow);
  ASSERT_EQ(c.mismatches.size(), 1u);
  EXPECT_NE(comparison_markdown(base, other_capture, c, allow).find("Mismatch allowed"), std::string::npos);
  // Only the timing protocol differs: comparable.
  ojson longer = synthetic_table_json(1, noisy_source(1.0, 0.01));
  longer["config"]["timing"]["min_repetitions"] = 50;
  EXPECT_NO_THROW(compare_runs(base, run_of(longer), {}));
}

TEST(CompareRuns, DifferentDevicesAreComparedAndLabelled) {
  const BenchRun a = run_of(synthetic_table_json(1, noisy_source(1.0, 0.01)));
  const BenchRun b = run_of(synthetic_table_json(1, noisy_source(1.0, 0.01), "Other GPU"));
  const RunComparison c = compare_runs(a, b, {});
  EXPECT_TRUE(c.different_devices);
  const std::string md = comparison_markdown(a, b, c, {});
  EXPECT_NE(md.find("Different devices"), std::string::npos);
  EXPECT_NE(md.find("| table1/fis_modified/light_view/filtered_sampling |"), std::string::npos) << md;
  EXPECT_NE(md.find("Geometric mean"), std::string::npos);
}

TEST(CompareRuns, RowsOfOneSideOnlyAreListedNotCompared) {
  ojson fewer = synthetic_table_json(1, noisy_source(1.0, 0.01));
  fewer["generators"].erase("fis_tok15");
  const RunComparison c = compare_runs(run_of(synthetic_table_json(1, noisy_source(1.0, 0.01))), run_of(fewer), {});
  EXPECT_EQ(c.rows.size(), 9u);
  EXPECT_EQ(c.only_in_base.size(), 9u);
  // Nothing in common at all is an error.
  EXPECT_THROW(compare_runs(run_of(synthetic_table_json(1, noisy_source(1.0, 0.01))),
                            run_of(synthetic_table_json(2, noisy_source(1.0, 0.01))), {}),
               InputError);
}

TEST(CompareRuns, MissingFieldsAreNamedByPointer) {
  ojson doc = synthetic_table_json(1, noisy_source(1.0, 0.01));
  doc["generators"]["fis_tok15"]["views"]["camera_view"]["phases"]["mipmapping"].erase("samples_ms");
  try {
    run_of(doc);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/generators/fis_tok15/views/camera_view/phases/mipmapping/samples_ms: missing field"),
              std::string::npos)
        << e.what();
  }
  ojson negative = synthetic_table_json(1, noisy_source(1.0, 0.01));
  negative["generators"]["fis_tok15"]["total"]["samples_ms"][0] = -1.0;
  EXPECT_THROW(run_of(negative), InputError);
  EXPECT_THROW(run_of(ojson{{"hello", 1}}), InputError);
}

ojson synthetic_gbench(int repetitions, double scale) {
  ojson benchmarks = ojson::array();
  for (int r = 0; r < repetitions; ++r)
    for (const std::string phase : {"additional", "total"}) {
      const std::string name = "table1/fis_modified/light_view/" + phase + "/iterations:30/manual_time";
      benchmarks.push_back(ojson{{"name", name}, {"run_name", name}, {"run_type", "iteration"}, {"repetitions", repetitions},
                                 {"repetition_index", r}, {"real_time", scale * (20.0 + r % 3)}, {"time_unit", "us"}});
    }
  if (repetitions > 1)  // Google Benchmark's aggregates: skipped
    benchmarks.push_back(ojson{{"name", "table1/fis_modified/light_view/total/iterations:30/manual_time_mean"},
                               {"run_name", "table1/fis_modified/light_view/total/iterations:30/manual_time"},
                               {"run_type", "aggregate"}, {"real_time", 1e9}, {"time_unit", "us"}});
  return ojson{{"context", ojson{{"date", "2026-01-01T00:00:00+00:00"},
                                 {"vsgl_device", "Test GPU"},
                                 {"vsgl_git_commit", "abc"},
                                 {"vsgl_config", R"({"K":1.0,"camera_vsgls":2048})"},
                                 {"vsgl_table1_capture_hashes", R"({"gbuffer":{"P.X":"a"},"rsm":{"P.X":"b"}})"}}},
               {"benchmarks", benchmarks}};
}

TEST(CompareRuns, GoogleBenchmarkRepetitionsAreTheSamples) {
  const BenchRun run = parse_bench_run(synthetic_gbench(9, 1.0), "gbench.json");
  ASSERT_EQ(run.series.size(), 2u);
  EXPECT_EQ(run.series[0].name, "table1/fis_modified/light_view/additional");
  EXPECT_EQ(run.series[1].samples_ms.size(), 9u);  // the aggregate is not a sample
  EXPECT_NEAR(run.series[0].median_ms, 0.021, 1e-12);  // us -> ms
  const RunComparison slower = compare_runs(run, parse_bench_run(synthetic_gbench(9, 1.2), "b.json"), {});
  EXPECT_EQ(slower.count(Verdict::kSlower), 2u);
  // Without --benchmark_repetitions: one sample per benchmark, nothing can be decided.
  const RunComparison single = compare_runs(parse_bench_run(synthetic_gbench(1, 1.0), "a.json"),
                                            parse_bench_run(synthetic_gbench(1, 1.2), "b.json"), {});
  EXPECT_EQ(single.count(Verdict::kAmbiguous), 2u);
  // A table JSON and a gbench JSON do not compare (samples mean different things).
  EXPECT_THROW(compare_runs(run_of(synthetic_table_json(1, noisy_source(1.0, 0.01))), run, {}), InputError);
  ojson failed = synthetic_gbench(2, 1.0);
  failed["benchmarks"][0]["error_occurred"] = true;
  EXPECT_THROW(parse_bench_run(failed, "failed.json"), InputError);
}

TEST(CompareRuns, CommittedResultsLoad) {
  const fs::path dir = fs::path(VSGL_SOURCE_DIR) / "results/nvidia-h100-80gb-hbm3";
  const BenchRun tables = load_bench_run_path(dir);  // table1.json + table2.json
  EXPECT_EQ(tables.tables.size(), 2u);
  EXPECT_EQ(tables.series.size(), 2u * 6u * (2u * 4u + 1u));
  EXPECT_EQ(tables.series.front().name, "table1/fis_tok15/camera_view/additional");
  const BenchRun gbench = load_bench_run(dir / "gbench.json");
  EXPECT_EQ(gbench.format, "gbench");
  EXPECT_EQ(gbench.series.size(), 96u);
  EXPECT_NE(gbench.find("table2/kmeans_3d/light_view/total"), nullptr);
  EXPECT_EQ(gbench.tables.at(1).capture_hashes, tables.tables.at(1).capture_hashes);
  // A run compared with itself through the CLI: every row SAME, exit 0 even with the gate on.
  const auto self = run_cli("compare " + dir.string() + " " + dir.string() + " --fail-on slower,ambiguous");
  EXPECT_EQ(self.exit_code, 0) << self.output;
  EXPECT_NE(self.output.find("108 rows compared: 0 FASTER, 0 SLOWER, 108 SAME, 0 AMBIGUOUS"), std::string::npos)
      << self.output;
}

TEST(CompareCli, ExitCodesMakeACiGate) {
  const TempDir dir("cli");
  const fs::path base = dir.write("base.json", synthetic_table_json(1, noisy_source(1.0, 0.01)).dump());
  const fs::path slow = dir.write("slow.json", synthetic_table_json(1, noisy_source(1.10, 0.01, 20, 7)).dump());
  const auto report = run_cli("compare " + base.string() + " " + slow.string() + " --out " + (dir.path / "r.md").string());
  EXPECT_EQ(report.exit_code, 0) << report.output;  // no gate: a report only
  EXPECT_NE(report.output.find("**SLOWER**"), std::string::npos) << report.output;
  EXPECT_TRUE(fs::exists(dir.path / "r.md"));
  const auto gate = run_cli("compare " + base.string() + " " + slow.string() + " --fail-on slower");
  EXPECT_EQ(gate.exit_code, 1) << gate.output;
  const auto pass = run_cli("compare " + slow.string() + " " + base.string() + " --fail-on slower");
  EXPECT_EQ(pass.exit_code, 0) << pass.output;  // faster is not a regression
  // 10 % is below a 20 % minimum change: SAME.
  const auto lenient = run_cli("compare " + base.string() + " " + slow.string() + " --fail-on slower --min-change 20%");
  EXPECT_EQ(lenient.exit_code, 0) << lenient.output;
}

TEST(CompareCli, BadInputsExitWithThreeBadCommandLinesWithTwoAndSayWhy) {
  const TempDir dir("bad");
  const std::string good_text = synthetic_table_json(1, noisy_source(1.0, 0.01)).dump(2);
  const fs::path good = dir.write("good.json", good_text);
  const fs::path truncated = dir.write("truncated.json", good_text.substr(0, good_text.size() / 2));
  const fs::path garbage = dir.write("garbage.json", "not json at all");
  ojson missing_doc = synthetic_table_json(1, noisy_source(1.0, 0.01));
  missing_doc.erase("capture");
  const fs::path missing = dir.write("missing.json", missing_doc.dump());
  const fs::path other =
      dir.write("other.json", synthetic_table_json(1, noisy_source(1.0, 0.01), "Test GPU", "fnv1a64:ff").dump());
  struct Case {
    std::string args, expect;
    int exit_code;
  };
  for (const Case& c : {Case{good.string() + " " + truncated.string(), "not valid JSON", 3},
                        Case{garbage.string() + " " + good.string(), "not valid JSON", 3},
                        Case{good.string() + " " + missing.string(), "/capture: missing field", 3},
                        Case{good.string() + " " + other.string(), "different captures", 3},
                        Case{good.string() + " " + (dir.path / "absent.json").string(), "cannot read", 3},
                        Case{good.string(), "NEW is required", 2},
                        Case{good.string() + " " + good.string() + " --alpha 2", "--alpha", 2},
                        Case{good.string() + " " + good.string() + " --min-samples 1", "--min-samples", 2}}) {
    SCOPED_TRACE(c.args);
    const auto r = run_cli("compare " + c.args + " --fail-on slower");
    EXPECT_EQ(r.exit_code, c.exit_code) << r.output;
    EXPECT_NE(r.output.find(c.expect), std::string::npos) << r.output;
  }
  const auto bad_gate = run_cli("compare " + good.string() + " " + good.string() + " --fail-on everything");
  EXPECT_EQ(bad_gate.exit_code, 2) << bad_gate.output;
  EXPECT_NE(bad_gate.output.find("--fail-on: takes"), std::string::npos) << bad_gate.output;
  const auto allowed = run_cli("compare " + good.string() + " " + other.string() + " --allow-mismatch --fail-on slower");
  EXPECT_EQ(allowed.exit_code, 0) << allowed.output;
  EXPECT_NE(allowed.output.find("Mismatch allowed"), std::string::npos);
}

}  // namespace
}  // namespace vsgl
