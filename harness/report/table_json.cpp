#include "harness/report/table_json.hpp"

#include <optional>
#include <stdexcept>

#include "harness/core/error.hpp"
#include "harness/core/generator_ids.hpp"
#include "harness/core/line_diff.hpp"
#include "harness/core/statistics.hpp"
#include "harness/generators/fis/fis_traffic.hpp"
#include "harness/generators/generator_registry.hpp"
#include "harness/report/paper_tables.hpp"
#include "harness/report/table_claims.hpp"

namespace vsgl {
namespace {

using ojson = nlohmann::ordered_json;

// The two FIS columns the overhead compares (core/generator_ids.hpp).
const std::string kTok15(kFisTok15), kModified(kFisModified);

GeneratorTiming generator_timing(const MeasuredTable& t, const std::string& g, const ReportContext& ctx) {
  GeneratorTiming out;
  out.name = g;
  out.label = generator_label(g);
  out.in_paper = generator_in_paper(g);
  for (const char* view : kTableViews) {
    const CaseTiming& c = need_case(t, g, view);
    ViewTiming v;
    for (std::size_t p = 0; p < c.phases.size(); ++p)
      v.phases.push_back(
          {c.phases[p], timing_statistics(c.phase_ms[p], paper_number(ctx.paper, {"tables", std::to_string(t.number), g,
                                                                                  view, c.phases[p]}))});
    v.total = timing_statistics(c.total_ms, paper_view_total(ctx.paper, t.number, g, view));
    v.dispatch_calls = c.dispatch_count;
    out.views[view] = std::move(v);
  }
  out.total = timing_statistics(generator_totals(t, g), paper_total(ctx.paper, t.number, g));
  return out;
}

// One paired difference (ms in, µs out) with the paper's difference beside it.
PairedDifference paired_difference(const PairedInterval& p, std::optional<double> paper_ms) {
  return PairedDifference{p.count,           1e3 * p.median,      1e3 * p.hodges_lehmann,
                          1e3 * p.low,       1e3 * p.high,        p.confidence,
                          p.reaches_nominal(), p.exact ? "exact" : "normal",
                          paper_ms ? std::optional<double>(1e3 * *paper_ms) : std::nullopt};
}

std::optional<double> paper_difference(std::optional<double> modified, std::optional<double> tok15) {
  return modified && tok15 ? std::optional<double>(*modified - *tok15) : std::nullopt;
}

// DESIGN.md §9: the overhead from per-round differences, so that drift and the noise of the shared
// passes cancel. Views: the total and the one pass the two generators do not share.
PairedOverhead paired_block(const MeasuredTable& t, const ReportContext& ctx) {
  const std::string table = std::to_string(t.number);
  PairedOverhead o;
  o.estimator = "Hodges-Lehmann (median of the Walsh averages of the per-round differences)";
  o.interval = "distribution-free, Wilcoxon signed-rank critical value (exact up to " + std::to_string(kSignedRankExactMax) +
               " rounds, normal approximation above)";
  o.nominal_confidence = kPairedConfidence;
  for (const char* view : kTableViews) {
    const auto paper_phase = [&](const std::string& g) {
      return paper_number(ctx.paper, {"tables", table, g, view, "filtered_sampling"});
    };
    o.views[view] = {paired_difference(paired_overhead(t, view, "total"),
                                       paper_difference(paper_view_total(ctx.paper, t.number, kModified, view),
                                                        paper_view_total(ctx.paper, t.number, kTok15, view))),
                     paired_difference(paired_overhead(t, view, "filtered_sampling"),
                                       paper_difference(paper_phase(kModified), paper_phase(kTok15)))};
  }
  o.total = paired_difference(paired_overhead(t), paper_difference(paper_total(ctx.paper, t.number, kModified),
                                                                   paper_total(ctx.paper, t.number, kTok15)));
  return o;
}

std::optional<double> paper_ratio(std::optional<double> num, std::optional<double> den) {
  return num && den ? std::optional<double>(*num / *den) : std::nullopt;
}

// The difference of the medians, kept beside the paired one.
KeyedRatios median_differences(const MeasuredTable& t, const ReportContext& ctx) {
  KeyedRatios o;
  const auto us = [](std::optional<double> m, std::optional<double> tk) {
    return m && tk ? std::optional<double>(1e3 * (*m - *tk)) : std::nullopt;
  };
  for (const char* view : kTableViews)
    o.emplace_back(view, MeasuredVsPaper{1e3 * (median_view(t, kModified, view) - median_view(t, kTok15, view)),
                                         us(paper_view_total(ctx.paper, t.number, kModified, view),
                                            paper_view_total(ctx.paper, t.number, kTok15, view))});
  o.emplace_back("total", MeasuredVsPaper{1e3 * (median_total(t, kModified) - median_total(t, kTok15)),
                                          us(paper_total(ctx.paper, t.number, kModified),
                                             paper_total(ctx.paper, t.number, kTok15))});
  return o;
}

KeyedRatios kmeans_over_modified(const MeasuredTable& t, const ReportContext& ctx) {
  KeyedRatios o;
  const auto pm = paper_total(ctx.paper, t.number, kModified);
  for (const auto& g : t.generators)
    if (generator_descriptor(g).family == GeneratorFamily::kKmeans)
      o.emplace_back(g, MeasuredVsPaper{median_total(t, g) / median_total(t, kModified),
                                        paper_ratio(paper_total(ctx.paper, t.number, g), pm)});
  return o;
}

KeyedRatios table1_to_table2(const MeasuredTable& t, const MeasuredTable& other, const ReportContext& ctx) {
  const MeasuredTable& t1 = t.number == 1 ? t : other;
  const MeasuredTable& t2 = t.number == 1 ? other : t;
  KeyedRatios o;
  for (const auto& g : t.generators)
    if (has_generator(other, g))
      o.emplace_back(g, MeasuredVsPaper{median_total(t2, g) / median_total(t1, g),
                                        paper_ratio(paper_total(ctx.paper, 2, g), paper_total(ctx.paper, 1, g))});
  return o;
}

TableRatios table_ratios(const MeasuredTable& t, const MeasuredTable* other, const ReportContext& ctx) {
  TableRatios r;
  const bool tok = has_generator(t, kTok15), mod = has_generator(t, kModified);
  if (tok && mod) {
    r.modified_minus_tok15_us = median_differences(t, ctx);
    r.paired_modified_minus_tok15 = paired_block(t, ctx);
  }
  if (mod)
    if (KeyedRatios k = kmeans_over_modified(t, ctx); !k.empty()) r.kmeans_over_modified = std::move(k);
  if (other != nullptr)
    if (KeyedRatios c = table1_to_table2(t, *other, ctx); !c.empty()) r.table1_to_table2 = std::move(c);
  return r;
}

// DESIGN.md §9, the physical limit: the device's copy bandwidth, and for the passes of each FIS
// generator that only stream data the least bytes they must move (generators/fis/fis_traffic.hpp)
// over their median time, as a fraction of it.
TableBandwidth table_bandwidth(const MeasuredTable& t) {
  const CopyBandwidth& c = t.copy_bandwidth;
  TableBandwidth out;
  out.copy = CopyBandwidthResult{"vkCmdCopyBuffer between two device-local buffers; timestamps between copies; median",
                                 c.requested_bytes, c.bytes, c.reduced_because, 2 * c.bytes, c.warmup, c.samples_ms,
                                 c.median_ms, c.bytes_per_s};
  out.model = fis_traffic_model();
  const auto pass = [&](const PassBytes& b, double median_ms) {
    const double achieved = static_cast<double>(b.total()) / (median_ms * 1e-3);
    return PassTraffic{b.read, b.written, b.total(), median_ms, achieved, achieved / c.bytes_per_s, std::nullopt, std::nullopt};
  };
  for (const auto& g : t.generators) {
    if (generator_descriptor(g).family != GeneratorFamily::kFis) continue;
    GeneratorTraffic traffic{g, {}};
    for (const char* view : kTableViews) {
      const ViewExtent& e = t.views.at(view);
      const FisPassBytes bytes = fis_minimum_bytes(e.width, e.height);
      const double mip_ms = summarize(case_samples(t, g, view, "mipmapping")).median;
      PassTraffic mip = pass(bytes.mipmapping, mip_ms);
      const PassTraffic level = pass(bytes.mipmapping_level_by_level, mip_ms);
      mip.level_by_level_bytes = level.min_bytes;
      mip.level_by_level_fraction_of_copy = level.fraction_of_copy;
      traffic.views[view] = {{"additional", pass(bytes.additional, summarize(case_samples(t, g, view, "additional")).median)},
                             {"mipmapping", mip}};
    }
    out.passes.push_back(std::move(traffic));
  }
  return out;
}

std::vector<Table3Row> table3_rows(const MeasuredTable& t, const ReportContext& ctx) {
  std::vector<Table3Row> rows;
  for (const auto& g : t.generators) {
    const GeneratorLines& lines = ctx.lines.at(g);
    Table3Row row;
    row.generator = g;
    row.shaders = {static_cast<double>(ctx.shaders.at(g)), paper_number(ctx.paper, {"tables", "3", g, "shaders"})};
    row.dispatch_camera_view = need_case(t, g, "camera_view").dispatch_count;
    row.dispatch_light_view = need_case(t, g, "light_view").dispatch_count;
    row.dispatch_paper = paper_number(ctx.paper, {"tables", "3", g, "dispatch_calls"});
    if (generator_descriptor(g).family == GeneratorFamily::kKmeans)
      for (const char* view : kTableViews) row.dispatch_iterations[view] = iteration_dispatches(need_case(t, g, view));
    row.lines_of_code = lines.total;
    row.lines_of_code_paper = paper_number(ctx.paper, {"tables", "3", g, "lines_of_code"});
    row.shader_lines = lines.shader;
    row.host_lines = lines.host;
    for (const auto& f : lines.files) row.files.push_back({f.path, f.lines, f.shader ? "shader" : "host"});
    rows.push_back(std::move(row));
  }
  return rows;
}

// Tokuyoshi 2016, §5 "Code size": the modified FIS differs from [Tok15] "only [in] the mip level
// determination (10 lines of code)".
constexpr double kPaperFisDifferenceLines = 10;

Table3Counting table3_counting(const ReportContext& ctx) {
  Table3Counting out;
  out.rule = kTable3CountingRule;
  out.difference_rule = kTable3DifferenceRule;
  const auto from = ctx.lines.find(kTok15);
  const auto to = ctx.lines.find(kModified);
  if (from != ctx.lines.end() && to != ctx.lines.end()) {
    const LineDiff d = diff_lines(from->second.code, to->second.code);
    out.difference = Table3Difference{from->first,
                                      to->first,
                                      d.removed,
                                      d.added,
                                      d.differing(),
                                      static_cast<int64_t>(to->second.total) - static_cast<int64_t>(from->second.total),
                                      kPaperFisDifferenceLines};
  }
  return out;
}

}  // namespace

std::string generator_label(const std::string& g) { return generator_descriptor(g).label; }

TableModel table_model(const MeasuredTable& t, const MeasuredTable* other, const ReportContext& ctx) {
  TableModel m;
  m.schema_version = kTableSchemaVersion;
  if (t.number != 0) {
    m.table = t.number;
    m.title = "Computation times of VSGL generation (ms), Table " + std::to_string(t.number) + " of Tokuyoshi 2016";
  } else {  // a user's capture: the paper has no numbers for it (every "paper" value is null)
    m.title = "Computation times of VSGL generation (ms) on scene " + t.scene + ", measured as for the tables of Tokuyoshi 2016";
  }
  m.scene = t.identity;
  m.unit = "ms";
  // The driver, API version and timestamps the table states beside its device are the device's.
  const DeviceRecord device = device_record(ctx.device);
  m.driver = DriverSummary{device.driver_name, device.driver_info, device.driver_version};
  m.api_version = device.api_version;
  m.timestamp_period_ns = device.timestamp_period_ns;
  m.timestamp_valid_bits = device.timestamp_valid_bits;
  m.device = device;
  m.build = ctx.build;
  m.run = ctx.run;
  m.config = ctx.config;
  nlohmann::ordered_json capture{{"scene", t.scene}, {"dir", t.capture_dir}, {"recorded_now", t.recorded_now}};
  for (const auto& [k, v] : t.capture.items()) capture[k] = v;
  try {
    m.capture = capture_summary_from_json(capture, "capture " + t.capture_dir);
  } catch (const InputError& e) {
    throw std::invalid_argument(e.what());
  }
  m.paper = PaperSource{ctx.paper.value("source", ""), ctx.paper_path,
                        ctx.paper.contains("setup") ? ctx.paper["setup"].value("gpu", "") : ""};
  m.timing = TimingStop{t.timing.repetitions, t.timing.timed_seconds, t.timing.stop_reason, t.timing.worst_noise};
  for (const auto& g : t.generators) m.generators.push_back(generator_timing(t, g, ctx));
  m.ratios = table_ratios(t, other, ctx);
  m.bandwidth = table_bandwidth(t);
  m.table3 = table3_rows(t, ctx);
  m.table3_counting = table3_counting(ctx);
  m.claims = table_claims(t, other, ctx);
  return m;
}

nlohmann::ordered_json table_json(const MeasuredTable& t, const MeasuredTable* other, const ReportContext& ctx) {
  return to_json(table_model(t, other, ctx));
}

}  // namespace vsgl
