#include "harness/formats/sweep_model.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "harness/core/path_text.hpp"
#include "harness/core/error.hpp"
#include "harness/core/growth_fit.hpp"
#include "harness/core/json_reader.hpp"
#include "harness/core/printable_text.hpp"
#include "harness/core/text_format.hpp"

namespace vsgl {
namespace {

using ojson = nlohmann::ordered_json;

// Field access that names the file and the JSON pointer of whatever is missing or mistyped.
using Reader = JsonReader;  // core/json_reader.hpp, with JSON pointers

// A count or an index into the document (size_t; the reader's non-negative integer).
std::size_t index(const Reader& r, const ojson& v, const std::string& pointer) {
  return static_cast<std::size_t>(r.uint64(v, pointer));
}

TimingStatistics read_stats(const Reader& r, const ojson& series, const std::string& p) {
  return timing_statistics_from_json(r, series, p, StatisticsLayout::kSweep);
}

SweepCase read_case(const Reader& r, const ojson& c, const std::string& p) {
  if (!c.is_object()) r.wrong_type(c, p, "an object");
  SweepCase out;
  out.generator = r.string(c, p, "generator");
  out.view = r.string(c, p, "view");
  if (out.view != "camera_view" && out.view != "light_view")
    r.fail(p + "/view", "is " + quoted_text(out.view) + ", not camera_view or light_view");
  out.dispatches = r.uint32(c, p, "dispatches");
  const ojson& phases = r.nonempty_array(c, p, "phases");
  for (std::size_t i = 0; i < phases.size(); ++i) {
    const std::string pp = p + "/phases/" + std::to_string(i);
    if (!phases[i].is_object()) r.wrong_type(phases[i], pp, "an object");
    out.phases.push_back(SweepPhaseTiming{r.string(phases[i], pp, "name"), read_stats(r, phases[i], pp)});
  }
  out.total = read_stats(r, r.object(c, p, "total"), p + "/total");
  return out;
}

SweepAxisModel read_axis(const Reader& r, const ojson& a, const std::string& p) {
  if (!a.is_object()) r.wrong_type(a, p, "an object");
  SweepAxisModel out;
  out.name = r.string(a, p, "name");
  out.spec = r.string(a, p, "spec");
  out.symbol = r.string(a, p, "symbol");
  out.growth_x_title = r.string(a, p, "growth_x");
  const ojson& values = r.nonempty_array(a, p, "values");
  for (std::size_t i = 0; i < values.size(); ++i) {
    const std::string vp = p + "/values/" + std::to_string(i);
    const ojson& v = values[i];
    if (!v.is_object()) r.wrong_type(v, vp, "an object");
    SweepAxisValue value{r.string(v, vp, "text"), r.non_negative(r.member(v, vp, "value"), vp + "/value"),
                         r.non_negative(r.member(v, vp, "growth_x"), vp + "/growth_x"), std::nullopt, std::nullopt};
    if (v.contains("width")) value.width = r.uint32(v, vp, "width");
    if (v.contains("height")) value.height = r.uint32(v, vp, "height");
    out.values.push_back(std::move(value));
    for (std::size_t k = 0; k + 1 < out.values.size(); ++k)
      if (out.values[k].text == out.values.back().text)
        r.fail(vp + "/text", "repeats value " + quoted_text(out.values[k].text));
  }
  return out;
}

// A point's "values": each axis's value as text, as an index into that axis's values.
std::vector<std::size_t> read_value_index(const Reader& r, const ojson& pj, const std::string& p,
                                          const std::vector<SweepAxisModel>& axes) {
  const ojson& values = r.object(pj, p, "values");
  for (const auto& [name, text] : r.string_map(values, p + "/values")) {
    bool known = false;
    for (const SweepAxisModel& a : axes) known = known || a.name == name;
    if (!known) r.fail(p + "/values/" + name, "names no axis of the sweep");
  }
  std::vector<std::size_t> out;
  for (const SweepAxisModel& a : axes) {
    const std::string vp = p + "/values/" + a.name;
    const std::string text = r.string(values, p + "/values", a.name);
    std::size_t k = 0;
    while (k < a.values.size() && a.values[k].text != text) ++k;
    if (k == a.values.size()) r.fail(vp, "is " + quoted_text(text) + ", not a value of axis " + a.name);
    out.push_back(k);
  }
  return out;
}

SweepPointTiming read_point_timing(const Reader& r, const ojson& t, const std::string& p) {
  SweepPointTiming out;
  out.time_cap_s = r.time(t, p, "time_cap_s");
  out.repetitions = r.uint32(t, p, "repetitions");
  out.timed_seconds = r.non_negative(r.member(t, p, "timed_seconds"), p + "/timed_seconds");
  out.stop_reason = r.string(t, p, "stop_reason");
  out.worst_noise = r.non_negative(r.member(t, p, "worst_noise"), p + "/worst_noise");
  if (t.contains("block_rounds")) {
    const ojson& rounds = r.nonempty_array(t, p, "block_rounds");
    uint64_t sum = 0;
    for (std::size_t k = 0; k < rounds.size(); ++k) {
      out.block_rounds.push_back(static_cast<uint32_t>(r.uint64(rounds[k], p + "/block_rounds/" + std::to_string(k))));
      sum += out.block_rounds.back();
    }
    if (sum != out.repetitions)
      r.fail(p + "/block_rounds",
             "sums to " + std::to_string(sum) + ", not the " + std::to_string(out.repetitions) + " repetitions");
  }
  return out;
}

SweepOrderModel read_order(const Reader& r, const ojson& o, std::size_t planned) {
  if (!o.is_object()) r.wrong_type(o, "/order", "an object");
  SweepOrderModel out;
  out.blocks = r.uint32(o, "/order", "blocks");
  out.seed = r.uint64(o, "/order", "seed");
  const ojson& visits = r.nonempty_array(o, "/order", "visits");
  if (visits.size() != out.blocks)
    r.fail("/order/visits", "has " + std::to_string(visits.size()) + " blocks, not " + std::to_string(out.blocks));
  for (std::size_t b = 0; b < visits.size(); ++b) {
    const std::string vp = "/order/visits/" + std::to_string(b);
    if (!visits[b].is_array()) r.wrong_type(visits[b], vp, "an array");
    std::vector<std::size_t> block;
    for (std::size_t k = 0; k < visits[b].size(); ++k)
      block.push_back(index(r, visits[b][k], vp + "/" + std::to_string(k)));
    std::vector<std::size_t> sorted = block;
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t k = 0; k < sorted.size(); ++k)
      if (sorted[k] != k || sorted.size() != planned)
        r.fail(vp, "is not an order of the " + std::to_string(planned) + " points of the axes' product");
    out.visits.push_back(std::move(block));
  }
  return out;
}

SweepPdfSharpness read_pdf_sharpness(const Reader& r, const ojson& s, const std::string& p) {
  SweepPdfSharpness out;
  out.gamma = r.non_negative(r.member(s, p, "gamma"), p + "/gamma");
  out.definition = r.string(s, p, "definition");
  const ojson& frequency = r.object(s, p, "pdf_frequency");
  for (const auto& [view, f] : frequency.items()) {
    const std::string fp = p + "/pdf_frequency/" + view;
    if (!f.is_object()) r.wrong_type(f, fp, "an object");
    SweepPdfFrequency freq;
    freq.relative_variance = r.non_negative(r.member(f, fp, "relative_variance"), fp + "/relative_variance");
    const ojson& shares = r.array(f, fp, "fine_share");
    for (std::size_t k = 0; k < shares.size(); ++k)
      freq.fine_share.push_back(r.non_negative(shares[k], fp + "/fine_share/" + std::to_string(k)));
    out.frequency.emplace_back(view, std::move(freq));
  }
  return out;
}

SweepPoint read_point(const Reader& r, const ojson& pj, const std::string& p, std::size_t position,
                      const std::vector<SweepAxisModel>& axes) {
  if (!pj.is_object()) r.wrong_type(pj, p, "an object");
  SweepPoint out;
  out.index = index(r, r.member(pj, p, "index"), p + "/index");
  if (out.index != position)
    r.fail(p + "/index", "is " + std::to_string(out.index) + ", not its position " + std::to_string(position));
  out.value_index = read_value_index(r, pj, p, axes);
  out.capture_dir = r.string(pj, p, "capture_dir");
  out.capture = r.object(pj, p, "capture");
  out.config = r.object(pj, p, "config");
  out.timing = read_point_timing(r, r.object(pj, p, "timing"), p + "/timing");
  const ojson& cases = r.nonempty_array(pj, p, "cases");
  for (std::size_t i = 0; i < cases.size(); ++i)
    out.cases.push_back(read_case(r, cases[i], p + "/cases/" + std::to_string(i)));
  if (pj.contains("pdf_sharpness"))
    out.pdf_sharpness = read_pdf_sharpness(r, r.object(pj, p, "pdf_sharpness"), p + "/pdf_sharpness");
  return out;
}

SweepFitModel read_fit(const Reader& r, const ojson& f, const std::string& p, const SweepModel& m) {
  if (!f.is_object()) r.wrong_type(f, p, "an object");
  SweepFitModel out;
  const std::string axis = r.string(f, p, "axis");
  while (out.axis < m.axes.size() && m.axes[out.axis].name != axis) ++out.axis;
  if (out.axis == m.axes.size()) r.fail(p + "/axis", "is " + quoted_text(axis) + ", not an axis of the sweep");
  out.slice = r.string_map(r.member(f, p, "slice"), p + "/slice");
  out.generator = r.string(f, p, "generator");
  out.view = r.string(f, p, "view");
  out.phase = r.string(f, p, "phase");
  const ojson& points = r.nonempty_array(f, p, "points");
  const ojson& xs = r.array(f, p, "growth_x");
  if (xs.size() != points.size())
    r.fail(p + "/growth_x",
           "has " + std::to_string(xs.size()) + " values for " + std::to_string(points.size()) + " points");
  for (std::size_t k = 0; k < points.size(); ++k) {
    const std::string pp = p + "/points/" + std::to_string(k);
    const std::size_t i = index(r, points[k], pp);
    if (i >= m.points.size()) r.fail(pp, "is " + std::to_string(i) + ", past the last point");
    const SweepCase* c = m.points[i].find(out.generator, out.view);
    if (c == nullptr || c->find(out.phase) == nullptr)
      r.fail(pp,
             "is point " + std::to_string(i) + ", which has no " + out.generator + " " + out.view + " " + out.phase);
    const std::string xp = p + "/growth_x/" + std::to_string(k);
    const double x = r.non_negative(xs[k], xp);
    const double expected = m.axes[out.axis].values[m.points[i].value_index[out.axis]].growth_x;
    if (std::abs(x - expected) > 1e-9 * std::max(1.0, std::abs(expected)))
      r.fail(xp, "is " + number_text(x, 9) + ", not point " + std::to_string(i) + "'s " + axis + " growth_x " +
                     number_text(expected, 9));
    out.points.push_back(i);
    out.growth_x.push_back(x);
  }
  const ojson& growth = r.member(f, p, "growth");
  if (!growth.is_null()) {
    if (!growth.is_object()) r.wrong_type(growth, p + "/growth", "an object or null");
    const std::string gp = p + "/growth";
    out.growth = SweepGrowth{r.number(growth, gp, "slope"),
                             r.number(growth, gp, "low"),
                             r.number(growth, gp, "high"),
                             r.number(growth, gp, "confidence"),
                             index(r, r.member(growth, gp, "resamples"), gp + "/resamples"),
                             index(r, r.member(growth, gp, "points"), gp + "/points"),
                             r.string(growth, gp, "text")};
  }
  out.note = r.optional_string(f, p, "note").value_or("");
  const ojson& expected = r.member(f, p, "expected");
  if (!expected.is_null()) {
    if (!expected.is_object()) r.wrong_type(expected, p + "/expected", "an object or null");
    const std::string ep = p + "/expected";
    out.expected = SweepExpected{r.number(expected, ep, "slope"), r.number(expected, ep, "tolerance"),
                                 r.string(expected, ep, "why")};
  }
  const ojson& verdict = r.member(f, p, "verdict");
  const bool flagged = r.boolean(f, p, "flagged");
  if (!verdict.is_null()) {
    const std::string word = r.string(f, p, "verdict");
    if (word != "consistent" && word != "faster" && word != "slower")
      r.fail(p + "/verdict", "is " + quoted_text(word) + ", not consistent, faster, slower or null");
    if (!out.growth || !out.expected) r.fail(p + "/verdict", "is set, but the fit has no growth or no expectation");
    try {
      out.verdict = growth_verdict(out.growth->low, out.growth->high, out.expected->slope, out.expected->tolerance);
    } catch (const std::invalid_argument& e) {
      r.fail(p + "/verdict", std::string("cannot be judged again: ") + e.what());
    }
    if (out.verdict_word() != word)
      r.fail(p + "/verdict", "is " + quoted_text(word) + ", but the growth interval against the expected band says " +
                                 quoted_text(out.verdict_word()));
  }
  if (flagged != out.flagged())
    r.fail(p + "/flagged", std::string("is ") + (flagged ? "true" : "false") + ", but the verdict says otherwise");
  out.judgement = r.optional_string(f, p, "judgement").value_or("");
  return out;
}

// A p-value or a level: a number in [0, 1].
double p_value(const Reader& r, const ojson& object, const std::string& parent, const char* key) {
  const double v = r.number(object, parent, key);
  if (!(v >= 0 && v <= 1)) r.fail(parent + "/" + key, "is " + number_text(v, 6) + ", not in [0, 1]");
  return v;
}

SweepClaimMeasure read_claim_measure(const Reader& r, const ojson& m, const std::string& p) {
  if (!m.is_object()) r.wrong_type(m, p, "an object");
  SweepClaimMeasure out;
  out.generator = r.string(m, p, "generator");
  out.view = r.string(m, p, "view");
  out.family = r.string(m, p, "family");
  out.in_paper = r.boolean(m, p, "in_paper");
  out.spread = r.number(m, p, "spread");
  out.spread_low = r.number(m, p, "spread_low");
  out.spread_high = r.number(m, p, "spread_high");
  const ojson& changes = r.array(m, p, "changes");
  for (std::size_t k = 0; k < changes.size(); ++k) {
    const std::string cp = p + "/changes/" + std::to_string(k);
    const ojson& c = changes[k];
    if (!c.is_object()) r.wrong_type(c, cp, "an object");
    SweepClaimChange change{r.non_negative(r.member(c, cp, "gamma"), cp + "/gamma"),
                            index(r, r.member(c, cp, "point"), cp + "/point"),
                            r.number(c, cp, "change"),
                            r.number(c, cp, "low"),
                            r.number(c, cp, "high"),
                            {},
                            {}};
    if (c.contains("p_equivalent")) change.p_equivalent = p_value(r, c, cp, "p_equivalent");
    if (c.contains("p_outside")) change.p_outside = p_value(r, c, cp, "p_outside");
    out.changes.push_back(change);
  }
  if (m.contains("equivalence")) {
    const std::string ep = p + "/equivalence";
    const ojson& e = r.object(m, p, "equivalence");
    SweepClaimEquivalence q{p_value(r, e, ep, "p_equivalent"),
                            p_value(r, e, ep, "p_outside"),
                            p_value(r, e, ep, "level_equivalent"),
                            p_value(r, e, ep, "level_outside"),
                            {}};
    const std::string word = r.string(e, ep, "verdict");
    bool known = false;
    for (const Outcome o : {Outcome::kHolds, Outcome::kDoesNotHold, Outcome::kInconclusive})
      if (word == equivalence_text(o)) {
        q.verdict.outcome = o;
        known = true;
      }
    if (!known)
      r.fail(ep + "/verdict", "is " + quoted_text(word) + R"(, not "equivalent", "not equivalent" or "inconclusive")");
    q.verdict.rule = kEquivalenceRule;
    out.equivalence = q;
  }
  return out;
}

std::vector<SweepClaim> read_claims(const Reader& r, const ojson& a) {
  if (!a.is_array()) r.wrong_type(a, "/claims", "an array");
  std::vector<SweepClaim> out;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::string p = "/claims/" + std::to_string(i);
    const ojson& c = a[i];
    if (!c.is_object()) r.wrong_type(c, p, "an object");
    SweepClaim sweep;
    Claim& claim = sweep.claim;  // the fields every document's claim has
    claim.id = r.string(c, p, "id");
    claim.text = r.string(c, p, "text");
    sweep.axis = r.string(c, p, "axis");
    sweep.slice = r.string_map(r.member(c, p, "slice"), p + "/slice");
    claim.criterion = r.string(c, p, "criterion");
    sweep.reference_gamma = r.non_negative(r.member(c, p, "reference_gamma"), p + "/reference_gamma");
    sweep.band = r.number(c, p, "band");
    if (c.contains("alpha")) {
      sweep.alpha = r.number(c, p, "alpha");
      if (!(*sweep.alpha > 0 && *sweep.alpha < 1)) r.fail(p + "/alpha", "is not in (0, 1)");
    }
    const ojson& measured = r.array(c, p, "measured");
    for (std::size_t k = 0; k < measured.size(); ++k)
      sweep.measures.push_back(read_claim_measure(r, measured[k], p + "/measured/" + std::to_string(k)));
    const ojson& holds = r.member(c, p, "holds");
    set_verdict(claim, holds.is_null() ? std::nullopt : std::optional<bool>(r.boolean(c, p, "holds")),
                r.string(c, p, "note"));
    claim.informative = r.boolean(c, p, "informative");
    out.push_back(std::move(sweep));
  }
  return out;
}

