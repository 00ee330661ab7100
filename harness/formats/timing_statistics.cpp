#include "harness/formats/timing_statistics.hpp"

#include <stdexcept>

#include <nlohmann/json.hpp>

#include "harness/core/json_reader.hpp"
#include "harness/core/statistics.hpp"
#include "harness/core/text_format.hpp"

namespace vsgl {
namespace {

using ojson = nlohmann::ordered_json;

double required(const std::optional<double>& v, const char* name) {
  if (!v) throw std::invalid_argument(std::string("the sweep's statistics need ") + name);
  return *v;
}

ojson table_json(const TimingStatistics& s) {
  ojson o{{"median_ms", s.median_ms}, {"paper_ms", s.paper_ms ? ojson(*s.paper_ms) : ojson(nullptr)}};
  if (s.min_ms) o["min_ms"] = *s.min_ms;
  if (s.max_ms) o["max_ms"] = *s.max_ms;
  o["q1_ms"] = s.q1_ms;
  o["q3_ms"] = s.q3_ms;
  if (s.mean_ms) o["mean_ms"] = *s.mean_ms;
  if (s.stdev_ms) o["stdev_ms"] = *s.stdev_ms;
  if (s.relative_iqr) o["relative_iqr"] = *s.relative_iqr;
  if (s.count) o["count"] = *s.count;
  o["samples_ms"] = s.samples_ms;
  return o;
}

ojson sweep_json(const TimingStatistics& s) {
  if (!s.count) throw std::invalid_argument("the sweep's statistics need count");
  const ojson stats{{"count", *s.count},
                    {"median", s.median_ms},
                    {"q1", s.q1_ms},
                    {"q3", s.q3_ms},
                    {"min", required(s.min_ms, "min")},
                    {"max", required(s.max_ms, "max")},
                    {"mean", required(s.mean_ms, "mean")},
                    {"stdev", required(s.stdev_ms, "stdev")}};
  return ojson{{"stats", stats}, {"samples_ms", s.samples_ms}};
}

void check_quartiles(const JsonReader& r, const TimingStatistics& s, const std::string& path) {
  if (!(s.q1_ms <= s.median_ms && s.median_ms <= s.q3_ms))
    r.fail(path, "has quartiles that do not enclose the median (q1 " + number_text(s.q1_ms, 6) + ", median " +
                     number_text(s.median_ms, 6) + ", q3 " + number_text(s.q3_ms, 6) + ")");
}

TimingStatistics read_table(const JsonReader& r, const ojson& s, const std::string& p) {
  if (!s.is_object()) r.wrong_type(s, p, "an object");
  TimingStatistics out;
  out.samples_ms = r.times(s, p, "samples_ms");
  out.median_ms = r.time(s, p, "median_ms");
  out.q1_ms = r.time(s, p, "q1_ms");
  out.q3_ms = r.time(s, p, "q3_ms");
  out.paper_ms = r.optional_number(s, p, "paper_ms");
  out.min_ms = r.optional_number(s, p, "min_ms");
  out.max_ms = r.optional_number(s, p, "max_ms");
  out.mean_ms = r.optional_number(s, p, "mean_ms");
  out.stdev_ms = r.optional_number(s, p, "stdev_ms");
  out.relative_iqr = r.optional_number(s, p, "relative_iqr");
  out.count = r.optional_uint64(s, p, "count");
  check_quartiles(r, out, p);
  return out;
}

TimingStatistics read_sweep(const JsonReader& r, const ojson& series, const std::string& p) {
  if (!series.is_object()) r.wrong_type(series, p, "an object");
  const ojson& stats = r.object(series, p, "stats");
  const std::string sp = r.child(p, "stats");
  TimingStatistics out;
  out.count = r.uint64(stats, sp, "count");
  out.median_ms = r.time(stats, sp, "median");
  out.q1_ms = r.time(stats, sp, "q1");
  out.q3_ms = r.time(stats, sp, "q3");
  out.min_ms = r.time(stats, sp, "min");
  out.max_ms = r.time(stats, sp, "max");
  out.mean_ms = r.time(stats, sp, "mean");
  out.stdev_ms = r.non_negative(r.member(stats, sp, "stdev"), r.child(sp, "stdev"));
  check_quartiles(r, out, sp);
  out.samples_ms = r.times(series, p, "samples_ms");
  return out;
}

}  // namespace

TimingStatistics timing_statistics(std::span<const double> samples, std::optional<double> paper_ms) {
  const SampleStats s = summarize(samples);
  TimingStatistics out;
  out.samples_ms.assign(samples.begin(), samples.end());
  out.median_ms = s.median;
  out.q1_ms = s.q1;
  out.q3_ms = s.q3;
  out.min_ms = s.min;
  out.max_ms = s.max;
  out.mean_ms = s.mean;
  out.stdev_ms = s.stdev;
  out.relative_iqr = relative_iqr(s);
  out.count = s.count;
  out.paper_ms = paper_ms;
  return out;
}

nlohmann::ordered_json to_json(const TimingStatistics& statistics, StatisticsLayout layout) {
  return layout == StatisticsLayout::kTable ? table_json(statistics) : sweep_json(statistics);
}

TimingStatistics timing_statistics_from_json(const JsonReader& reader, const nlohmann::ordered_json& value,
                                             const std::string& path, StatisticsLayout layout) {
  return layout == StatisticsLayout::kTable ? read_table(reader, value, path) : read_sweep(reader, value, path);
}

}  // namespace vsgl
