#include "harness/report/table_json.hpp"

#include <optional>
#include <stdexcept>

#include "harness/core/statistics.hpp"
#include "harness/generators/fis/fis_traffic.hpp"
#include "harness/generators/generator_registry.hpp"
#include "harness/report/paper_tables.hpp"
#include "harness/report/table_claims.hpp"

namespace vsgl {
namespace {

using ojson = nlohmann::ordered_json;

ojson number_or_null(std::optional<double> v) { return v ? ojson(*v) : ojson(nullptr); }

ojson stats_json(const std::vector<double>& samples, std::optional<double> paper_ms) {
  const SampleStats s = summarize(samples);
  return ojson{{"median_ms", s.median},   {"paper_ms", number_or_null(paper_ms)},
               {"min_ms", s.min},         {"max_ms", s.max},
               {"q1_ms", s.q1},           {"q3_ms", s.q3},
               {"mean_ms", s.mean},       {"stdev_ms", s.stdev},
               {"relative_iqr", relative_iqr(s)}, {"count", s.count},
               {"samples_ms", samples}};
}

ojson measured_paper(double measured, std::optional<double> paper) {
  return ojson{{"measured", measured}, {"paper", number_or_null(paper)}};
}

ojson generator_json(const MeasuredTable& t, const std::string& g, const ReportContext& ctx) {
  ojson views = ojson::object();
  for (const char* view : kTableViews) {
    const CaseTiming& c = need_case(t, g, view);
    ojson phases = ojson::object();
    for (std::size_t p = 0; p < c.phases.size(); ++p)
      phases[c.phases[p]] = stats_json(c.phase_ms[p], paper_number(ctx.paper, {"tables", std::to_string(t.number), g, view, c.phases[p]}));
    views[view] = ojson{{"phases", phases},
                        {"total", stats_json(c.total_ms, paper_view_total(ctx.paper, t.number, g, view))},
                        {"dispatch_calls", c.dispatch_count}};
  }
  return ojson{{"label", generator_label(g)},
               {"in_paper", generator_in_paper(g)},
               {"views", views},
               {"total", stats_json(generator_totals(t, g), paper_total(ctx.paper, t.number, g))}};
}

// One paired difference (ms in, µs out) with the paper's difference beside it.
ojson paired_json(const PairedInterval& p, std::optional<double> paper_ms) {
  return ojson{{"rounds", p.count},
               {"median_us", 1e3 * p.median},
               {"hodges_lehmann_us", 1e3 * p.hodges_lehmann},
               {"ci_low_us", 1e3 * p.low},
               {"ci_high_us", 1e3 * p.high},
               {"confidence", p.confidence},
               {"reaches_nominal", p.reaches_nominal()},
               {"critical_value", p.exact ? "exact" : "normal"},
               {"paper_us", paper_ms ? ojson(1e3 * *paper_ms) : ojson(nullptr)}};
}

std::optional<double> paper_difference(std::optional<double> modified, std::optional<double> tok15) {
  return modified && tok15 ? std::optional<double>(*modified - *tok15) : std::nullopt;
}

// DESIGN.md §9: the overhead from per-round differences, so that drift and the noise of the shared
// passes cancel. Views: the total and the one pass the two generators do not share.
ojson paired_block(const MeasuredTable& t, const ReportContext& ctx) {
  const std::string table = std::to_string(t.number);
  ojson o{{"estimator", "Hodges-Lehmann (median of the Walsh averages of the per-round differences)"},
          {"interval", "distribution-free, Wilcoxon signed-rank critical value (exact up to " +
                           std::to_string(kSignedRankExactMax) + " rounds, normal approximation above)"},
          {"nominal_confidence", kPairedConfidence}};
  for (const char* view : kTableViews) {
    ojson v = ojson::object();
    v["total"] = paired_json(paired_overhead(t, view, "total"),
                             paper_difference(paper_view_total(ctx.paper, t.number, "fis_modified", view),
                                              paper_view_total(ctx.paper, t.number, "fis_tok15", view)));
    v["filtered_sampling"] =
        paired_json(paired_overhead(t, view, "filtered_sampling"),
                    paper_difference(paper_number(ctx.paper, {"tables", table, "fis_modified", view, "filtered_sampling"}),
                                     paper_number(ctx.paper, {"tables", table, "fis_tok15", view, "filtered_sampling"})));
    o[view] = v;
  }
  o["total"] = paired_json(paired_overhead(t), paper_difference(paper_total(ctx.paper, t.number, "fis_modified"),
                                                                paper_total(ctx.paper, t.number, "fis_tok15")));
  return o;
}

ojson ratios_json(const MeasuredTable& t, const MeasuredTable* other, const ReportContext& ctx) {
  ojson r = ojson::object();
  const bool tok = has_generator(t, "fis_tok15"), mod = has_generator(t, "fis_modified");
  if (tok && mod) {
    ojson o = ojson::object();
    for (const char* view : kTableViews) {
      const auto pt = paper_view_total(ctx.paper, t.number, "fis_tok15", view);
      const auto pm = paper_view_total(ctx.paper, t.number, "fis_modified", view);
      o[view] = measured_paper(1e3 * (median_view(t, "fis_modified", view) - median_view(t, "fis_tok15", view)),
                               pt && pm ? std::optional<double>(1e3 * (*pm - *pt)) : std::nullopt);
    }
    const auto pt = paper_total(ctx.paper, t.number, "fis_tok15"), pm = paper_total(ctx.paper, t.number, "fis_modified");
    o["total"] = measured_paper(1e3 * (median_total(t, "fis_modified") - median_total(t, "fis_tok15")),
                                pt && pm ? std::optional<double>(1e3 * (*pm - *pt)) : std::nullopt);
    r["modified_minus_tok15_us"] = o;  // difference of the medians, kept beside the paired one
    r["paired_modified_minus_tok15"] = paired_block(t, ctx);
  }
  if (mod) {
    ojson o = ojson::object();
    const auto pm = paper_total(ctx.paper, t.number, "fis_modified");
    for (const auto& g : t.generators) {
      if (g.rfind("kmeans", 0) != 0) continue;
      const auto pk = paper_total(ctx.paper, t.number, g);
      o[g] = measured_paper(median_total(t, g) / median_total(t, "fis_modified"),
                            pk && pm ? std::optional<double>(*pk / *pm) : std::nullopt);
    }
    if (!o.empty()) r["kmeans_over_modified"] = o;
  }
  if (other != nullptr) {
    const MeasuredTable& t1 = t.number == 1 ? t : *other;
    const MeasuredTable& t2 = t.number == 1 ? *other : t;
    ojson o = ojson::object();
    for (const auto& g : t.generators) {
      if (!has_generator(*other, g)) continue;
      const auto p1 = paper_total(ctx.paper, 1, g), p2 = paper_total(ctx.paper, 2, g);
      o[g] = measured_paper(median_total(t2, g) / median_total(t1, g),
                            p1 && p2 ? std::optional<double>(*p2 / *p1) : std::nullopt);
    }
    if (!o.empty()) r["table1_to_table2"] = o;
  }
  return r;
}

// DESIGN.md §9, the physical limit: the device's copy bandwidth, and for the passes of each FIS
// generator that only stream data the least bytes they must move (generators/fis/fis_traffic.hpp)
// over their median time, as a fraction of it.
ojson bandwidth_json(const MeasuredTable& t) {
  const CopyBandwidth& c = t.copy_bandwidth;
  ojson copy{{"method", "vkCmdCopyBuffer between two device-local buffers; timestamps between copies; median"},
             {"requested_bytes", c.requested_bytes},
             {"buffer_bytes", c.bytes},
             {"reduced_because", c.reduced_because},
             {"bytes_per_copy", 2 * c.bytes},
             {"warmup_copies", c.warmup},
             {"samples_ms", c.samples_ms},
             {"median_ms", c.median_ms},
             {"bytes_per_s", c.bytes_per_s}};
  const auto pass = [&](const PassBytes& b, double median_ms) {
    const double achieved = static_cast<double>(b.total()) / (median_ms * 1e-3);
    return ojson{{"min_bytes_read", b.read},
                 {"min_bytes_written", b.written},
                 {"min_bytes", b.total()},
                 {"median_ms", median_ms},
                 {"achieved_bytes_per_s", achieved},
                 {"fraction_of_copy", achieved / c.bytes_per_s}};
  };
  ojson passes = ojson::object();
  for (const auto& g : t.generators) {
    if (generator_descriptor(g).family != GeneratorFamily::kFis) continue;
    ojson views = ojson::object();
    for (const char* view : kTableViews) {
      const ViewExtent& e = t.views.at(view);
      const FisPassBytes bytes = fis_minimum_bytes(e.width, e.height);
      const double mip_ms = summarize(case_samples(t, g, view, "mipmapping")).median;
      ojson mip = pass(bytes.mipmapping, mip_ms);
      const ojson level = pass(bytes.mipmapping_level_by_level, mip_ms);
      mip["level_by_level_bytes"] = level["min_bytes"];
      mip["level_by_level_fraction_of_copy"] = level["fraction_of_copy"];
      views[view] = ojson{{"additional", pass(bytes.additional, summarize(case_samples(t, g, view, "additional")).median)},
                          {"mipmapping", mip}};
    }
    passes[g] = views;
  }
  return ojson{{"copy", copy},
               {"model", fis_traffic_model()},
               {"passes", passes}};
}

ojson table3_json(const MeasuredTable& t, const ReportContext& ctx) {
  ojson out = ojson::object();
  for (const auto& g : t.generators) {
    const GeneratorLines& lines = ctx.lines.at(g);
    ojson files = ojson::array();
    for (const auto& f : lines.files) files.push_back(ojson{{"path", f.path}, {"lines", f.lines}});
    ojson dispatch{{"camera_view", need_case(t, g, "camera_view").dispatch_count},
                   {"light_view", need_case(t, g, "light_view").dispatch_count},
                   {"paper", number_or_null(paper_number(ctx.paper, {"tables", "3", g, "dispatch_calls"}))}};
    out[g] = ojson{{"shaders", measured_paper(ctx.shaders.at(g), paper_number(ctx.paper, {"tables", "3", g, "shaders"}))},
                   {"dispatch_calls", dispatch},
                   {"lines_of_code", ojson{{"measured", lines.total},
                                           {"paper", number_or_null(paper_number(ctx.paper, {"tables", "3", g, "lines_of_code"}))},
                                           {"files", files}}}};
  }
  return out;
}

}  // namespace

std::string generator_label(const std::string& g) { return generator_descriptor(g).label; }

nlohmann::ordered_json table_json(const MeasuredTable& t, const MeasuredTable* other, const ReportContext& ctx) {
  const DeviceInfo& d = ctx.device;
  ojson doc;
  doc["schema_version"] = kTableSchemaVersion;
  if (t.number != 0) {
    doc["table"] = t.number;
    doc["title"] = "Computation times of VSGL generation (ms), Table " + std::to_string(t.number) + " of Tokuyoshi 2016";
  } else {  // a user's capture: the paper has no numbers for it (every "paper" value is null)
    doc["table"] = nullptr;
    doc["title"] = "Computation times of VSGL generation (ms) on scene " + t.scene +
                   ", measured as for the tables of Tokuyoshi 2016";
  }
  doc["scene"] = t.scene;
  doc["unit"] = "ms";
  doc["device"] = to_json(d);
  doc["driver"] = ojson{{"name", d.driver_name}, {"info", d.driver_info}, {"version", driver_version_string(d)}};
  doc["api_version"] = api_version_string(d.api_version);
  doc["timestamp_period_ns"] = d.timestamp_period_ns;
  doc["timestamp_valid_bits"] = d.timestamp_valid_bits;
  doc["build"] = ctx.build;
  doc["run"] = ctx.run;
  doc["config"] = ctx.config;
  doc["capture"] = ojson{{"scene", t.scene}, {"dir", t.capture_dir}, {"recorded_now", t.recorded_now}};
  for (const auto& [k, v] : t.capture.items()) doc["capture"][k] = v;
  doc["paper"] = ojson{{"source", ctx.paper.value("source", "")}, {"file", ctx.paper_path},
                       {"gpu", ctx.paper.contains("setup") ? ctx.paper["setup"].value("gpu", "") : ""}};
  doc["timing"] = ojson{{"repetitions", t.timing.repetitions},
                        {"timed_seconds", t.timing.timed_seconds},
                        {"stop_reason", t.timing.stop_reason},
                        {"worst_relative_iqr", t.timing.worst_noise}};
  ojson gens = ojson::object();
  for (const auto& g : t.generators) gens[g] = generator_json(t, g, ctx);
  doc["generators"] = gens;
  doc["ratios"] = ratios_json(t, other, ctx);
  doc["bandwidth"] = bandwidth_json(t);
  doc["table3"] = table3_json(t, ctx);
  doc["claims"] = claims_json(t, other, ctx);
  return doc;
}

}  // namespace vsgl