// The writer's side, key for key in the order the reader reads and the schema lists them.

ojson string_map_json(const std::vector<std::pair<std::string, std::string>>& map) {
  ojson j = ojson::object();
  for (const auto& [key, value] : map) j[key] = value;
  return j;
}

// A point's "values": each axis's name and value text.
ojson values_json(const std::vector<SweepAxisModel>& axes, const std::vector<std::size_t>& value_index) {
  ojson values = ojson::object();
  for (std::size_t a = 0; a < axes.size(); ++a) values[axes[a].name] = axes[a].values[value_index[a]].text;
  return values;
}

// A named series: its name first, then the sweep layout of its statistics.
ojson named_stats_json(const std::string& name, const TimingStatistics& s) {
  const ojson series = to_json(s, StatisticsLayout::kSweep);
  ojson out = ojson::object();
  out["name"] = name;
  out["stats"] = series.at("stats");
  out["samples_ms"] = series.at("samples_ms");
  return out;
}

ojson case_json(const SweepCase& c) {
  ojson phases = ojson::array();
  for (const SweepPhaseTiming& p : c.phases) phases.push_back(named_stats_json(p.name, p.stats));
  return ojson{{"generator", c.generator},
               {"view", c.view},
               {"dispatches", c.dispatches},
               {"phases", phases},
               {"total", to_json(c.total, StatisticsLayout::kSweep)}};
}

