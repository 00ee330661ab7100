#include "harness/report/table_markdown.hpp"

#include <cstdio>
#include <sstream>
#include <vector>

#include "harness/report/table_claims.hpp"

namespace vsgl {
namespace {

using ojson = nlohmann::ordered_json;

std::string fixed(double v, int digits = 3) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}
std::string paper_cell(const ojson& v, int digits = 3) { return v.is_number() ? fixed(v.get<double>(), digits) : "—"; }

std::string phase_title(const std::string& phase, const std::string& view) {
  if (phase == "additional") return view == "camera_view" ? "Additional G-buffer" : "Additional RSM";
  if (phase == "mipmapping") return "Mipmapping";
  if (phase == "filtered_sampling") return "Filtered sampling";
  if (phase == "cluster_assignment") return "Cluster assignment";
  if (phase == "sort") return "Sort";
  if (phase == "sum") return "Sum";
  return phase;
}

std::string signed_fixed(double v, int digits) { return (v > 0 ? "+" : "") + fixed(v, digits); }

// Bytes and bytes/s in decimal units (GB = 1e9), as bandwidths are quoted.
std::string gigabytes(double bytes, int digits = 2) { return fixed(bytes * 1e-9, digits); }

void row(std::ostringstream& os, const std::vector<std::string>& cells) {
  os << "|";
  for (const auto& c : cells) os << " " << c << " |";
  os << "\n";
}

}  // namespace

