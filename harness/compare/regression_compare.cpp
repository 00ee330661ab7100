#include "harness/compare/regression_compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>
#include <stdexcept>

#include "harness/core/error.hpp"
#include "harness/core/text_format.hpp"
#include "harness/core/printable_text.hpp"

namespace vsgl {
namespace {

std::string percent(double ratio_minus_one) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%+.2f %%", ratio_minus_one * 100.0);
  return buf;
}

std::string p_text(double p) {
  char buf[64];
  if (p < 1e-4) std::snprintf(buf, sizeof buf, "%.1e", p);
  else std::snprintf(buf, sizeof buf, "%.4f", p);
  return buf;
}

std::string run_label(const BenchRun& r) {
  std::string s = "`" + r.path + "` — " + r.device + (r.device_type.empty() ? "" : " (" + r.device_type + ")") +
                  ", commit " + r.git_commit + (r.git_dirty ? " (dirty)" : "") + ", " + r.date + ", " + r.format + " JSON";
  if (r.quick) s += ", --quick";
  if (!r.altered_generators.empty()) {
    s += ", altered timings (not a measurement): ";
    for (std::size_t i = 0; i < r.altered_generators.size(); ++i) s += (i ? "," : "") + r.altered_generators[i];
  }
  return s;
}

double geomean(const std::vector<double>& ratios) {
  if (ratios.empty()) return 1.0;
  double log_sum = 0;
  for (double r : ratios) log_sum += std::log(r);
  return std::exp(log_sum / static_cast<double>(ratios.size()));
}

}  // namespace

std::size_t RunComparison::count(Verdict v) const {
  return static_cast<std::size_t>(std::count_if(rows.begin(), rows.end(), [v](const RowComparison& r) { return r.result.verdict == v; }));
}

RunComparison compare_runs(const BenchRun& base, const BenchRun& fresh, const CompareOptions& options) {
  RunComparison out;
  out.different_devices = base.device != fresh.device;
  if (base.format != fresh.format)
    out.mismatches.push_back("BASE is " + base.format + " JSON and NEW is " + fresh.format +
                             " JSON: their samples mean different things (single replays vs repetition means)");
  for (const auto& [number, bt] : base.tables) {
    const auto it = fresh.tables.find(number);
    if (it == fresh.tables.end()) continue;  // its rows are listed as only in BASE
    const std::string table = "table " + std::to_string(number);
    // A paper scene and its procedural stand-in are different inputs: no flag makes them one series.
    if (bt.scene && it->second.scene) {
      const std::string differs = scene_difference(*bt.scene, *it->second.scene);
      if (!differs.empty())
        throw InputError("refusing to compare " + base.path + " with " + fresh.path + ": " + table + ": " + differs +
                         " (runs of different scenes time different inputs; --allow-mismatch does not apply)");
    } else if (bt.scene.has_value() != it->second.scene.has_value()) {
      out.mismatches.push_back(table + ": " + (bt.scene ? "NEW" : "BASE") + " does not say which scene it timed");
    }
    if (bt.capture_hashes != it->second.capture_hashes)
      out.mismatches.push_back(table + ": the runs used different captures (capture hashes differ)");
    if (bt.workload != it->second.workload)
      out.mismatches.push_back(table + ": the runs used different configs: BASE " + printable_text(bt.workload.dump(), 4000) +
                               ", NEW " + printable_text(it->second.workload.dump(), 4000));
  }
  if (!out.mismatches.empty() && !options.allow_mismatch) {
    std::string all;
    for (const auto& m : out.mismatches) all += "\n  " + m;
    throw InputError("refusing to compare " + base.path + " with " + fresh.path + ":" + all +
                     "\n(pass --allow-mismatch to compare them anyway; the report will say so)");
  }

  std::set<std::string> base_names;
  std::vector<double> ratios, total_ratios, view_total_ratios;
  for (const RunSeries& b : base.series) {
    base_names.insert(b.name);
    const RunSeries* n = fresh.find(b.name);
    if (n == nullptr) {
      out.only_in_base.push_back(b.name);
      continue;
    }
    RowComparison row;
    row.name = b.name;
    row.total = b.is_total();
    row.base_samples = b.samples_ms.size();
    row.new_samples = n->samples_ms.size();
    try {
      row.result = compare_samples(b.samples_ms, n->samples_ms, options.verdict);
    } catch (const std::invalid_argument& e) {
      throw InputError(printable_text(b.name) + ": cannot compare the samples: " + e.what());
    }
    const double ratio = row.result.new_median / row.result.base_median;
    ratios.push_back(ratio);
    if (b.is_total()) (b.view.empty() ? total_ratios : view_total_ratios).push_back(ratio);
    out.rows.push_back(std::move(row));
  }
  for (const RunSeries& n : fresh.series)
    if (!base_names.contains(n.name)) out.only_in_new.push_back(n.name);
  if (out.rows.empty())
    throw InputError(base.path + " and " + fresh.path + " have no benchmark in common (different tables or generators?)");
  out.geomean_ratio = geomean(ratios);
  out.geomean_ratio_totals = geomean(total_ratios.empty() ? view_total_ratios : total_ratios);
  return out;
}