ojson axis_json(const SweepAxisModel& a) {
  ojson values = ojson::array();
  for (const SweepAxisValue& v : a.values) {
    ojson value{{"text", v.text}, {"value", v.value}, {"growth_x", v.growth_x}};
    if (v.width) value["width"] = *v.width;
    if (v.height) value["height"] = *v.height;
    values.push_back(std::move(value));
  }
  return ojson{
      {"name", a.name}, {"spec", a.spec}, {"symbol", a.symbol}, {"growth_x", a.growth_x_title}, {"values", values}};
}

ojson point_json(const SweepPoint& p, const std::vector<SweepAxisModel>& axes) {
  ojson cases = ojson::array();
  for (const SweepCase& c : p.cases) cases.push_back(case_json(c));
  ojson point{{"index", p.index},
              {"values", values_json(axes, p.value_index)},
              {"capture_dir", p.capture_dir},
              {"capture", p.capture},
              {"config", p.config},
              {"timing", ojson{{"time_cap_s", p.timing.time_cap_s},
                               {"repetitions", p.timing.repetitions},
                               {"timed_seconds", p.timing.timed_seconds},
                               {"stop_reason", p.timing.stop_reason},
                               {"worst_noise", p.timing.worst_noise}}},
              {"cases", cases}};
  if (!p.timing.block_rounds.empty()) point["timing"]["block_rounds"] = p.timing.block_rounds;
  if (p.pdf_sharpness) {
    ojson frequency = ojson::object();
    for (const auto& [view, f] : p.pdf_sharpness->frequency)
      frequency[view] = ojson{{"relative_variance", f.relative_variance}, {"fine_share", f.fine_share}};
    point["pdf_sharpness"] = ojson{
        {"gamma", p.pdf_sharpness->gamma}, {"definition", p.pdf_sharpness->definition}, {"pdf_frequency", frequency}};
  }
  return point;
}

