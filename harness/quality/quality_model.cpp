#include "harness/quality/quality_model.hpp"

#include "harness/core/json_reader.hpp"

namespace vsgl {
namespace {

using nlohmann::json;

class Reader : public JsonReader {
 public:
  explicit Reader(std::string what) : JsonReader(std::move(what), JsonPathStyle::kPointer) {}
  double num(const json& o, const std::string& p, const char* key) const { return number(o, p, key); }
  const json& obj(const json& o, const std::string& p, const std::string& key) const { return object(o, p, key); }
  const json& any(const json& o, const std::string& p, const std::string& key) const { return member(o, p, key); }
  std::optional<double> optional_num(const json& o, const std::string& p, const char* key) const {
    if (!o.contains(key)) return std::nullopt;
    return number(o, p, key);
  }
};

CoverageCountsSummary read_counts(const Reader& r, const json& o, const std::string& p) {
  return {r.num(o, p, "gap"), r.num(o, p, "surplus"), r.num(o, p, "count_error"), r.num(o, p, "mean_count"),
          r.optional_num(o, p, "overlap")};
}

CoverageSummary read_coverage(const Reader& r, const json& c, const std::string& p) {
  CoverageSummary s;
  s.gap = r.num(c, p, "gap");
  s.overlap = r.num(c, p, "overlap");
  s.gap_plus_overlap = r.num(c, p, "gap_plus_overlap");
  const json& m = r.obj(c, p, "mass_over_target");
  const std::string mp = p + "/mass_over_target";
  s.mass_over_target = {r.num(m, mp, "mean"), r.num(m, mp, "stdev"), r.num(m, mp, "min"), r.num(m, mp, "max"), r.num(m, mp, "p99")};
  s.box = read_counts(r, r.obj(c, p, "box"), p + "/box");
  s.eq3 = read_counts(r, r.obj(c, p, "eq3"), p + "/eq3");
  const json& floor = r.obj(c, p, "lattice_floor");
  s.floor_box = read_counts(r, r.obj(floor, p + "/lattice_floor", "box"), p + "/lattice_floor/box");
  s.floor_eq3 = read_counts(r, r.obj(floor, p + "/lattice_floor", "eq3"), p + "/lattice_floor/eq3");
  const json& excess = r.obj(c, p, "excess");
  s.excess_box = read_counts(r, r.obj(excess, p + "/excess", "box"), p + "/excess/box");
  s.excess_eq3 = read_counts(r, r.obj(excess, p + "/excess", "eq3"), p + "/excess/eq3");
  return s;
}

PowerSummary read_power(const Reader& r, const json& o, const std::string& p) {
  return {r.num(o, p, "max_over_mean"), r.num(o, p, "p99_over_mean"), r.num(o, p, "power_ratio")};
}

ImageErrorSummary read_error(const Reader& r, const json& o, const std::string& p) {
  return {r.num(o, p, "relative_rmse"), r.num(o, p, "p99_pixel_error")};
}

ViewQuality read_view(const Reader& r, const json& v, const std::string& p) {
  ViewQuality out;
  out.vsgls = r.any(v, p, "vsgls");
  out.total_flux = r.num(v, p, "total_flux");
  if (v.contains("pdf_frequency")) {
    const json& f = r.obj(v, p, "pdf_frequency");
    const std::string fp = p + "/pdf_frequency";
    PdfFrequencySummary s;
    s.relative_variance = r.num(f, fp, "relative_variance");
    const json& shares = r.any(f, fp, "fine_share");
    if (!shares.is_array()) r.wrong_type(shares, fp + "/fine_share", "an array");
    for (std::size_t k = 0; k < shares.size(); ++k) s.fine_share.push_back(r.number(shares[k], r.element(fp + "/fine_share", k)));
    s.share_below_kernel = r.num(f, fp, "share_below_kernel");
    s.share_below_kernel_side_texels = r.num(f, fp, "share_below_kernel_side_texels");
    s.mean_kernel_side_texels = r.num(f, fp, "mean_kernel_side_texels");
    out.pdf_frequency = s;
  }
  for (const auto& [name, g] : r.obj(v, p, "generators").items()) {
    const std::string gp = p + "/generators/" + name;
    if (!g.is_object()) r.wrong_type(g, gp, "an object");
    GeneratorQuality q;
    if (g.contains("coverage")) q.coverage = read_coverage(r, r.obj(g, gp, "coverage"), gp + "/coverage");
    q.power = read_power(r, r.obj(g, gp, "power"), gp + "/power");
    out.generators[name] = q;
  }
  return out;
}

}  // namespace

QualityModel quality_model_from_json(const json& doc, const std::string& what) {
  const Reader r(what);
  if (!doc.is_object()) r.fail("", "is not a JSON object");
  QualityModel m;
  m.schema_version = r.any(doc, "", "schema_version");
  m.scene = r.string(doc, "", "scene");
  const json& capture = r.obj(doc, "", "capture");
  m.capture_path = r.string(capture, "/capture", "path");
  m.gbuffer_size = r.array(capture, "/capture", "gbuffer", 2);
  m.rsm_size = r.array(capture, "/capture", "rsm", 2);
  m.device_name = r.string(r.obj(doc, "", "device"), "/device", "name");
  const json& build = r.obj(doc, "", "build");
  m.version = r.string(build, "/build", "vsgl_bench_version");
  m.git_commit = r.string(build, "/build", "git_commit");
  m.git_dirty = r.boolean(build, "/build", "git_dirty");
  const json& config = r.obj(doc, "", "config");
  const json& gens = r.any(config, "/config", "generators");
  if (!gens.is_array()) r.wrong_type(gens, "/config/generators", "an array");
  for (std::size_t i = 0; i < gens.size(); ++i) {
    if (!gens[i].is_string()) r.wrong_type(gens[i], r.element("/config/generators", i), "a string");
    m.generators.push_back(gens[i].get<std::string>());
  }
  m.light_vsgls = r.any(config, "/config", "light_vsgls");
  m.camera_vsgls = r.any(config, "/config", "camera_vsgls");
  m.K = r.any(config, "/config", "K");
  m.frames = r.any(config, "/config", "frames");

  const json& views = r.obj(doc, "", "views");
  for (const char* view : {"camera_view", "light_view"}) m.views[view] = read_view(r, r.obj(views, "/views", view), std::string("/views/") + view);

  const json& ref = r.obj(doc, "", "reference");
  m.reference_power_ratio = r.num(ref, "/reference", "power_ratio");
  m.reference_method = r.string(ref, "/reference", "method");
  m.reference_vpls = r.any(ref, "/reference", "vpls");
  m.reference_rsm_side = r.any(ref, "/reference", "reference_rsm_side");
  m.reference_rsm_stride = r.any(ref, "/reference", "rsm_stride");
  m.reference_image = r.array(ref, "/reference", "image", 2);
  const json& errors = r.obj(doc, "", "reference_error");
  const json& fs = r.obj(doc, "", "flicker_static");
  m.flicker_image = r.array(fs, "/flicker_static", "image", 2);
  const json& fsg = r.obj(fs, "/flicker_static", "generators");
  for (const std::string& g : m.generators) {
    m.reference_error[g] = read_error(r, r.obj(errors, "/reference_error", g), "/reference_error/" + g);
    const std::string p = "/flicker_static/generators/" + g;
    const json& f = r.obj(fsg, "/flicker_static/generators", g);
    m.flicker_static[g] = {r.num(f, p, "weighted_cv"), r.num(f, p, "power_stdev"), r.num(f, p, "power_relative_stdev")};
  }
  if (doc.contains("flicker_animated")) {
    const json& fa = r.obj(doc, "", "flicker_animated");
    QualityModel::Animated a;
    a.frames = r.any(fa, "/flicker_animated", "frames");
    a.sequence = r.string(fa, "/flicker_animated", "sequence");
    a.note = r.string(fa, "/flicker_animated", "note");
    a.reference_weighted_cv = r.num(fa, "/flicker_animated", "reference_weighted_cv");
    const json& ag = r.obj(fa, "/flicker_animated", "generators");
    for (const auto& [g, f] : ag.items()) {
      const std::string p = "/flicker_animated/generators/" + g;
      if (!f.is_object()) r.wrong_type(f, p, "an object");
      a.generators[g] = {r.num(f, p, "weighted_cv"), r.num(f, p, "error_cv"), r.num(f, p, "power_relative_stdev")};
    }
    m.flicker_animated = a;
  }
  if (doc.contains("k_sweep"))
    for (const auto& [g, rows] : r.obj(doc, "", "k_sweep").items()) {
      const std::string gp = "/k_sweep/" + g;
      if (!rows.is_array()) r.wrong_type(rows, gp, "an array");
      std::vector<KSweepRow> out;
      for (std::size_t i = 0; i < rows.size(); ++i) {
        const std::string p = r.element(gp, i);
        const json& row = rows[i];
        if (!row.is_object()) r.wrong_type(row, p, "an object");
        out.push_back({r.num(row, p, "K"), r.num(row, p, "weighted_cv"), read_error(r, r.obj(row, p, "error"), p + "/error"),
                       read_coverage(r, r.obj(row, p, "coverage"), p + "/coverage"), read_power(r, r.obj(row, p, "power"), p + "/power")});
      }
      m.k_sweep.emplace_back(g, std::move(out));
    }
  if (doc.contains("claims")) {
    const json& claims = r.any(doc, "", "claims");
    if (!claims.is_array()) r.wrong_type(claims, "/claims", "an array");
    for (std::size_t i = 0; i < claims.size(); ++i) {
      const std::string p = r.element("/claims", i);
      const json& c = claims[i];
      if (!c.is_object()) r.wrong_type(c, p, "an object");
      m.claims.push_back({r.string(c, p, "claim"), r.string(c, p, "measure"), r.string(c, p, "verdict"),
                          r.optional_num(c, p, "fis_tok15"), r.optional_num(c, p, "fis_modified")});
    }
  }
  if (doc.contains("timings_s"))
    for (const auto& [k, v] : r.obj(doc, "", "timings_s").items()) m.timings_s.emplace_back(k, r.number(v, "/timings_s/" + k));
  return m;
}

}  // namespace vsgl