std::string comparison_markdown(const BenchRun& base, const BenchRun& fresh, const RunComparison& c,
                                const CompareOptions& options) {
  std::ostringstream os;
  os << "# vsgl-bench compare\n\n";
  os << "- BASE: " << run_label(base) << "\n";
  os << "- NEW: " << run_label(fresh) << "\n";
  if (c.different_devices)
    os << "- **Different devices** (" << base.device << " → " << fresh.device
       << "): the verdicts compare the devices, not a code change.\n";
  for (const auto& m : c.mismatches) os << "- **Mismatch allowed** (--allow-mismatch): " << m << "\n";
  os << "- Verdict per row from the raw samples: two-sided Mann–Whitney U test at α = " << options.verdict.alpha
     << ", minimum relevant change of the median " << options.verdict.min_change * 100.0 << " %, noise factor "
     << options.verdict.noise_factor << " x the larger relative IQR of the two runs, at least "
     << options.verdict.min_samples << " samples per side. SAME: the median moved less than the minimum; "
     << "FASTER/SLOWER: it moved more than both the minimum and the noise, and p < α; AMBIGUOUS: too few "
     << "samples, a move within the runs' noise, or p ≥ α.\n\n";

  os << "| benchmark | BASE median (ms) | NEW median (ms) | change | p | n (BASE/NEW) | verdict |\n";
  os << "|---|---:|---:|---:|---:|---:|---|\n";
  for (const auto& r : c.rows) {
    const std::string name = r.total ? "**" + r.name + "**" : r.name;
    const std::string verdict = r.result.verdict == Verdict::kSame ? "SAME"
                                                                    : std::string("**") + verdict_name(r.result.verdict) + "**";
    os << "| " << name << " | " << fixed_text(r.result.base_median, 4) << " | " << fixed_text(r.result.new_median, 4)
       << " | " << percent(r.result.change) << " | " << p_text(r.result.p_value) << " | " << r.base_samples << "/"
       << r.new_samples << " | " << verdict << " |\n";
  }
  os << "\n## Summary\n\n";
  os << "- " << c.rows.size() << " rows compared: " << c.count(Verdict::kFaster) << " FASTER, " << c.count(Verdict::kSlower)
     << " SLOWER, " << c.count(Verdict::kSame) << " SAME, " << c.count(Verdict::kAmbiguous) << " AMBIGUOUS.\n";
  os << "- Geometric mean of NEW/BASE medians: " << percent(c.geomean_ratio - 1.0) << " over all rows, "
     << percent(c.geomean_ratio_totals - 1.0) << " over the totals.\n";
  const auto list = [&os](const char* what, const std::vector<std::string>& names) {
    if (names.empty()) return;
    os << "- " << names.size() << " rows only in " << what << " (not compared):";
    for (const auto& n : names) os << " `" << n << "`";
    os << "\n";
  };
  list("BASE", c.only_in_base);
  list("NEW", c.only_in_new);
  return os.str();
}

std::vector<Verdict> parse_fail_on(const std::string& list) {
  std::vector<Verdict> out;
  std::stringstream ss(list);
  for (std::string item; std::getline(ss, item, ',');) {
    if (item == "slower") out.push_back(Verdict::kSlower);
    else if (item == "ambiguous") out.push_back(Verdict::kAmbiguous);
    else if (item == "faster") out.push_back(Verdict::kFaster);
    else if (item == "none" || item.empty()) continue;
    else throw UsageError("--fail-on takes slower, ambiguous, faster (comma-separated) or none, not '" + item + "'");
  }
  return out;
}

}  // namespace vsgl