ojson beyond_json(const SweepBeyondDevice& b, const std::vector<SweepAxisModel>& axes) {
  ojson entry{{"values", values_json(axes, b.value_index)}};
  if (!b.generator.empty()) entry["generator"] = b.generator;
  if (!b.view.empty()) entry["view"] = b.view;
  entry["reason"] = b.reason;
  return entry;
}

ojson fit_json(const SweepFitModel& f, const std::vector<SweepAxisModel>& axes) {
  ojson j{{"axis", axes[f.axis].name}, {"slice", string_map_json(f.slice)},
          {"generator", f.generator},  {"view", f.view},
          {"phase", f.phase},          {"points", f.points},
          {"growth_x", f.growth_x}};
  if (f.growth) {
    j["growth"] = ojson{{"slope", f.growth->slope},
                        {"low", f.growth->low},
                        {"high", f.growth->high},
                        {"confidence", f.growth->confidence},
                        {"resamples", f.growth->resamples},
                        {"points", f.growth->points},
                        {"text", f.growth->text}};
  } else {
    j["growth"] = nullptr;
    j["note"] = f.note;
  }
  j["expected"] =
      f.expected ? ojson{{"slope", f.expected->slope}, {"tolerance", f.expected->tolerance}, {"why", f.expected->why}}
                 : ojson(nullptr);
  j["verdict"] = f.verdict ? ojson(f.verdict_word()) : ojson(nullptr);
  j["flagged"] = f.flagged();
  if (f.verdict) j["judgement"] = f.judgement;
  return j;
}

