#pragma once
// `vsgl-bench export` (DESIGN.md §10): a run's series (regression_run.hpp, stable names such as
// "table1/fis_modified/light_view/filtered_sampling") in the formats dashboards read.
//
// gab — github-action-benchmark, tool "customSmallerIsBetter": a JSON array of
//   {"name": stable name, "unit": "ms", "value": median,
//    "range": "± (q3 - q1) / 2" (half the interquartile range, as text),
//    "extra": "q1 .. q3 ms, n samples, device, commit"}.
// bmf — Bencher Metric Format: {stable name: {"latency": {"value": median, "lower_value": q1,
//   "upper_value": q3}}}, in nanoseconds (Bencher's built-in latency measure is in ns).
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "harness/compare/regression_run.hpp"

namespace vsgl {

enum class ExportFormat { kGithubActionBenchmark, kBencherMetricFormat };

// "gab" | "bmf"; throws UsageError for anything else.
ExportFormat parse_export_format(const std::string& name);

nlohmann::ordered_json export_run(const BenchRun& run, ExportFormat format);

// The documented shape of each format as a schema for harness/core/json_schema_subset.hpp; the
// exporter checks its own output against it before anything is written.
nlohmann::ordered_json export_schema(ExportFormat format);

}  // namespace vsgl
