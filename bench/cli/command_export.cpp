// `vsgl-bench export --format gab|bmf RUN [RUN...] --out FILE` (DESIGN.md §10): a run's medians and
// quartiles under stable names for dashboards (harness/compare/export_formats.hpp). RUN is a table JSON, a
// directory of table*.json (one `tables` run) or Google Benchmark JSON; several are merged.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "bench/cli/option_types.hpp"

#include "bench/cli/commands.hpp"
#include "harness/core/platform_path.hpp"
#include "harness/core/atomic_file.hpp"
#include "harness/core/error.hpp"
#include "harness/core/generator_ids.hpp"
#include "harness/compare/export_formats.hpp"

namespace vsgl::cli {

Command add_export_command(CLI::App& parent) {
  CLI::App* app = parent.add_subcommand(
      "export",
      "medians and quartiles under stable names (table1/" + std::string(kFisModified) +
          "/light_view/filtered_sampling) for "
          "github-action-benchmark (gab: customSmallerIsBetter) or Bencher (bmf: Bencher Metric Format, ns); several "
          "runs are merged");
  struct Options {
    std::string format;
    std::vector<std::string> runs;
    std::string out;
  };
  auto o = std::make_shared<Options>();
  app->add_option("--format", o->format, "gab or bmf")
      ->required()
      ->check(usage_checked([](const std::string& t) { (void)parse_export_format(t); }, "gab|bmf"));
  app->add_option("--out", o->out, "output file")->required()->type_name("FILE");
  app->add_option("RUN", o->runs, "a table JSON, a directory of table*.json (one `tables` run) or Google Benchmark JSON")
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->required();
  return {app, [o] {
            std::vector<BenchRun> runs;
            for (const auto& f : o->runs) runs.push_back(load_bench_run_path(path_from_utf8(f)));
            const BenchRun run = merge_bench_runs(runs);
            write_text_atomic(path_from_utf8(o->out), export_run(run, parse_export_format(o->format)).dump(2) + "\n");
            std::fprintf(stderr, "wrote %s (%zu benchmarks)\n", o->out.c_str(), run.series.size());
            return 0;
          }};
}

}  // namespace vsgl::cli