ojson claim_json(const SweepClaim& s) {
  // The shared fields go between the sweep's own keys, in the order the committed files have.
  const Claim& c = s.claim;
  ojson measured = ojson::array();
  for (const SweepClaimMeasure& m : s.measures) {
    ojson changes = ojson::array();
    for (const SweepClaimChange& g : m.changes) {
      ojson change{{"gamma", g.gamma}, {"point", g.point}, {"change", g.change}, {"low", g.low}, {"high", g.high}};
      if (g.p_equivalent) change["p_equivalent"] = *g.p_equivalent;
      if (g.p_outside) change["p_outside"] = *g.p_outside;
      changes.push_back(std::move(change));
    }
    ojson measure{{"generator", m.generator},     {"view", m.view},     {"family", m.family},
                  {"in_paper", m.in_paper},       {"spread", m.spread}, {"spread_low", m.spread_low},
                  {"spread_high", m.spread_high}, {"changes", changes}};
    if (m.equivalence)
      measure["equivalence"] = ojson{{"p_equivalent", m.equivalence->p_equivalent},
                                     {"p_outside", m.equivalence->p_outside},
                                     {"level_equivalent", m.equivalence->level_equivalent},
                                     {"level_outside", m.equivalence->level_outside},
                                     {"verdict", equivalence_text(m.equivalence->verdict.outcome)}};
    measured.push_back(std::move(measure));
  }
  ojson j{{"id", c.id},
          {"text", c.text},
          {"axis", s.axis},
          {"slice", string_map_json(s.slice)},
          {"criterion", c.criterion},
          {"reference_gamma", s.reference_gamma},
          {"band", s.band}};
  if (s.alpha) j["alpha"] = *s.alpha;
  j["measured"] = std::move(measured);
  j["holds"] = claim_holds_json(c);
  j["note"] = claim_note(c);
  j["informative"] = c.informative;
  return j;
}

}  // namespace

