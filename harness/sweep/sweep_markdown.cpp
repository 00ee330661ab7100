#include "harness/sweep/sweep_markdown.hpp"

#include <algorithm>
#include <vector>

#include "harness/core/text_format.hpp"
#include "harness/sweep/pdf_independence.hpp"

namespace vsgl {
namespace {

std::string ms_text(double v) { return number_text(v, 4); }

// "1.234 (IQR 0.0123)": the median and its spread, as the tables print them.
std::string cell_text(const TimingStatistics& s) {
  return ms_text(s.median_ms) + " (IQR " + ms_text(s.q3_ms - s.q1_ms) + ")";
}

std::string verdict_text(const SweepFitModel& f) {
  if (!f.growth) return "no fit: " + f.note;
  if (!f.verdict) return "no expectation";
  return f.flagged() ? "**" + f.verdict_word() + "** (expected " + number_text(f.expected->slope, 3) + ": " +
                           f.expected->why + ")"
                     : f.verdict_word();
}

// "gbuffer=3840x2176, K=2": each axis's value at a point.
std::string values_text(const SweepModel& s, const std::vector<std::size_t>& value_index) {
  std::string out;
  for (std::size_t a = 0; a < s.axes.size(); ++a)
    out += (out.empty() ? "" : ", ") + s.axes[a].name + "=" + s.axes[a].values[value_index.at(a)].text;
  return out;
}

std::string header(const SweepModel& s) {
  std::string md = "# Sweep: " + scene_label(s.scene) + "\n\n";
  md += "Axes:";
  for (const SweepAxisModel& a : s.axes) md += " `" + a.spec + "`";
  md += " (" + std::to_string(s.points.size()) + " points). Median ms (IQR) per generator, view and phase";
  if (s.time_budget_s) md += "; time budget " + number_text(*s.time_budget_s, 4) + " s split over the points";
  md += ".\n";
  if (s.order)
    md += "Timed in " + std::to_string(s.order->blocks) +
          " repeated blocks, each visiting every point once in an order drawn from seed " +
          std::to_string(s.order->seed) + "; a point's rounds are pooled over its visits.\n";
  if (!s.beyond_device.empty()) {
    md += "\nBeyond this device, not timed (a case: its generator and view; else the whole point):\n\n";
    for (const SweepBeyondDevice& b : s.beyond_device)
      md += "- " + values_text(s, b.value_index) +
            (b.generator.empty() ? std::string() : ", " + b.generator + " " + b.view) + ": " + b.reason + "\n";
  }
  std::size_t flagged = 0;
  for (const SweepFitModel& f : s.fits) flagged += f.flagged() ? 1 : 0;
  md += flagged == 0
            ? "No phase grows other than its algorithm predicts.\n"
            : std::to_string(flagged) + " fit(s) exclude the expected growth (marked **faster**/**slower**).\n";
  return md;
}

// The value of axis `a` at a point, to order the columns by.
double axis_value(const SweepModel& s, std::size_t a, std::size_t point) {
  return s.axes[a].values[s.points[point].value_index[a]].value;
}

// Every point any case of the slice was timed at, by the axis's value (a case beyond the device at
// one of them shows "beyond" there).
std::vector<std::size_t> slice_columns(const SweepModel& s, std::size_t a, const std::string& slice) {
  std::vector<std::size_t> columns;
  for (const SweepFitModel& g : s.fits)
    if (g.axis == a && sweep_slice_text(g.slice) == slice)
      for (std::size_t i : g.points)
        if (std::find(columns.begin(), columns.end(), i) == columns.end()) columns.push_back(i);
  std::sort(columns.begin(), columns.end(),
            [&](std::size_t i, std::size_t j) { return axis_value(s, a, i) < axis_value(s, a, j); });
  return columns;
}

std::string axis_tables(const SweepModel& s, std::size_t a) {
  const SweepAxisModel& axis = s.axes[a];
  std::string md = "\n## Axis " + axis.name + " (`" + axis.spec + "`)\n";
  std::string current_slice = "\x01";
  std::vector<std::size_t> columns;
  for (const SweepFitModel& f : s.fits) {
    if (f.axis != a) continue;
    const std::string st = sweep_slice_text(f.slice);
    if (st != current_slice) {
      current_slice = st;
      columns = slice_columns(s, a, st);
      if (!st.empty()) md += "\n### " + st + "\n";
      md += "\n| generator | view | phase |";
      for (std::size_t i : columns) md += " " + axis.name + "=" + axis.values[s.points[i].value_index[a]].text + " |";
      md += " growth | verdict |\n|---|---|---|";
      for (std::size_t k = 0; k < columns.size(); ++k) md += "---:|";
      md += "---|---|\n";
    }
    md += "| " + f.generator + " | " + f.view + " | " + f.phase + " |";
    for (std::size_t i : columns) {
      const SweepCase* c = s.points[i].find(f.generator, f.view);
      const TimingStatistics* stats = c != nullptr ? c->find(f.phase) : nullptr;
      md += " " + (stats != nullptr ? cell_text(*stats) : std::string("beyond")) + " |";
    }
    md += " " + (f.growth ? f.growth->text : std::string("–")) + " | " + verdict_text(f) + " |\n";
  }
  return md;
}

std::string pdf_frequency_table(const SweepModel& s) {
  std::string md =
      "\n## PDF frequency at each γ\n\nvar(p) of each view's PDF (DESIGN.md §11a), the measure FIS must not "
      "depend on.\n\n| point | γ | camera_view var(p) | light_view var(p) |\n|---:|---:|---:|---:|\n";
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const std::optional<SweepPdfSharpness>& p = s.points[i].pdf_sharpness;
    if (!p) continue;
    const auto var = [&](const char* view) {
      for (const auto& [name, f] : p->frequency)
        if (name == view) return number_text(f.relative_variance, 4);
      return std::string("–");
    };
    md += "| " + std::to_string(i) + " | " + number_text(p->gamma, 4) + " | " + var("camera_view") + " | " +
          var("light_view") + " |\n";
  }
  return md;
}

std::string claim_table(const SweepClaim& c) {
  // Files written before the equivalence test (no alpha) keep their own wording and columns.
  const bool tost = c.alpha.has_value();
  std::string md =
      "\n## PDF independence" + (c.slice.empty() ? std::string() : " (" + sweep_slice_text(c.slice) + ")") + ": " +
      claim_verdict(c.claim) + "\n\nChange of each view's median total from γ=" + number_text(c.reference_gamma, 4) +
      ", with 95 % bootstrap intervals; ";
  if (tost)
    md += "each FIS case must be shown equivalent within ±" + number_text(100 * c.band, 3) +
          " % at every γ (TOST, Holm-corrected across the FIS cases at α=" + number_text(*c.alpha, 3) +
          ") and each paper k-means generator must move more than either FIS.\n\n";
  else
    md += "FIS must stay within ±" + number_text(100 * c.band, 3) +
          " % and each paper k-means generator must move more than either FIS.\n\n";
  md += "| generator | view |";
  const std::size_t gammas = c.measures.empty() ? 0 : c.measures.front().changes.size();
  for (std::size_t k = 0; k < gammas; ++k) md += " γ=" + number_text(c.measures.front().changes[k].gamma, 4) + " |";
  md += tost ? " spread | equivalence (TOST p, Holm level) |\n|---|---|" : " spread |\n|---|---|";
  for (std::size_t k = 0; k < gammas; ++k) md += "---:|";
  md += tost ? "---:|---|\n" : "---:|\n";
  const auto pct = [](double v) { return number_text(100 * v, 3) + " %"; };
  for (const SweepClaimMeasure& p : c.measures) {
    md += "| " + p.generator + " | " + p.view + " |";
    for (const SweepClaimChange& g : p.changes)
      md += " " + pct(g.change) + " [" + pct(g.low) + ", " + pct(g.high) + "] |";
    md += " " + pct(p.spread) + " [" + pct(p.spread_low) + ", " + pct(p.spread_high) + "] |";
    if (tost)
      md += p.equivalence ? " " + equivalence_text(p.equivalence->verdict.outcome) + " (p " +
                                number_text(p.equivalence->p_equivalent, 3) + ", level " +
                                number_text(p.equivalence->level_equivalent, 3) + ") |"
                          : " |";
    md += "\n";
  }
  if (!claim_note(c.claim).empty()) md += "\n" + claim_note(c.claim) + "\n";
  return md;
}

}  // namespace

std::string sweep_markdown(const SweepModel& s) {
  std::string md = header(s);
  for (std::size_t a = 0; a < s.axes.size(); ++a) md += axis_tables(s, a);
  if (std::any_of(s.points.begin(), s.points.end(), [](const SweepPoint& p) { return p.pdf_sharpness.has_value(); }))
    md += pdf_frequency_table(s);
  if (s.claims)
    for (const SweepClaim& c : *s.claims) md += claim_table(c);
  return md;
}

}  // namespace vsgl
