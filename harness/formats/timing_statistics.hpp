#pragma once
// DESIGN.md §9's statistics of one timed series (ms), as the documents state them: one type for
// the table and the sweep documents, which write it each in its own layout (the keys differ; a
// committed file's keys never change).
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace vsgl {

class JsonReader;  // core/json_reader.hpp

struct TimingStatistics {
  std::vector<double> samples_ms;  // every timed round, positive
  double median_ms = 0;
  double q1_ms = 0;  // type-7 quartiles (core/statistics.hpp): q1 <= median <= q3
  double q3_ms = 0;
  std::optional<double> min_ms, max_ms, mean_ms;
  std::optional<double> stdev_ms;      // sample standard deviation (n - 1)
  std::optional<double> relative_iqr;  // (q3 - q1) / median, the stop rule's noise
  std::optional<uint64_t> count;
  // The paper's number for the series, beside it in a document that compares (the table's;
  // null there: the paper has no number here).
  std::optional<double> paper_ms;
};

// Every statistic of `samples` (core/statistics.hpp summarize). Throws std::invalid_argument for
// fewer than 2 samples or one that is not finite.
TimingStatistics timing_statistics(std::span<const double> samples, std::optional<double> paper_ms = std::nullopt);

// How a document writes the statistics.
enum class StatisticsLayout {
  // The table's (results/schema/table.schema.json): one object, keys with the unit ("median_ms",
  // "q1_ms", ...), the paper's number and the samples inside it; the optional ones only when set.
  kTable,
  // The sweep's (results/schema/sweep.schema.json): {"stats": {count, median, q1, q3, min, max,
  // mean, stdev}, "samples_ms": [...]}, keys without the unit; every statistic is required.
  kSweep,
};

// Throws std::invalid_argument when the layout needs a statistic the series lacks.
nlohmann::ordered_json to_json(const TimingStatistics& statistics, StatisticsLayout layout);
// `value` is what to_json writes, at `path`. Throws InputError naming the pointer of a missing or
// mistyped field, a time that is not positive, and quartiles that do not enclose the median.
TimingStatistics timing_statistics_from_json(const JsonReader& reader, const nlohmann::ordered_json& value,
                                             const std::string& path, StatisticsLayout layout);

}  // namespace vsgl