std::string table_markdown(const ojson& t) {
  std::ostringstream os;
  const ojson& gens = t.at("generators");
  const ojson& views = t.at("config").at("views");
  // The paper's columns only for the paper's tables; another capture has no paper numbers.
  const bool paper = t.at("table").is_number();
  if (paper) {
    os << "## Table " << t.at("table").get<int>() << ": " << t.at("title").get<std::string>() << "\n\n";
  } else {
    os << "## Scene " << t.at("capture").at("scene").get<std::string>() << ": " << t.at("title").get<std::string>() << "\n\n";
  }
  os << "Scene `" << t.at("capture").at("scene").get<std::string>() << "` on **" << t.at("device").at("name").get<std::string>()
     << "** (" << t.at("driver").at("name").get<std::string>() << " " << t.at("driver").at("version").get<std::string>()
     << ", Vulkan " << t.at("api_version").get<std::string>() << ")";
  if (paper) os << "; paper: " << t.at("paper").at("gpu").get<std::string>();
  const ojson& capture = t.at("capture");
  if (capture.contains("source")) {
    const ojson& src = capture.at("source");
    os << "; from " << src.at("format").get<std::string>() << " file `" << src.at("file").get<std::string>() << "` ("
       << src.at("triangles").get<uint64_t>() << " triangles, " << src.at("content_hash").get<std::string>() << ")";
  }
  os << ". Median of " << t.at("timing").at("repetitions").get<int>() << " repetitions (stop: "
     << t.at("timing").at("stop_reason").get<std::string>() << ", worst IQR/median "
     << fixed(t.at("timing").at("worst_relative_iqr").get<double>()) << "), ms.\n\n";

  std::vector<std::string> head{""}, rule{"---"};
  for (const auto& [g, gj] : gens.items()) {
    head.push_back(gj.at("label").get<std::string>());
    rule.push_back("---:");
    if (!paper) continue;
    head.push_back("paper");
    rule.push_back("---:");
  }
  const std::size_t per_generator = paper ? 2 : 1;
  row(os, head);
  row(os, rule);
  for (const char* view : {"camera_view", "light_view"}) {
    const ojson& vc = views.at(view);
    std::vector<std::string> title{std::string("**") + (std::string(view) == "camera_view" ? "PDF for BRSM (camera view)" : "PDF (light view)") +
                                   "**, N = " + std::to_string(vc.at("vsgl_count").get<int>())};
    for (std::size_t i = 0; i < per_generator * gens.size(); ++i) title.emplace_back("");
    row(os, title);
    for (std::size_t p = 0; p < 3; ++p) {
      std::vector<std::string> cells{"phase " + std::to_string(p + 1)};
      for (const auto& [g, gj] : gens.items()) {
        const ojson& phases = gj.at("views").at(view).at("phases");
        if (p >= phases.size()) {
          for (std::size_t i = 0; i < per_generator; ++i) cells.emplace_back("");
          continue;
        }
        auto it = phases.begin();
        std::advance(it, static_cast<std::ptrdiff_t>(p));
        cells.push_back(phase_title(it.key(), view) + ": " + fixed(it.value().at("median_ms").get<double>()));
        if (paper) cells.push_back(paper_cell(it.value().at("paper_ms")));
      }
      row(os, cells);
    }
  }
  std::vector<std::string> total{"**Total**"};
  for (const auto& [g, gj] : gens.items()) {
    total.push_back("**" + fixed(gj.at("total").at("median_ms").get<double>()) + "**");
    if (paper) total.push_back(paper_cell(gj.at("total").at("paper_ms")));
  }
  row(os, total);

  const ojson& r = t.at("ratios");
  if (!r.empty()) {
    os << "\n### Ratios the paper argues with\n\n";
    const auto ratio_row = [&](const std::string& name, const std::string& measured, const std::string& paper_value) {
      if (paper) row(os, {name, measured, paper_value});
      else row(os, {name, measured});
    };
    ratio_row("ratio", "this run", "paper");
    ratio_row("---", "---:", "---:");
    if (r.contains("modified_minus_tok15_us"))
      for (const auto& [k, v] : r["modified_minus_tok15_us"].items())
        ratio_row("modified − Tok15, " + k + " (µs)", fixed(v.at("measured").get<double>(), 1), paper_cell(v.at("paper"), 1));
    if (r.contains("kmeans_over_modified"))
      for (const auto& [k, v] : r["kmeans_over_modified"].items())
        ratio_row(k + " / modified total", fixed(v.at("measured").get<double>(), 2), paper_cell(v.at("paper"), 2));
    if (r.contains("table1_to_table2"))
      for (const auto& [k, v] : r["table1_to_table2"].items())
        row(os, {k + " total, Table 2 / Table 1", fixed(v.at("measured").get<double>(), 3), paper_cell(v.at("paper"), 3)});
  }

  if (r.contains("paired_modified_minus_tok15")) {
    const ojson& p = r["paired_modified_minus_tok15"];
    os << "\n### Overhead of the modified FIS, paired by round (µs)\n\n"
       << "Per-round differences fis_modified − fis_tok15 (same round, so drift and the shared passes' noise "
          "cancel): median, Hodges–Lehmann estimate and its "
       << fixed(100 * p.at("nominal_confidence").get<double>(), 0)
       << " % distribution-free interval (Wilcoxon signed-rank).\n\n";
    // The paper's column only for the paper's tables, as above.
    std::vector<std::string> columns{"difference", "median", "Hodges–Lehmann", "interval", "confidence", "rounds"};
    if (paper) columns.push_back("paper");
    row(os, columns);
    row(os, std::vector<std::string>(columns.size(), "---:"));
    const auto line = [&](const std::string& name, const ojson& d) {
      const double conf = d.at("confidence").get<double>();
      std::vector<std::string> cells{
          name, signed_fixed(d.at("median_us").get<double>(), 1), signed_fixed(d.at("hodges_lehmann_us").get<double>(), 1),
          "[" + signed_fixed(d.at("ci_low_us").get<double>(), 1) + ", " + signed_fixed(d.at("ci_high_us").get<double>(), 1) + "]",
          fixed(100 * conf, 1) + " %" + (d.at("reaches_nominal").get<bool>() ? "" : " (short)"),
          std::to_string(d.at("rounds").get<int>())};
      if (paper) cells.push_back(paper_cell(d.at("paper_us"), 1));
      row(os, cells);
    };
    for (const char* view : {"camera_view", "light_view"}) {
      line(std::string(view) + " total", p.at(view).at("total"));
      line(std::string(view) + " filtered sampling", p.at(view).at("filtered_sampling"));
    }
    line("generator total", p.at("total"));
  }

  const ojson& bw = t.at("bandwidth");
  const ojson& copy = bw.at("copy");
  os << "\n### Physical limit: copy bandwidth and the streaming passes\n\n"
     << "Copy bandwidth (vkCmdCopyBuffer, read + written): **" << gigabytes(copy.at("bytes_per_s").get<double>())
     << " GB/s** (buffers of " << fixed(copy.at("buffer_bytes").get<double>() / (1 << 20), 0) << " MiB, median of "
     << copy.at("samples_ms").size() << " copies";
  if (!copy.at("reduced_because").get<std::string>().empty())
    os << "; smaller than the " << fixed(copy.at("requested_bytes").get<double>() / (1 << 20), 0)
       << " MiB asked: " << copy.at("reduced_because").get<std::string>();
  os << "). Each pass's least traffic (" << bw.at("model").get<std::string>() << ") over its median time:\n\n";
  if (!bw.at("passes").empty()) {
    row(os, {"generator", "view", "pass", "least traffic (MB)", "median (ms)", "achieved (GB/s)", "of copy bandwidth"});
    row(os, {"---", "---", "---", "---:", "---:", "---:", "---:"});
    for (const auto& [g, pass_views] : bw.at("passes").items())
      for (const auto& [view, passes] : pass_views.items())
        for (const auto& [pass, v] : passes.items()) {
          std::string fraction = fixed(100 * v.at("fraction_of_copy").get<double>(), 1) + " %";
          if (v.contains("level_by_level_fraction_of_copy"))
            fraction += " (level by level: " + fixed(100 * v.at("level_by_level_fraction_of_copy").get<double>(), 1) + " %)";
          row(os, {gens.at(g).at("label").get<std::string>(), view, pass,
                   fixed(v.at("min_bytes").get<double>() * 1e-6, 1), fixed(v.at("median_ms").get<double>()),
                   gigabytes(v.at("achieved_bytes_per_s").get<double>()), fraction});
        }
  }

  os << "\n### Table 3 analog (counted, not typed in)\n\n";
  row(os, {"generator", "compute shaders", "paper", "dispatch calls (camera / light)", "paper", "lines of code", "paper"});
  row(os, {"---", "---:", "---:", "---:", "---:", "---:", "---:"});
  for (const auto& [g, v] : t.at("table3").items()) {
    row(os, {gens.at(g).at("label").get<std::string>(), std::to_string(v.at("shaders").at("measured").get<int>()),
             paper_cell(v.at("shaders").at("paper"), 0),
             std::to_string(v.at("dispatch_calls").at("camera_view").get<int>()) + " / " +
                 std::to_string(v.at("dispatch_calls").at("light_view").get<int>()),
             paper_cell(v.at("dispatch_calls").at("paper"), 0), std::to_string(v.at("lines_of_code").at("measured").get<int>()),
             paper_cell(v.at("lines_of_code").at("paper"), 0)});
  }

  os << "\n### The paper's claims on this run\n\n";
  for (const auto& c : t.at("claims")) {
    const ojson& h = c.at("holds");
    const std::string note = c.at("note").get<std::string>();
    const std::string verdict = !h.is_null()                          ? (h.get<bool>() ? "holds" : "does not hold")
                                : note.rfind(kInconclusivePrefix, 0) == 0 ? "inconclusive"
                                                                          : "not measured";
    os << "- **" << verdict << "**" << (c.at("informative_only").get<bool>() && !c.at("measured").empty() ? " (informative: CPU device)" : "")
       << " — " << c.at("claim").get<std::string>() << "\n  - criterion: " << c.at("criterion").get<std::string>();
    if (!c.at("measured").empty()) os << "\n  - measured: `" << c.at("measured").dump() << "`";
    if (!c.at("note").get<std::string>().empty()) os << "\n  - " << c.at("note").get<std::string>();
    os << "\n";
  }
  return os.str();
}

}  // namespace vsgl
