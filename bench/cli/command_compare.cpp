// `vsgl-bench compare BASE NEW` (DESIGN.md §10): a FASTER / SLOWER / SAME / AMBIGUOUS verdict per
// benchmark row of two runs (table JSON, a directory of them, or Google Benchmark JSON with
// repetitions), a markdown report, and an exit status a CI gate can use:
//   0 no verdict listed in --fail-on · 1 some (a regression) · 2 bad command line · 3 unreadable or
//   malformed input, incomparable runs (bad input, as for every command).
// The work is harness/compare/regression_compare.hpp.
#include <memory>
#include <optional>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "bench/cli/commands.hpp"
#include "harness/core/platform_path.hpp"
#include "harness/core/atomic_file.hpp"
#include "harness/core/error.hpp"
#include "harness/core/program_name.hpp"
#include "bench/cli/option_types.hpp"
#include "harness/compare/regression_compare.hpp"

namespace vsgl::cli {

namespace {

// A number in [0, 1) (open_upper) or [0, 1]; "2%" reads as 0.02 where `percent_ok`.
std::optional<double> read_fraction(std::string text, bool open_upper, bool percent_ok) {
  double scale = 1.0;
  if (percent_ok && !text.empty() && text.back() == '%') {
    text.pop_back();
    scale = 0.01;
  }
  std::size_t used = 0;
  double d = -1;
  try {
    d = std::stod(text, &used) * scale;
  } catch (const std::exception&) {
    used = 0;
  }
  if (text.empty() || used != text.size() || !(d >= 0) || (open_upper ? !(d < 1) : !(d <= 1))) return std::nullopt;
  return d;
}

CLI::Option* add_fraction_option(CLI::App& app, const std::string& name, double& target, const std::string& description,
                                 bool open_upper, bool percent_ok = false) {
  const std::string range = std::string("a number in [0, 1") + (open_upper ? ")" : "]") + (percent_ok ? " or a percentage" : "");
  return app
      .add_option_function<std::string>(
          name, [&target, open_upper, percent_ok](const std::string& t) { target = *read_fraction(t, open_upper, percent_ok); },
          description)
      ->check(CLI::Validator(
          [open_upper, percent_ok, range](std::string& t) {
            return read_fraction(t, open_upper, percent_ok) ? std::string() : "takes " + range + ", not '" + t + "'";
          },
          "X"));
}

struct CompareCommandOptions {
  std::string base, fresh;
  CompareOptions options;
  std::string fail_on = "none";
  std::optional<std::string> out;
};

int run_compare(const CompareCommandOptions& o) {
  const CompareOptions& options = o.options;
  const std::vector<Verdict> fail_on = parse_fail_on(o.fail_on);
  const BenchRun base = load_bench_run_path(path_from_utf8(o.base));
  const BenchRun fresh = load_bench_run_path(path_from_utf8(o.fresh));
  const RunComparison c = compare_runs(base, fresh, options);
  const std::string report = comparison_markdown(base, fresh, c, options);
  if (o.out) write_text_atomic(path_from_utf8(*o.out), report);
  std::fputs(report.c_str(), stdout);
  std::size_t failing = 0;
  for (Verdict v : fail_on) failing += c.count(v);
  if (failing > 0) {
    std::fprintf(stderr, "%s compare: %zu row(s) with a verdict in --fail-on: failing\n", program_name().c_str(), failing);
    return static_cast<int>(ExitCode::kFailure);
  }
  return 0;
}

}  // namespace

Command add_compare_command(CLI::App& parent) {
  CLI::App* app = parent.add_subcommand(
      "compare",
      "a FASTER / SLOWER / SAME / AMBIGUOUS verdict per phase, view total and generator total of two runs from "
      "their raw samples (Mann-Whitney U test + a minimum change), as a markdown report with the change in % and "
      "a geometric-mean summary; refuses other captures or configs unless --allow-mismatch. Exit 1 when a row's "
      "verdict is in --fail-on (a CI gate), 3 for unreadable or incomparable runs");
  auto o = std::make_shared<CompareCommandOptions>();
  const std::string run_kinds =
      "a tableN.json, a directory of them, or vsgl-gbench JSON run with --benchmark_repetitions=5 or more";
  app->add_option("BASE", o->base, "the baseline run: " + run_kinds)->required();
  app->add_option("NEW", o->fresh, "the new run, of the same kind")->required();
  add_fraction_option(*app, "--alpha", o->options.verdict.alpha, "significance level of the U test", true)
      ->check(CLI::Validator([](std::string& t) { return std::stod(t) > 0 ? std::string() : "must be positive"; }, ""))
      ->default_str("0.05");
  add_fraction_option(*app, "--min-change", o->options.verdict.min_change,
                      "smallest relevant change of the median (0.02 or 2%)", false, true)
      ->default_str("2%");
  app->add_option("--noise-factor", o->options.verdict.noise_factor,
                  "a change must also exceed F x the larger relative IQR of the two runs, else AMBIGUOUS (0: off)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app->add_option("--min-samples", o->options.verdict.min_samples, "fewer samples on a side: AMBIGUOUS")
      ->check(at_least(2))
      ->capture_default_str();
  app->add_option("--fail-on", o->fail_on, "exit 1 when a row is slower / ambiguous / faster (comma-separated) or none")
      ->check(usage_checked([](const std::string& t) { (void)parse_fail_on(t); }, "V[,V]"))
      ->capture_default_str();
  app->add_flag("--allow-mismatch", o->options.allow_mismatch,
                "compare runs on different captures or configs (labelled in the report)");
  add_optional(*app, "--out", o->out, "also write the report")->type_name("FILE");
  return {app, [o] { return run_compare(*o); }};
}

}  // namespace vsgl::cli
