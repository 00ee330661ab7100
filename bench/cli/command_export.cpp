// `vsgl-bench export --format gab|bmf RUN [RUN...] --out FILE` (DESIGN.md §10): a run's medians and
// quartiles under stable names for dashboards (harness/compare/export_formats.hpp). RUN is a table JSON, a
// directory of table*.json (one `tables` run) or Google Benchmark JSON; several are merged.
#include <cstdio>

#include "bench/cli/commands.hpp"
#include "harness/core/atomic_file.hpp"
#include "harness/core/error.hpp"
#include "harness/compare/export_formats.hpp"

namespace vsgl::cli {

int run_export(std::vector<std::string> tokens) {
  const std::vector<std::string> files = take_positionals(tokens, {"--format", "--out"});
  Args args(tokens);
  const auto format_name = args.value("--format");
  const auto out = args.value("--out");
  args.finish();
  if (!format_name) throw UsageError("export needs --format gab|bmf");
  const ExportFormat format = parse_export_format(*format_name);
  if (!out) throw UsageError("export needs --out FILE");
  if (files.empty()) throw UsageError("export needs at least one run (table JSON, a directory, or Google Benchmark JSON)");
  std::vector<BenchRun> runs;
  for (const auto& f : files) runs.push_back(load_bench_run_path(f));
  const BenchRun run = merge_bench_runs(runs);
  write_text_atomic(*out, export_run(run, format).dump(2) + "\n");
  std::fprintf(stderr, "wrote %s (%zu benchmarks)\n", out->c_str(), run.series.size());
  return 0;
}

}  // namespace vsgl::cli
