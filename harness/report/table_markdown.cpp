#include "harness/report/table_markdown.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <vector>

#include "harness/core/error.hpp"
#include "harness/core/text_format.hpp"
#include "harness/core/generator_ids.hpp"
#include "harness/report/table_claims.hpp"

namespace vsgl {
namespace {

using ojson = nlohmann::ordered_json;

std::string phase_title(const std::string& phase, const std::string& view) {
  if (phase == "additional") return view == "camera_view" ? "Additional G-buffer" : "Additional RSM";
  if (phase == "mipmapping") return "Mipmapping";
  if (phase == "filtered_sampling") return "Filtered sampling";
  if (phase == "cluster_assignment") return "Cluster assignment";
  if (phase == "sort") return "Sort";
  if (phase == "sum") return "Sum";
  return phase;
}

std::string signed_fixed(double v, int digits) { return (v > 0 ? "+" : "") + fixed_text(v, digits); }

// Bytes and bytes/s in decimal units (GB = 1e9), as bandwidths are quoted.
std::string gigabytes(double bytes, int digits = 2) { return fixed_text(bytes * 1e-9, digits); }

void row(std::ostringstream& os, const std::vector<std::string>& cells) {
  os << "|";
  for (const auto& c : cells) os << " " << c << " |";
  os << "\n";
}

template <typename T>
const T& need(const std::optional<T>& v, const char* what) {
  if (!v) throw InputError(std::string("the table has no ") + what + ", which the markdown shows");
  return *v;
}

std::string paper_cell(const std::optional<double>& v, int digits = 3) { return v ? fixed_text(*v, digits) : "—"; }

// The generator's column name (its key when the file has no label).
std::string label_of(const TableModel& t, const std::string& g) {
  const GeneratorTiming* gen = t.find_generator(g);
  return gen != nullptr && gen->label ? *gen->label : g;
}

const char* view_title(const std::string& view) {
  return view == "camera_view" ? "PDF for BRSM (camera view)" : "PDF (light view)";
}

const char* scene_label_kind(const SceneIdentity& s) {
  switch (s.kind) {
    case SceneKind::kPaper: return "the paper's scene";
    case SceneKind::kStandIn: return "procedural stand-in for the paper's scene";
    case SceneKind::kProcedural: return "procedural";
    case SceneKind::kUser: return "a user's model";
  }
  return "?";
}

// The heading and the line saying where and how the table was measured.
void write_heading(std::ostringstream& os, const TableModel& t, bool paper) {
  const std::string scene = t.capture.scene ? *t.capture.scene : t.scene ? t.scene->name : "?";
  if (paper) os << "## Table " << *t.table << ": " << need(t.title, "title") << "\n\n";
  else os << "## Scene " << scene << ": " << need(t.title, "title") << "\n\n";
  const DriverSummary& driver = need(t.driver, "driver");
  // Schema 3 names the scene's kind: a stand-in's numbers are not the paper scene's.
  const std::string kind = t.scene && !t.scene->name_only ? std::string(" (") + scene_label_kind(*t.scene) + ")" : "";
  os << "Scene `" << scene << "`" << kind << " on **" << need(t.device, "device").name << "** (" << driver.name << " "
     << driver.version << ", Vulkan " << need(t.api_version, "api_version") << ")";
  if (paper) os << "; paper: " << need(t.paper, "paper").gpu;
  if (const auto& src = t.capture.source)
    os << "; from " << src->format << " file `" << src->file << "` (" << src->triangles << " triangles, " << src->content_hash << ")";
  const TimingStop& timing = need(t.timing, "timing");
  os << ". Median of " << timing.repetitions << " repetitions (stop: " << timing.stop_reason << ", worst IQR/median "
     << fixed_text(timing.worst_relative_iqr) << "), ms.\n\n";
}

// Per view the first three phases of every generator, then the generator totals.
void write_timing_table(std::ostringstream& os, const TableModel& t, bool paper) {
  std::vector<std::string> head{""}, rule{"---"};
  for (const GeneratorTiming& g : t.generators) {
    head.push_back(label_of(t, g.name));
    rule.push_back("---:");
    if (!paper) continue;
    head.push_back("paper");
    rule.push_back("---:");
  }
  const std::size_t per_generator = paper ? 2 : 1;
  row(os, head);
  row(os, rule);
  for (const char* view : {"camera_view", "light_view"}) {
    std::vector<std::string> title{std::string("**") + view_title(view) + "**, N = " + std::to_string(t.vsgl_count(view))};
    for (std::size_t i = 0; i < per_generator * t.generators.size(); ++i) title.emplace_back("");
    row(os, title);
    for (std::size_t p = 0; p < 3; ++p) {
      std::vector<std::string> cells{"phase " + std::to_string(p + 1)};
      for (const GeneratorTiming& g : t.generators) {
        const std::vector<PhaseTiming>& phases = g.views.at(view).phases;
        if (p >= phases.size()) {
          for (std::size_t i = 0; i < per_generator; ++i) cells.emplace_back("");
          continue;
        }
        cells.push_back(phase_title(phases[p].phase, view) + ": " + fixed_text(phases[p].stats.median_ms));
        if (paper) cells.push_back(paper_cell(phases[p].stats.paper_ms));
      }
      row(os, cells);
    }
  }
  std::vector<std::string> total{"**Total**"};
  for (const GeneratorTiming& g : t.generators) {
    total.push_back("**" + fixed_text(g.total.median_ms) + "**");
    if (paper) total.push_back(paper_cell(g.total.paper_ms));
  }
  row(os, total);
}

void write_ratios(std::ostringstream& os, const TableRatios& r, bool paper) {
  if (!r.modified_minus_tok15_us && !r.paired_modified_minus_tok15 && !r.kmeans_over_modified && !r.table1_to_table2) return;
  os << "\n### Ratios the paper argues with\n\n";
  const auto ratio_row = [&](const std::string& name, const std::string& measured, const std::string& paper_value) {
    if (paper) row(os, {name, measured, paper_value});
    else row(os, {name, measured});
  };
  ratio_row("ratio", "this run", "paper");
  ratio_row("---", "---:", "---:");
  for (const auto& [k, v] : r.modified_minus_tok15_us.value_or(KeyedRatios{}))
    ratio_row("modified − Tok15, " + k + " (µs)", fixed_text(v.measured, 1), paper_cell(v.paper, 1));
  for (const auto& [k, v] : r.kmeans_over_modified.value_or(KeyedRatios{}))
    ratio_row(k + " / modified total", fixed_text(v.measured, 2), paper_cell(v.paper, 2));
  for (const auto& [k, v] : r.table1_to_table2.value_or(KeyedRatios{}))
    row(os, {k + " total, Table 2 / Table 1", fixed_text(v.measured, 3), paper_cell(v.paper, 3)});
}

void write_paired(std::ostringstream& os, const PairedOverhead& p, bool paper) {
  os << "\n### Overhead of the modified FIS, paired by round (µs)\n\n"
     << "Per-round differences " << kFisModified << " − " << kFisTok15
     << " (same round, so drift and the shared passes' noise cancel): median, Hodges–Lehmann estimate and its "
     << fixed_text(100 * p.nominal_confidence, 0) << " % distribution-free interval (Wilcoxon signed-rank).\n\n";
  // The paper's column only for the paper's tables, as above.
  std::vector<std::string> columns{"difference", "median", "Hodges–Lehmann", "interval", "confidence", "rounds"};
  if (paper) columns.push_back("paper");
  row(os, columns);
  row(os, std::vector<std::string>(columns.size(), "---:"));
  const auto line = [&](const std::string& name, const PairedDifference& d) {
    std::vector<std::string> cells{name,
                                   signed_fixed(d.median_us, 1),
                                   signed_fixed(d.hodges_lehmann_us, 1),
                                   "[" + signed_fixed(d.ci_low_us, 1) + ", " + signed_fixed(d.ci_high_us, 1) + "]",
                                   fixed_text(100 * d.confidence, 1) + " %" + (d.reaches_nominal ? "" : " (short)"),
                                   std::to_string(d.rounds)};
    if (paper) cells.push_back(paper_cell(d.paper_us, 1));
    row(os, cells);
  };
  for (const auto& [view, v] : p.views) {
    line(view + " total", v.total);
    line(view + " filtered sampling", v.filtered_sampling);
  }
  line("generator total", p.total);
}

void write_bandwidth(std::ostringstream& os, const TableModel& t, const TableBandwidth& bw) {
  const CopyBandwidthResult& copy = bw.copy;
  os << "\n### Physical limit: copy bandwidth and the streaming passes\n\n"
     << "Copy bandwidth (vkCmdCopyBuffer, read + written): **" << gigabytes(copy.bytes_per_s) << " GB/s** (buffers of "
     << fixed_text(static_cast<double>(copy.buffer_bytes) / (1 << 20), 0) << " MiB, median of "
     << copy.samples_ms.size() << " copies";
  if (!copy.reduced_because.empty())
    os << "; smaller than the " << fixed_text(static_cast<double>(copy.requested_bytes) / (1 << 20), 0)
       << " MiB asked: " << copy.reduced_because;
  os << "). Each pass's least traffic (" << bw.model << ") over its median time:\n\n";
  if (bw.passes.empty()) return;
  row(os, {"generator", "view", "pass", "least traffic (MB)", "median (ms)", "achieved (GB/s)", "of copy bandwidth"});
  row(os, {"---", "---", "---", "---:", "---:", "---:", "---:"});
  for (const GeneratorTraffic& g : bw.passes)
    for (const auto& [view, passes] : g.views)
      for (const auto& [pass, v] : passes) {
        std::string fraction = fixed_text(100 * v.fraction_of_copy, 1) + " %";
        if (v.level_by_level_fraction_of_copy)
          fraction += " (level by level: " + fixed_text(100 * *v.level_by_level_fraction_of_copy, 1) + " %)";
        row(os, {label_of(t, g.generator), view, pass, fixed_text(static_cast<double>(v.min_bytes) * 1e-6, 1),
                 fixed_text(v.median_ms), gigabytes(v.achieved_bytes_per_s), fraction});
      }
}

std::string optional_count(const std::optional<uint64_t>& v) { return v ? std::to_string(*v) : "—"; }

// "4 x 61 + 25" per view: iterations x dispatches per iteration + the rest.
std::string iteration_cell(const Table3Row& r) {
  if (r.dispatch_iterations.empty()) return "—";
  std::string cell;
  for (const char* view : {"camera_view", "light_view"}) {
    const auto it = r.dispatch_iterations.find(view);
    if (it == r.dispatch_iterations.end()) continue;
    const IterationDispatches& d = it->second;
    cell += (cell.empty() ? "" : " / ") + std::to_string(d.iterations) + " × " + std::to_string(d.per_iteration) +
            " + " + std::to_string(d.outside);
  }
  return cell;
}

void write_table3(std::ostringstream& os, const TableModel& t, const std::vector<Table3Row>& rows,
                  const std::optional<Table3Counting>& counting) {
  os << "\n### Table 3 analog (counted, not typed in)\n\n";
  // Files written before the split had neither column; they render as they were written.
  const bool split =
      std::any_of(rows.begin(), rows.end(), [](const Table3Row& r) { return r.shader_lines.has_value(); });
  const bool iterations =
      std::any_of(rows.begin(), rows.end(), [](const Table3Row& r) { return !r.dispatch_iterations.empty(); });
  std::vector<std::string> head{"generator", "compute shaders", "paper", "dispatch calls (camera / light)"};
  head.push_back("paper");
  if (iterations) head.push_back("iterations × per iteration + rest");
  if (split) head.insert(head.end(), {"shader lines", "host lines"});
  head.insert(head.end(), {"lines of code", "paper"});
  row(os, head);
  std::vector<std::string> align(head.size(), "---:");
  align[0] = "---";
  row(os, align);
  for (const Table3Row& r : rows) {
    std::vector<std::string> cells{
        label_of(t, r.generator), std::to_string(static_cast<int>(r.shaders.measured)), paper_cell(r.shaders.paper, 0),
        std::to_string(r.dispatch_camera_view) + " / " + std::to_string(r.dispatch_light_view)};
    cells.push_back(paper_cell(r.dispatch_paper, 0));
    if (iterations) cells.push_back(iteration_cell(r));
    if (split) cells.insert(cells.end(), {optional_count(r.shader_lines), optional_count(r.host_lines)});
    cells.insert(cells.end(), {std::to_string(r.lines_of_code), paper_cell(r.lines_of_code_paper, 0)});
    row(os, cells);
  }
  if (!counting) return;
  os << "\nCounted: " << counting->rule << "\n";
  if (const auto& d = counting->difference) {
    os << "\n"
       << label_of(t, d->from) << " → " << label_of(t, d->to) << ": " << d->differing << " lines differ (" << d->removed
       << " removed, " << d->added << " added; net " << (d->net >= 0 ? "+" : "") << d->net << ")";
    if (d->paper) os << "; the paper: " << fixed_text(*d->paper, 0) << " lines";
    os << ". " << counting->difference_rule << "\n";
  }
}

void write_claims(std::ostringstream& os, const std::vector<Claim>& claims) {
  os << "\n### The paper's claims on this run\n\n";
  for (const Claim& c : claims) {
    const bool measured = !c.measured.empty();
    os << "- **" << claim_verdict(c) << "**" << (c.informative && measured ? " (informative: CPU device)" : "") << " — "
       << c.text << "\n  - criterion: " << c.criterion;
    if (measured) os << "\n  - measured: `" << c.measured.dump() << "`";
    if (!claim_note(c).empty()) os << "\n  - " << claim_note(c);
    os << "\n";
  }
}

}  // namespace

std::string table_markdown(const TableModel& t) {
  std::ostringstream os;
  // The paper's columns only for the paper's tables; another capture has no paper numbers.
  const bool paper = t.table.has_value();
  write_heading(os, t, paper);
  write_timing_table(os, t, paper);
  const TableRatios& ratios = need(t.ratios, "ratios");
  write_ratios(os, ratios, paper);
  if (ratios.paired_modified_minus_tok15) write_paired(os, *ratios.paired_modified_minus_tok15, paper);
  write_bandwidth(os, t, need(t.bandwidth, "bandwidth"));
  write_table3(os, t, need(t.table3, "table3"), t.table3_counting);
  write_claims(os, need(t.claims, "claims"));
  return os.str();
}

std::string table_markdown(const ojson& t) { return table_markdown(table_model_from_json(t, "the table")); }

}  // namespace vsgl
