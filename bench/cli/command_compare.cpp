// `vsgl-bench compare BASE NEW` (DESIGN.md §10): a FASTER / SLOWER / SAME / AMBIGUOUS verdict per
// benchmark row of two runs (table JSON, a directory of them, or Google Benchmark JSON with
// repetitions), a markdown report, and an exit status a CI gate can use:
//   0 no verdict listed in --fail-on · 1 some (a regression) · 2 error (bad command line, unreadable
//   or malformed input, incomparable runs).
// The work is harness/compare/regression_compare.hpp.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "bench/cli/commands.hpp"
#include "harness/core/atomic_file.hpp"
#include "harness/core/error.hpp"
#include "harness/compare/regression_compare.hpp"

namespace vsgl::cli {

std::vector<std::string> take_positionals(std::vector<std::string>& tokens, const std::vector<std::string>& value_options) {
  std::vector<std::string> positionals, options;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const std::string& t = tokens[i];
    if (t.rfind("--", 0) != 0) {
      positionals.push_back(t);
      continue;
    }
    options.push_back(t);
    const bool takes_value = std::find(value_options.begin(), value_options.end(), t) != value_options.end();
    if (takes_value && i + 1 < tokens.size()) options.push_back(tokens[++i]);
  }
  tokens = options;
  return positionals;
}

namespace {

constexpr int kCompareError = 2;  // the contract: 0 ok, 1 regression, 2 error

// A number in [0, 1) (open_upper) or [0, 1]; "2%" reads as 0.02 where `percent_ok`.
double fraction(Args& args, const std::string& name, double fallback, bool open_upper, bool percent_ok = false) {
  const auto v = args.value(name);
  if (!v) return fallback;
  std::string text = *v;
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
  if (text.empty() || used != text.size() || !(d >= 0) || (open_upper ? !(d < 1) : !(d <= 1)))
    throw UsageError(name + " takes a number in [0, 1" + (open_upper ? ")" : "]") + (percent_ok ? " or a percentage" : "") +
                     ", not '" + *v + "'");
  return d;
}

}  // namespace

int run_compare(std::vector<std::string> tokens) {
  const std::vector<std::string> files =
      take_positionals(tokens, {"--alpha", "--min-change", "--noise-factor", "--min-samples", "--fail-on", "--out"});
  Args args(tokens);
  CompareOptions options;
  options.verdict.alpha = fraction(args, "--alpha", 0.05, true);
  // --min-change 0.02 or 2%: the relative change of the median below which nothing matters.
  options.verdict.min_change = fraction(args, "--min-change", 0.02, false, true);
  // --noise-factor F: a change must also exceed F x the runs' relative IQR (0 = off).
  if (const auto f = args.value("--noise-factor")) {
    Args one(std::vector<std::string>{"--noise-factor", *f});
    options.verdict.noise_factor = *f == "0" ? 0.0 : double{one.positive_float("--noise-factor", 1.0f)};
  }
  options.verdict.min_samples = args.u32("--min-samples", 5, 2);
  options.allow_mismatch = args.flag("--allow-mismatch");
  const std::vector<Verdict> fail_on = parse_fail_on(args.string("--fail-on", "none"));
  const auto out = args.value("--out");
  args.finish();
  if (files.size() != 2)
    throw UsageError("compare takes two runs, BASE and NEW (table JSON, a directory of tableN.json, or Google "
                     "Benchmark JSON), not " + std::to_string(files.size()));
  if (!(options.verdict.alpha > 0)) throw UsageError("--alpha must be positive");

  try {
    const BenchRun base = load_bench_run_path(files[0]);
    const BenchRun fresh = load_bench_run_path(files[1]);
    const RunComparison c = compare_runs(base, fresh, options);
    const std::string report = comparison_markdown(base, fresh, c, options);
    if (out) write_text_atomic(*out, report);
    std::fputs(report.c_str(), stdout);
    std::size_t failing = 0;
    for (Verdict v : fail_on) failing += c.count(v);
    if (failing > 0) {
      std::fprintf(stderr, "vsgl-bench compare: %zu row(s) with a verdict in --fail-on: failing\n", failing);
      return static_cast<int>(ExitCode::kFailure);
    }
    return 0;
  } catch (const std::exception& e) {  // InputError and anything else: an error, not a regression
    std::fprintf(stderr, "vsgl-bench compare: error: %s\n", e.what());
    return kCompareError;
  }
}

}  // namespace vsgl::cli
