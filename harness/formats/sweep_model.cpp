#include "harness/formats/sweep_model.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "harness/core/error.hpp"
#include "harness/core/json_reader.hpp"
#include "harness/core/printable_text.hpp"
#include "harness/core/text_format.hpp"

namespace vsgl {
namespace {

using ojson = nlohmann::ordered_json;

SweepTimingStats read_stats(const OrderedJsonReader& r, const ojson& series, const std::string& p) {
  if (!series.is_object()) r.wrong_type(series, p, "an object");
  const ojson& stats = r.object(series, p, "stats");
  const std::string sp = p + "/stats";
  SweepTimingStats out;
  out.median_ms = r.time(stats, sp, "median");
  out.q1_ms = r.time(stats, sp, "q1");
  out.q3_ms = r.time(stats, sp, "q3");
  if (!(out.q1_ms <= out.median_ms && out.median_ms <= out.q3_ms))
    r.fail(sp, "has quartiles that do not enclose the median (q1 " + number_text(out.q1_ms, 6) + ", median " +
                   number_text(out.median_ms, 6) + ", q3 " + number_text(out.q3_ms, 6) + ")");
  const ojson& samples = r.nonempty_array(series, p, "samples_ms");
  for (std::size_t i = 0; i < samples.size(); ++i)
    out.samples_ms.push_back(r.time(samples[i], p + "/samples_ms/" + std::to_string(i)));
  return out;
}

SweepCase read_case(const OrderedJsonReader& r, const ojson& c, const std::string& p) {
  if (!c.is_object()) r.wrong_type(c, p, "an object");
  SweepCase out;
  out.generator = r.string(c, p, "generator");
  out.view = r.string(c, p, "view");
  if (out.view != "camera_view" && out.view != "light_view")
    r.fail(p + "/view", "is " + quoted_text(out.view) + ", not camera_view or light_view");
  const ojson& phases = r.nonempty_array(c, p, "phases");
  for (std::size_t i = 0; i < phases.size(); ++i) {
    const std::string pp = p + "/phases/" + std::to_string(i);
    if (!phases[i].is_object()) r.wrong_type(phases[i], pp, "an object");
    out.phases.push_back(SweepPhaseTiming{r.string(phases[i], pp, "name"), read_stats(r, phases[i], pp)});
  }
  out.total = read_stats(r, r.object(c, p, "total"), p + "/total");
  return out;
}

SweepAxisModel read_axis(const OrderedJsonReader& r, const ojson& a, const std::string& p) {
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
    out.values.push_back(SweepAxisValue{r.string(v, vp, "text"),
                                        r.non_negative(r.member(v, vp, "value"), vp + "/value"),
                                        r.non_negative(r.member(v, vp, "growth_x"), vp + "/growth_x")});
    for (std::size_t k = 0; k + 1 < out.values.size(); ++k)
      if (out.values[k].text == out.values.back().text)
        r.fail(vp + "/text", "repeats value " + quoted_text(out.values[k].text));
  }
  return out;
}

// A point's "values": each axis's value as text, as an index into that axis's values.
std::vector<std::size_t> read_value_index(const OrderedJsonReader& r, const ojson& pj, const std::string& p,
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

SweepPoint read_point(const OrderedJsonReader& r, const ojson& pj, const std::string& p, std::size_t position,
                      const std::vector<SweepAxisModel>& axes) {
  if (!pj.is_object()) r.wrong_type(pj, p, "an object");
  SweepPoint out;
  out.index = static_cast<std::size_t>(r.uint64(pj, p, "index"));
  if (out.index != position)
    r.fail(p + "/index", "is " + std::to_string(out.index) + ", not its position " + std::to_string(position));
  out.value_index = read_value_index(r, pj, p, axes);
  const ojson& cases = r.nonempty_array(pj, p, "cases");
  for (std::size_t i = 0; i < cases.size(); ++i)
    out.cases.push_back(read_case(r, cases[i], p + "/cases/" + std::to_string(i)));
  return out;
}

SweepFitModel read_fit(const OrderedJsonReader& r, const ojson& f, const std::string& p, const SweepModel& m) {
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
    const auto i = static_cast<std::size_t>(r.uint64(points[k], pp));
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
    out.growth = SweepGrowth{r.number(growth, gp, "slope"), r.number(growth, gp, "low"), r.number(growth, gp, "high"),
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
  if (!verdict.is_null()) {
    out.verdict = r.string(f, p, "verdict");
    if (*out.verdict != "consistent" && *out.verdict != "faster" && *out.verdict != "slower")
      r.fail(p + "/verdict", "is " + quoted_text(*out.verdict) + ", not consistent, faster, slower or null");
  }
  out.flagged = r.boolean(f, p, "flagged");
  out.judgement = r.optional_string(f, p, "judgement").value_or("");
  return out;
}

std::vector<SweepClaim> read_claims(const OrderedJsonReader& r, const ojson& a) {
  if (!a.is_array()) r.wrong_type(a, "/claims", "an array");
  std::vector<SweepClaim> out;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::string p = "/claims/" + std::to_string(i);
    const ojson& c = a[i];
    if (!c.is_object()) r.wrong_type(c, p, "an object");
    SweepClaim claim;
    claim.id = r.string(c, p, "id");
    claim.text = r.string(c, p, "text");
    claim.criterion = r.string(c, p, "criterion");
    const ojson& holds = r.member(c, p, "holds");
    if (!holds.is_null()) claim.holds = r.boolean(c, p, "holds");
    claim.note = r.string(c, p, "note");
    claim.informative = r.boolean(c, p, "informative");
    if (c.contains("slice")) claim.slice = r.string_map(c["slice"], p + "/slice");
    claim.fields = c;
    out.push_back(std::move(claim));
  }
  return out;
}

}  // namespace

const SweepTimingStats* SweepCase::find(const std::string& phase) const {
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
  const OrderedJsonReader r(what, JsonPathStyle::kPointer);
  if (!doc.is_object()) r.fail("", "is not a JSON object");
  // The kind first: a table or quality JSON is told apart from a damaged sweep.
  if (!doc.contains("kind")) r.fail("/kind", "missing field: not a sweep JSON (kind \"sweep\")");
  const std::string kind = r.string(doc, "", "kind");
  if (kind != "sweep") r.fail("/kind", "is " + quoted_text(kind) + ": not a sweep JSON (kind \"sweep\")");
  SweepModel m;
  const ojson& version = r.member(doc, "", "schema_version");
  if (!version.is_number_integer()) r.wrong_type(version, "/schema_version", "an integer");
  m.schema_version = version.get<int>();
  if (m.schema_version != kReadableSweepSchemaVersion)
    r.fail("/schema_version", "is " + std::to_string(m.schema_version) + "; this build reads sweep schema version " +
                                  std::to_string(kReadableSweepSchemaVersion));
  if (doc.contains("complete")) m.complete = r.boolean(doc, "", "complete");
  if (const std::string unit = r.string(doc, "", "unit"); unit != "ms")
    r.fail("/unit", "is " + quoted_text(unit) + ", not \"ms\"");

  m.device = r.object(doc, "", "device");
  m.device_name = r.string(m.device, "/device", "name");
  m.build = r.object(doc, "", "build");
  m.git_commit = r.optional_string(m.build, "/build", "git_commit");
  if (m.build.contains("git_dirty")) m.git_dirty = r.boolean(m.build, "/build", "git_dirty");
  m.run = r.object(doc, "", "run");
  m.started_utc = r.string(m.run, "/run", "started_utc");
  m.quick = r.boolean(m.run, "/run", "quick");
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
  return read_sweep_model(read_json_file(path, "the sweep JSON"), path.string());
}

}  // namespace vsgl
