#include "harness/formats/table_model.hpp"

#include <cstdint>
#include <stdexcept>

#include "harness/core/error.hpp"
#include "harness/core/json_reader.hpp"
#include "harness/core/printable_text.hpp"

namespace vsgl {
namespace {

using ojson = nlohmann::ordered_json;

ojson number_or_null(const std::optional<double>& v) { return v ? ojson(*v) : ojson(nullptr); }

// ---- writing ----

ojson generator_json(const GeneratorTiming& g) {
  ojson views = ojson::object();
  for (const auto& [view, v] : g.views) {
    ojson phases = ojson::object();
    for (const PhaseTiming& p : v.phases) phases[p.phase] = to_json(p.stats, StatisticsLayout::kTable);
    ojson vj{{"phases", phases}, {"total", to_json(v.total, StatisticsLayout::kTable)}};
    if (v.dispatch_calls) vj["dispatch_calls"] = *v.dispatch_calls;
    views[view] = vj;
  }
  ojson o = ojson::object();
  if (g.label) o["label"] = *g.label;
  if (g.in_paper) o["in_paper"] = *g.in_paper;
  o["views"] = views;
  o["total"] = to_json(g.total, StatisticsLayout::kTable);
  return o;
}

ojson measured_paper_json(const MeasuredVsPaper& m) { return ojson{{"measured", m.measured}, {"paper", number_or_null(m.paper)}}; }

ojson keyed_json(const KeyedRatios& rows) {
  ojson o = ojson::object();
  for (const auto& [k, v] : rows) o[k] = measured_paper_json(v);
  return o;
}

ojson paired_json(const PairedDifference& p) {
  return ojson{{"rounds", p.rounds},
               {"median_us", p.median_us},
               {"hodges_lehmann_us", p.hodges_lehmann_us},
               {"ci_low_us", p.ci_low_us},
               {"ci_high_us", p.ci_high_us},
               {"confidence", p.confidence},
               {"reaches_nominal", p.reaches_nominal},
               {"critical_value", p.critical_value},
               {"paper_us", number_or_null(p.paper_us)}};
}

ojson ratios_json(const TableRatios& r) {
  ojson o = ojson::object();
  if (r.modified_minus_tok15_us) o["modified_minus_tok15_us"] = keyed_json(*r.modified_minus_tok15_us);
  if (r.paired_modified_minus_tok15) {
    const PairedOverhead& p = *r.paired_modified_minus_tok15;
    ojson pj{{"estimator", p.estimator}, {"interval", p.interval}, {"nominal_confidence", p.nominal_confidence}};
    for (const auto& [view, v] : p.views)
      pj[view] = ojson{{"total", paired_json(v.total)}, {"filtered_sampling", paired_json(v.filtered_sampling)}};
    pj["total"] = paired_json(p.total);
    o["paired_modified_minus_tok15"] = pj;
  }
  if (r.kmeans_over_modified) o["kmeans_over_modified"] = keyed_json(*r.kmeans_over_modified);
  if (r.table1_to_table2) o["table1_to_table2"] = keyed_json(*r.table1_to_table2);
  return o;
}

ojson pass_json(const PassTraffic& p) {
  ojson o{{"min_bytes_read", p.min_bytes_read},
          {"min_bytes_written", p.min_bytes_written},
          {"min_bytes", p.min_bytes},
          {"median_ms", p.median_ms},
          {"achieved_bytes_per_s", p.achieved_bytes_per_s},
          {"fraction_of_copy", p.fraction_of_copy}};
  if (p.level_by_level_bytes) o["level_by_level_bytes"] = *p.level_by_level_bytes;
  if (p.level_by_level_fraction_of_copy) o["level_by_level_fraction_of_copy"] = *p.level_by_level_fraction_of_copy;
  return o;
}

ojson bandwidth_json(const TableBandwidth& b) {
  const CopyBandwidthResult& c = b.copy;
  ojson copy{{"method", c.method},
             {"requested_bytes", c.requested_bytes},
             {"buffer_bytes", c.buffer_bytes},
             {"reduced_because", c.reduced_because},
             {"bytes_per_copy", c.bytes_per_copy},
             {"warmup_copies", c.warmup_copies},
             {"samples_ms", c.samples_ms},
             {"median_ms", c.median_ms},
             {"bytes_per_s", c.bytes_per_s}};
  ojson passes = ojson::object();
  for (const GeneratorTraffic& g : b.passes) {
    ojson views = ojson::object();
    for (const auto& [view, pass_map] : g.views) {
      ojson pj = ojson::object();
      for (const auto& [pass, traffic] : pass_map) pj[pass] = pass_json(traffic);
      views[view] = pj;
    }
    passes[g.generator] = views;
  }
  return ojson{{"copy", copy}, {"model", b.model}, {"passes", passes}};
}

ojson table3_json(const std::vector<Table3Row>& rows) {
  ojson out = ojson::object();
  for (const Table3Row& r : rows) {
    ojson files = ojson::array();
    for (const auto& f : r.files) {
      ojson fj{{"path", f.path}, {"lines", f.lines}};
      if (f.kind) fj["kind"] = *f.kind;
      files.push_back(fj);
    }
    ojson dispatch{{"camera_view", r.dispatch_camera_view},
                   {"light_view", r.dispatch_light_view},
                   {"paper", number_or_null(r.dispatch_paper)}};
    if (!r.dispatch_iterations.empty()) {
      ojson it = ojson::object();
      for (const auto& [view, d] : r.dispatch_iterations)
        it[view] = ojson{{"iterations", d.iterations}, {"per_iteration", d.per_iteration}, {"outside", d.outside}};
      dispatch["iterations"] = it;
    }
    ojson lines{{"measured", r.lines_of_code}, {"paper", number_or_null(r.lines_of_code_paper)}};
    if (r.shader_lines) lines["shader_lines"] = *r.shader_lines;
    if (r.host_lines) lines["host_lines"] = *r.host_lines;
    lines["files"] = files;
    out[r.generator] =
        ojson{{"shaders", measured_paper_json(r.shaders)}, {"dispatch_calls", dispatch}, {"lines_of_code", lines}};
  }
  return out;
}

ojson table3_counting_json(const Table3Counting& c) {
  ojson out{{"rule", c.rule}, {"difference_rule", c.difference_rule}};
  if (c.difference) {
    const Table3Difference& d = *c.difference;
    out["difference"] = ojson{{"from", d.from},
                              {"to", d.to},
                              {"removed", d.removed},
                              {"added", d.added},
                              {"differing", d.differing},
                              {"net", d.net},
                              {"paper", number_or_null(d.paper)}};
  }
  return out;
}

}  // namespace

namespace {

// ---- reading ----

TimingStatistics read_stats(const JsonReader& r, const ojson& s, const std::string& p) {
  return timing_statistics_from_json(r, s, p, StatisticsLayout::kTable);
}

GeneratorTiming read_generator(const JsonReader& r, const std::string& name, const ojson& gj, const std::string& gp) {
  if (!gj.is_object()) r.wrong_type(gj, gp, "an object");
  GeneratorTiming g;
  g.name = name;
  g.label = r.optional_string(gj, gp, "label");
  if (gj.contains("in_paper")) g.in_paper = r.boolean(gj, gp, "in_paper");
  const ojson& views = r.object(gj, gp, "views");
  for (const char* view : {"camera_view", "light_view"}) {
    const std::string vp = gp + "/views/" + view;
    const ojson& vj = r.object(views, gp + "/views", view);
    ViewTiming v;
    const ojson& phases = r.object(vj, vp, "phases");
    if (phases.empty()) r.fail(vp + "/phases", "holds no phase");
    for (const auto& [phase, stats] : phases.items()) {
      if (!stats.is_object()) r.wrong_type(stats, vp + "/phases/" + phase, "an object");
      v.phases.push_back({phase, read_stats(r, stats, vp + "/phases/" + phase)});
    }
    v.total = read_stats(r, r.object(vj, vp, "total"), vp + "/total");
    if (vj.contains("dispatch_calls")) v.dispatch_calls = r.uint32(vj, vp, "dispatch_calls");
    g.views[view] = std::move(v);
  }
  g.total = read_stats(r, r.object(gj, gp, "total"), gp + "/total");
  return g;
}

MeasuredVsPaper read_measured_paper(const JsonReader& r, const ojson& o, const std::string& p) {
  if (!o.is_object()) r.wrong_type(o, p, "an object");
  return {r.number(o, p, "measured"), r.optional_number(o, p, "paper")};
}

KeyedRatios read_keyed(const JsonReader& r, const ojson& o, const std::string& p) {
  KeyedRatios rows;
  for (const auto& [k, v] : o.items()) rows.emplace_back(k, read_measured_paper(r, v, p + "/" + k));
  return rows;
}

PairedDifference read_paired(const JsonReader& r, const ojson& o, const std::string& p) {
  PairedDifference d;
  d.rounds = r.uint64(o, p, "rounds");
  d.median_us = r.number(o, p, "median_us");
  d.hodges_lehmann_us = r.number(o, p, "hodges_lehmann_us");
  d.ci_low_us = r.number(o, p, "ci_low_us");
  d.ci_high_us = r.number(o, p, "ci_high_us");
  d.confidence = r.number(o, p, "confidence");
  d.reaches_nominal = r.boolean(o, p, "reaches_nominal");
  d.critical_value = r.string(o, p, "critical_value");
  d.paper_us = r.optional_number(o, p, "paper_us");
  return d;
}

TableRatios read_ratios(const JsonReader& r, const ojson& o, const std::string& p) {
  TableRatios out;
  if (const ojson* m = r.optional_object(o, p, "modified_minus_tok15_us")) out.modified_minus_tok15_us = read_keyed(r, *m, p + "/modified_minus_tok15_us");
  if (const ojson* po = r.optional_object(o, p, "paired_modified_minus_tok15")) {
    const std::string pp = p + "/paired_modified_minus_tok15";
    PairedOverhead paired;
    paired.estimator = r.string(*po, pp, "estimator");
    paired.interval = r.string(*po, pp, "interval");
    paired.nominal_confidence = r.number(*po, pp, "nominal_confidence");
    for (const char* view : {"camera_view", "light_view"}) {
      const ojson& v = r.object(*po, pp, view);
      const std::string vp = pp + "/" + view;
      paired.views[view] = {read_paired(r, r.object(v, vp, "total"), vp + "/total"),
                            read_paired(r, r.object(v, vp, "filtered_sampling"), vp + "/filtered_sampling")};
    }
    paired.total = read_paired(r, r.object(*po, pp, "total"), pp + "/total");
    out.paired_modified_minus_tok15 = paired;
  }
  if (const ojson* k = r.optional_object(o, p, "kmeans_over_modified")) out.kmeans_over_modified = read_keyed(r, *k, p + "/kmeans_over_modified");
  if (const ojson* t = r.optional_object(o, p, "table1_to_table2")) out.table1_to_table2 = read_keyed(r, *t, p + "/table1_to_table2");
  return out;
}

PassTraffic read_pass(const JsonReader& r, const ojson& o, const std::string& p) {
  if (!o.is_object()) r.wrong_type(o, p, "an object");
  PassTraffic t;
  t.min_bytes_read = r.uint64(o, p, "min_bytes_read");
  t.min_bytes_written = r.uint64(o, p, "min_bytes_written");
  t.min_bytes = r.uint64(o, p, "min_bytes");
  t.median_ms = r.number(o, p, "median_ms");
  t.achieved_bytes_per_s = r.number(o, p, "achieved_bytes_per_s");
  t.fraction_of_copy = r.number(o, p, "fraction_of_copy");
  t.level_by_level_bytes = r.optional_uint64(o, p, "level_by_level_bytes");
  t.level_by_level_fraction_of_copy = r.optional_number(o, p, "level_by_level_fraction_of_copy");
  return t;
}

TableBandwidth read_bandwidth(const JsonReader& r, const ojson& o, const std::string& p) {
  TableBandwidth b;
  const ojson& c = r.object(o, p, "copy");
  const std::string cp = p + "/copy";
  b.copy.method = r.string(c, cp, "method");
  b.copy.requested_bytes = r.uint64(c, cp, "requested_bytes");
  b.copy.buffer_bytes = r.uint64(c, cp, "buffer_bytes");
  b.copy.reduced_because = r.string(c, cp, "reduced_because");
  b.copy.bytes_per_copy = r.uint64(c, cp, "bytes_per_copy");
  b.copy.warmup_copies = r.uint64(c, cp, "warmup_copies");
  b.copy.samples_ms = r.times(c, cp, "samples_ms");
  b.copy.median_ms = r.time(c, cp, "median_ms");
  b.copy.bytes_per_s = r.number(c, cp, "bytes_per_s");
  b.model = r.string(o, p, "model");
  for (const auto& [g, views] : r.object(o, p, "passes").items()) {
    const std::string gp = p + "/passes/" + g;
    if (!views.is_object()) r.wrong_type(views, gp, "an object");
    GeneratorTraffic traffic{g, {}};
    for (const auto& [view, passes] : views.items()) {
      if (!passes.is_object()) r.wrong_type(passes, gp + "/" + view, "an object");
      for (const auto& [pass, v] : passes.items()) traffic.views[view][pass] = read_pass(r, v, gp + "/" + view + "/" + pass);
    }
    b.passes.push_back(std::move(traffic));
  }
  return b;
}

std::vector<Table3Row> read_table3(const JsonReader& r, const ojson& o, const std::string& p) {
  std::vector<Table3Row> rows;
  for (const auto& [g, v] : o.items()) {
    const std::string gp = p + "/" + g;
    if (!v.is_object()) r.wrong_type(v, gp, "an object");
    Table3Row row;
    row.generator = g;
    row.shaders = read_measured_paper(r, r.object(v, gp, "shaders"), gp + "/shaders");
    const ojson& d = r.object(v, gp, "dispatch_calls");
    row.dispatch_camera_view = r.uint32(d, gp + "/dispatch_calls", "camera_view");
    row.dispatch_light_view = r.uint32(d, gp + "/dispatch_calls", "light_view");
    row.dispatch_paper = r.optional_number(d, gp + "/dispatch_calls", "paper");
    if (const ojson* it = r.optional_object(d, gp + "/dispatch_calls", "iterations"))
      for (const auto& [view, vj] : it->items()) {
        const std::string ip = gp + "/dispatch_calls/iterations/" + view;
        if (!vj.is_object()) r.wrong_type(vj, ip, "an object");
        row.dispatch_iterations[view] = {r.uint32(vj, ip, "iterations"), r.uint32(vj, ip, "per_iteration"),
                                         r.uint32(vj, ip, "outside")};
      }
    const ojson& l = r.object(v, gp, "lines_of_code");
    const std::string lp = gp + "/lines_of_code";
    row.lines_of_code = r.uint64(l, lp, "measured");
    row.lines_of_code_paper = r.optional_number(l, lp, "paper");
    row.shader_lines = r.optional_uint64(l, lp, "shader_lines");
    row.host_lines = r.optional_uint64(l, lp, "host_lines");
    const ojson& files = r.member(l, lp, "files");
    if (!files.is_array()) r.wrong_type(files, lp + "/files", "an array");
    for (std::size_t i = 0; i < files.size(); ++i) {
      const std::string fp = lp + "/files/" + std::to_string(i);
      if (!files[i].is_object()) r.wrong_type(files[i], fp, "an object");
      std::optional<std::string> kind;
      kind = r.optional_string(files[i], fp, "kind");
      row.files.push_back({r.string(files[i], fp, "path"), r.uint64(files[i], fp, "lines"), kind});
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

std::vector<Claim> read_claims(const JsonReader& r, const ojson& a) {
  if (!a.is_array()) r.wrong_type(a, "/claims", "an array");
  std::vector<Claim> out;
  for (std::size_t i = 0; i < a.size(); ++i)
    out.push_back(claim_from_json(r, a[i], "/claims/" + std::to_string(i), ClaimLayout::kTable));
  return out;
}

CaptureSummary read_capture(const JsonReader& r, const ojson& c) {
  CaptureSummary out;
  out.fields = c;
  if (const ojson* h = r.optional_object(c, "/capture", "hashes")) out.hashes = *h;
  out.scene = r.optional_string(c, "/capture", "scene");
  if (const ojson* s = r.optional_object(c, "/capture", "source")) {
    const std::string sp = "/capture/source";
    out.source = CaptureSummary::Source{r.string(*s, sp, "format"), r.string(*s, sp, "file"), r.string(*s, sp, "content_hash"),
                                        r.uint64(*s, sp, "triangles")};
  }
  return out;
}

// A scene known by name only (schema 1-2), its kind inferred from what else the file says: a
// capture of a model file is the user's, a paper table's procedural scene is its stand-in.
SceneIdentity name_only_scene(const std::string& name, const TableModel& m) {
  SceneIdentity s;
  s.name = name;
  s.name_only = true;
  if (m.capture.source) {
    s.kind = SceneKind::kUser;
    s.model_file = m.capture.source->file;
    s.content_hash = m.capture.source->content_hash;
    s.triangles = m.capture.source->triangles;
  } else {
    s.kind = m.table ? SceneKind::kStandIn : SceneKind::kProcedural;
  }
  return s;
}

// Schema 3's object; schema 2's plain name.
std::optional<SceneIdentity> read_scene(const JsonReader& r, const ojson& doc, const TableModel& m) {
  const auto it = doc.find("scene");
  if (it == doc.end()) return std::nullopt;
  if (it->is_string()) {
    if (m.schema_version >= 3) r.fail("/scene", "is a plain name; schema 3 gives an object {name, kind, ...}");
    return name_only_scene(it->get<std::string>(), m);
  }
  if (!it->is_object()) r.wrong_type(*it, "/scene", "an object (schema 3) or a scene name (schema 1-2)");
  return scene_identity_from_json(*it, r.where(), "/scene");
}

}  // namespace

std::optional<SceneIdentity> TableModel::timed_scene() const {
  if (scene) return scene;
  if (capture.scene) return name_only_scene(*capture.scene, *this);  // schema 1: only /capture/scene
  return std::nullopt;
}

const GeneratorTiming* TableModel::find_generator(const std::string& name) const {
  for (const GeneratorTiming& g : generators)
    if (g.name == name) return &g;
  return nullptr;
}

int TableModel::vsgl_count(const std::string& view) const {
  const auto views = config.find("views");
  if (views == config.end() || !views->is_object() || !views->contains(view) || !(*views)[view].is_object() ||
      !(*views)[view].contains("vsgl_count") || !(*views)[view]["vsgl_count"].is_number_integer())
    throw InputError("the table has no integer /config/views/" + view + "/vsgl_count");
  return (*views)[view]["vsgl_count"].get<int>();
}

CaptureSummary capture_summary_from_json(const nlohmann::ordered_json& capture, const std::string& what) {
  const JsonReader r(what, JsonPathStyle::kPointer);
  if (!capture.is_object()) r.wrong_type(capture, "/capture", "an object");
  return read_capture(r, capture);
}

nlohmann::ordered_json to_json(const TableModel& m) {
  ojson doc;
  doc["schema_version"] = m.schema_version;
  doc["table"] = m.table ? ojson(*m.table) : ojson(nullptr);
  if (m.title) doc["title"] = *m.title;
  if (m.scene) doc["scene"] = to_json(*m.scene);
  if (m.unit) doc["unit"] = *m.unit;
  if (m.device) doc["device"] = to_json(*m.device);
  if (m.driver) doc["driver"] = ojson{{"name", m.driver->name}, {"info", m.driver->info}, {"version", m.driver->version}};
  if (m.api_version) doc["api_version"] = *m.api_version;
  if (m.timestamp_period_ns) doc["timestamp_period_ns"] = *m.timestamp_period_ns;
  if (m.timestamp_valid_bits) doc["timestamp_valid_bits"] = *m.timestamp_valid_bits;
  if (m.build) doc["build"] = to_json(*m.build);
  if (m.run) doc["run"] = to_json(*m.run);
  doc["config"] = m.config;
  doc["capture"] = m.capture.fields;
  if (m.paper) doc["paper"] = ojson{{"source", m.paper->source}, {"file", m.paper->file}, {"gpu", m.paper->gpu}};
  if (m.timing)
    doc["timing"] = ojson{{"repetitions", m.timing->repetitions},
                          {"timed_seconds", m.timing->timed_seconds},
                          {"stop_reason", m.timing->stop_reason},
                          {"worst_relative_iqr", m.timing->worst_relative_iqr}};
  ojson gens = ojson::object();
  for (const GeneratorTiming& g : m.generators) {
    for (const char* view : {"camera_view", "light_view"})
      if (!g.views.contains(view)) throw std::invalid_argument("generator " + g.name + " has no " + view + " timing");
    gens[g.name] = generator_json(g);
  }
  doc["generators"] = gens;
  if (m.ratios) doc["ratios"] = ratios_json(*m.ratios);
  if (m.bandwidth) doc["bandwidth"] = bandwidth_json(*m.bandwidth);
  if (m.table3) doc["table3"] = table3_json(*m.table3);
  if (m.table3_counting) doc["table3_counting"] = table3_counting_json(*m.table3_counting);
  if (m.claims) {
    ojson claims = ojson::array();
    for (const Claim& c : *m.claims) claims.push_back(to_json(c, ClaimLayout::kTable));
    doc["claims"] = claims;
  }
  return doc;
}

TableModel table_model_from_json(const nlohmann::ordered_json& doc, const std::string& what) {
  const JsonReader r(what, JsonPathStyle::kPointer);
  if (!doc.is_object()) r.fail("", "is not a JSON object");
  TableModel m;
  const ojson& version = r.member(doc, "", "schema_version");
  if (!version.is_number_integer()) r.wrong_type(version, "/schema_version", "an integer");
  m.schema_version = version.get<int>();
  const ojson& table = r.member(doc, "", "table");
  if (!table.is_null()) {
    if (!table.is_number_integer()) r.fail("/table", "is " + printable_text(table.dump()) + ", not a table number or null");
    m.table = table.get<int>();
  }
  m.title = r.optional_string(doc, "", "title");
  m.unit = r.optional_string(doc, "", "unit");

  if (const ojson* device = r.optional_object(doc, "", "device"))
    m.device = device_record_from_json(r, *device, "/device");
  if (const ojson* d = r.optional_object(doc, "", "driver"))
    m.driver = DriverSummary{r.string(*d, "/driver", "name"), r.string(*d, "/driver", "info"), r.string(*d, "/driver", "version")};
  m.api_version = r.optional_string(doc, "", "api_version");
  m.timestamp_period_ns = r.optional_number(doc, "", "timestamp_period_ns");
  m.timestamp_valid_bits = r.optional_uint64(doc, "", "timestamp_valid_bits");

  if (const ojson* build = r.optional_object(doc, "", "build")) m.build = build_record_from_json(r, *build, "/build");
  if (const ojson* run = r.optional_object(doc, "", "run")) m.run = run_record_from_json(r, *run, "/run");
  if (const ojson* config = r.optional_object(doc, "", "config")) m.config = *config;
  else m.config = nullptr;
  if (const ojson* capture = r.optional_object(doc, "", "capture")) m.capture = read_capture(r, *capture);
  else m.capture.fields = nullptr;
  m.scene = read_scene(r, doc, m);
  if (const ojson* p = r.optional_object(doc, "", "paper"))
    m.paper = PaperSource{r.string(*p, "/paper", "source"), r.string(*p, "/paper", "file"), r.string(*p, "/paper", "gpu")};
  if (const ojson* t = r.optional_object(doc, "", "timing"))
    m.timing = TimingStop{r.uint64(*t, "/timing", "repetitions"), r.number(*t, "/timing", "timed_seconds"),
                          r.string(*t, "/timing", "stop_reason"), r.number(*t, "/timing", "worst_relative_iqr")};

  const ojson& generators = r.object(doc, "", "generators");
  if (generators.empty()) r.fail("/generators", "holds no generator");
  for (const auto& [g, gj] : generators.items()) m.generators.push_back(read_generator(r, g, gj, "/generators/" + g));

  if (const ojson* ratios = r.optional_object(doc, "", "ratios")) m.ratios = read_ratios(r, *ratios, "/ratios");
  if (const ojson* b = r.optional_object(doc, "", "bandwidth")) m.bandwidth = read_bandwidth(r, *b, "/bandwidth");
  if (const ojson* t3 = r.optional_object(doc, "", "table3")) m.table3 = read_table3(r, *t3, "/table3");
  if (const ojson* c = r.optional_object(doc, "", "table3_counting")) {
    Table3Counting counting{
        r.string(*c, "/table3_counting", "rule"), r.string(*c, "/table3_counting", "difference_rule"), {}};
    if (const ojson* d = r.optional_object(*c, "/table3_counting", "difference")) {
      const std::string dp = "/table3_counting/difference";
      const ojson& net = r.member(*d, dp, "net");
      if (!net.is_number_integer()) r.wrong_type(net, dp + "/net", "an integer");
      counting.difference = Table3Difference{r.string(*d, dp, "from"),          r.string(*d, dp, "to"),
                                             r.uint64(*d, dp, "removed"),       r.uint64(*d, dp, "added"),
                                             r.uint64(*d, dp, "differing"),     net.get<int64_t>(),
                                             r.optional_number(*d, dp, "paper")};
    }
    m.table3_counting = std::move(counting);
  }
  if (doc.contains("claims")) m.claims = read_claims(r, doc["claims"]);
  return m;
}

}  // namespace vsgl