const TimingStatistics* SweepCase::find(const std::string& phase) const {
  if (phase == "total") return &total;
  for (const SweepPhaseTiming& p : phases)
    if (p.name == phase) return &p.stats;
  return nullptr;
}

const SweepCase* SweepPoint::find(const std::string& generator, const std::string& view) const {
  for (const SweepCase& c : cases)
    if (c.generator == generator && c.view == view) return &c;
  return nullptr;
}

std::size_t SweepModel::planned_points() const {
  std::size_t n = axes.empty() ? 0 : 1;
  for (const SweepAxisModel& a : axes) n *= a.values.size();
  return n;
}

std::size_t SweepModel::reached_points() const {
  std::size_t n = points.size();
  for (const SweepBeyondDevice& b : beyond_device) n += b.generator.empty() ? 1 : 0;
  return n;
}

std::string sweep_slice_text(const std::vector<std::pair<std::string, std::string>>& slice) {
  std::string s;
  for (const auto& [name, value] : slice) s += (s.empty() ? "" : ", ") + name + "=" + value;
  return s;
}

SweepModel read_sweep_model(const nlohmann::ordered_json& doc, const std::string& what) {
  const Reader r(what, JsonPathStyle::kPointer);
  if (!doc.is_object()) r.fail("", "is not a JSON object");
  // The kind first: a table or quality JSON is told apart from a damaged sweep.
  if (!doc.contains("kind")) r.fail("/kind", "missing field: not a sweep JSON (kind \"sweep\")");
  const std::string kind = r.string(doc, "", "kind");
  if (kind != "sweep") r.fail("/kind", "is " + quoted_text(kind) + ": not a sweep JSON (kind \"sweep\")");
  SweepModel m;
  const ojson& version = r.member(doc, "", "schema_version");
  if (!version.is_number_integer()) r.wrong_type(version, "/schema_version", "an integer");
  m.schema_version = version.get<int>();
  if (m.schema_version != kSweepSchemaVersion)
    r.fail("/schema_version", "is " + std::to_string(m.schema_version) + "; this build reads sweep schema version " +
                                  std::to_string(kSweepSchemaVersion));
  m.complete_stated = doc.contains("complete");
  if (m.complete_stated) m.complete = r.boolean(doc, "", "complete");
  if (const std::string unit = r.string(doc, "", "unit"); unit != "ms")
    r.fail("/unit", "is " + quoted_text(unit) + ", not \"ms\"");

  m.device = device_record_from_json(r, r.member(doc, "", "device"), "/device");
  m.build = build_record_from_json(r, r.member(doc, "", "build"), "/build");
  m.run = run_record_from_json(r, r.member(doc, "", "run"), "/run");
  m.scene = scene_identity_from_json(r.object(doc, "", "scene"), what, "/scene");

  const ojson& generators = r.nonempty_array(doc, "", "generators");
  for (std::size_t i = 0; i < generators.size(); ++i) {
    if (!generators[i].is_string()) r.wrong_type(generators[i], "/generators/" + std::to_string(i), "a string");
    m.generators.push_back(generators[i].get<std::string>());
  }
  const ojson& axes = r.nonempty_array(doc, "", "axes");
  for (std::size_t i = 0; i < axes.size(); ++i) {
    m.axes.push_back(read_axis(r, axes[i], "/axes/" + std::to_string(i)));
    for (std::size_t k = 0; k + 1 < m.axes.size(); ++k)
      if (m.axes[k].name == m.axes.back().name)
        r.fail("/axes/" + std::to_string(i) + "/name", "repeats axis " + m.axes[k].name);
  }
  const ojson& budget = r.member(doc, "", "time_budget_s");
  if (!budget.is_null()) {
    m.time_budget_s = r.number(budget, "/time_budget_s");
    if (!(*m.time_budget_s > 0)) r.fail("/time_budget_s", "is not a positive time or null");
  }
  m.time_budget_rule = r.string(doc, "", "time_budget_rule");
  m.fit_method = r.string(doc, "", "fit_method");
  if (doc.contains("order")) m.order = read_order(r, doc["order"], m.planned_points());
  const ojson& points = r.nonempty_array(doc, "", "points");
  for (std::size_t i = 0; i < points.size(); ++i)
    m.points.push_back(read_point(r, points[i], "/points/" + std::to_string(i), i, m.axes));
  if (m.complete && m.points.size() < 2)
    r.fail("/points", "has 1 point, and a complete sweep has at least 2 (\"complete\": false marks one cut short)");
  if (doc.contains("beyond_device")) {
    const ojson& beyond = r.array(doc, "", "beyond_device");
    for (std::size_t i = 0; i < beyond.size(); ++i) {
      const std::string p = "/beyond_device/" + std::to_string(i);
      if (!beyond[i].is_object()) r.wrong_type(beyond[i], p, "an object");
      SweepBeyondDevice b;
      b.value_index = read_value_index(r, beyond[i], p, m.axes);
      if (beyond[i].contains("generator")) b.generator = r.string(beyond[i], p, "generator");
      if (beyond[i].contains("view")) b.view = r.string(beyond[i], p, "view");
      b.reason = r.string(beyond[i], p, "reason");
      m.beyond_device.push_back(std::move(b));
    }
  }
  const ojson& fits = r.array(doc, "", "fits");
  for (std::size_t i = 0; i < fits.size(); ++i) m.fits.push_back(read_fit(r, fits[i], "/fits/" + std::to_string(i), m));
  if (doc.contains("claims")) m.claims = read_claims(r, doc["claims"]);
  return m;
}

