#include "harness/compare/export_formats.hpp"

#include <cstdio>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "harness/core/error.hpp"
#include "harness/core/json_schema_subset.hpp"

namespace vsgl {
namespace {

using ojson = nlohmann::ordered_json;

std::string number_text(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// The stable name with the scene it was timed on, so a tracker never joins a stand-in's history to
// the paper scene's: "table1/fis_modified/total [sponza, paper scene]".
std::string export_name(const BenchRun& run, const RunSeries& s) {
  const auto t = run.tables.find(s.table);
  if (t == run.tables.end() || !t->second.scene) return s.name;
  return s.name + " [" + scene_label(*t->second.scene) + "]";
}

ojson gab(const BenchRun& run) {
  ojson out = ojson::array();
  for (const RunSeries& s : run.series) {
    const std::string extra = "q1 " + number_text(s.q1_ms) + " ms .. q3 " + number_text(s.q3_ms) + " ms, " +
                              std::to_string(s.samples_ms.size()) + " samples; " + run.device + "; commit " +
                              run.git_commit +
                              (run.altered_generators.empty() ? "" : "; altered timings, not a measurement");
    out.push_back(ojson{{"name", export_name(run, s)},
                        {"unit", "ms"},
                        {"value", s.median_ms},
                        {"range", "± " + number_text(0.5 * (s.q3_ms - s.q1_ms))},
                        {"extra", extra}});
  }
  return out;
}

ojson bmf(const BenchRun& run) {
  constexpr double kNsPerMs = 1e6;
  ojson out = ojson::object();
  for (const RunSeries& s : run.series)
    out[export_name(run, s)] = ojson{{"latency", ojson{{"value", s.median_ms * kNsPerMs},
                                                       {"lower_value", s.q1_ms * kNsPerMs},
                                                       {"upper_value", s.q3_ms * kNsPerMs}}}};
  return out;
}

}  // namespace

ExportFormat parse_export_format(const std::string& name) {
  if (name == "gab") return ExportFormat::kGithubActionBenchmark;
  if (name == "bmf") return ExportFormat::kBencherMetricFormat;
  throw UsageError("--format takes gab (github-action-benchmark customSmallerIsBetter) or bmf (Bencher Metric "
                   "Format), not '" + name + "'");
}

nlohmann::ordered_json export_schema(ExportFormat format) {
  if (format == ExportFormat::kGithubActionBenchmark)
    return nlohmann::ordered_json::parse(R"({
      "type": "array", "minItems": 1,
      "items": {"type": "object", "required": ["name", "unit", "value"], "additionalProperties": false,
                "properties": {"name": {"type": "string"}, "unit": {"const": "ms"},
                               "value": {"type": "number", "exclusiveMinimum": 0},
                               "range": {"type": "string"}, "extra": {"type": "string"}}}})");
  return nlohmann::ordered_json::parse(R"({
      "type": "object",
      "additionalProperties": {
        "type": "object", "required": ["latency"], "additionalProperties": false,
        "properties": {"latency": {"type": "object", "required": ["value"], "additionalProperties": false,
                                   "properties": {"value": {"type": "number", "exclusiveMinimum": 0},
                                                  "lower_value": {"type": "number", "exclusiveMinimum": 0},
                                                  "upper_value": {"type": "number", "exclusiveMinimum": 0}}}}}})");
}

ojson export_run(const BenchRun& run, ExportFormat format) {
  if (run.series.empty()) throw InputError(run.path + ": no benchmark to export");
  ojson out = format == ExportFormat::kGithubActionBenchmark ? gab(run) : bmf(run);
  require_finite_numbers(out);
  const auto problems = validate_against_schema(out, export_schema(format));
  if (!problems.empty()) throw std::logic_error("export does not have its documented shape: " + problems.front());
  return out;
}

}  // namespace vsgl