SweepModel read_sweep_file(const std::filesystem::path& path) {
  return read_sweep_model(read_json_file(path, "the sweep JSON"), path_text(path));
}

ojson to_json(const SweepModel& m) {
  ojson doc{{"schema_version", m.schema_version}, {"kind", "sweep"}};
  if (m.complete_stated) doc["complete"] = m.complete;
  doc["unit"] = "ms";
  doc["device"] = to_json(m.device);
  doc["build"] = to_json(m.build);
  doc["run"] = to_json(m.run);
  doc["scene"] = to_json(m.scene);
  doc["generators"] = m.generators;
  ojson axes = ojson::array();
  for (const SweepAxisModel& a : m.axes) axes.push_back(axis_json(a));
  doc["axes"] = std::move(axes);
  doc["time_budget_s"] = m.time_budget_s ? ojson(*m.time_budget_s) : ojson(nullptr);
  doc["time_budget_rule"] = m.time_budget_rule;
  doc["fit_method"] = m.fit_method;
  if (m.order) doc["order"] = ojson{{"blocks", m.order->blocks}, {"seed", m.order->seed}, {"visits", m.order->visits}};
  ojson points = ojson::array();
  for (const SweepPoint& p : m.points) points.push_back(point_json(p, m.axes));
  doc["points"] = std::move(points);
  ojson beyond = ojson::array();
  for (const SweepBeyondDevice& b : m.beyond_device) beyond.push_back(beyond_json(b, m.axes));
  doc["beyond_device"] = std::move(beyond);
  ojson fits = ojson::array();
  for (const SweepFitModel& f : m.fits) fits.push_back(fit_json(f, m.axes));
  doc["fits"] = std::move(fits);
  if (m.claims) {
    ojson claims = ojson::array();
    for (const SweepClaim& c : *m.claims) claims.push_back(claim_json(c));
    doc["claims"] = std::move(claims);
  }
  return doc;
}

std::string SweepFitModel::verdict_word() const {
  return verdict && expected ? growth_verdict_name(*verdict, expected->slope) : "";
}

std::string equivalence_text(Outcome outcome) {
  switch (outcome) {
    case Outcome::kHolds: return "equivalent";
    case Outcome::kDoesNotHold: return "not equivalent";
    case Outcome::kInconclusive: return "inconclusive";
  }
  return "inconclusive";
}

}  // namespace vsgl
