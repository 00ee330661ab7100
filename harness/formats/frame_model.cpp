#include "harness/formats/frame_model.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "harness/core/error.hpp"
#include "harness/core/text_format.hpp"
#include "harness/core/json_reader.hpp"
#include "harness/core/statistics.hpp"

namespace vsgl {
namespace {

using ojson = nlohmann::ordered_json;

ojson stats_json(const TimingStatistics& s) { return to_json(s, StatisticsLayout::kTable); }

FrameGeneratorTiming read_generator(const JsonReader& r, const ojson& g, const std::string& p) {
  if (!g.is_object()) r.wrong_type(g, p, "an object");
  r.only_keys(g, p, {"name", "phases", "frame", "dispatch_calls"});
  FrameGeneratorTiming out;
  out.name = r.string(g, p, "name");
  const ojson& phases = r.member(g, p, "phases");
  const std::string pp = r.child(p, "phases");
  if (!phases.is_object()) r.wrong_type(phases, pp, "an object");
  const auto& names = frame_phase_names();
  std::vector<std::string> keys;
  for (const auto& [k, v] : phases.items()) keys.push_back(k);
  if (keys != names) {
    std::string want;
    for (const auto& n : names) want += (want.empty() ? "" : ", ") + n;
    r.fail(pp, "does not hold the frame's phases " + want + " in that order");
  }
  for (const auto& n : names)
    out.phases.push_back({n, timing_statistics_from_json(r, phases[n], r.child(pp, n), StatisticsLayout::kTable)});
  out.frame = timing_statistics_from_json(r, r.member(g, p, "frame"), r.child(p, "frame"), StatisticsLayout::kTable);
  out.dispatch_calls = r.uint32(g, p, "dispatch_calls");
  // Sample i of every series is round i (DESIGN.md §9): the frame of round i is its phases' sum.
  const std::size_t rounds = out.frame.samples_ms.size();
  for (const auto& ph : out.phases)
    if (ph.stats.samples_ms.size() != rounds)
      r.fail(r.child(r.child(pp, ph.phase), "samples_ms"), "holds " + std::to_string(ph.stats.samples_ms.size()) +
                                                               " samples, the frame " + std::to_string(rounds) +
                                                               " (one per round in every series)");
  for (std::size_t i = 0; i < rounds; ++i) {
    double sum = 0;
    for (const auto& ph : out.phases) sum += ph.stats.samples_ms[i];
    const double frame = out.frame.samples_ms[i];
    if (std::abs(sum - frame) > 1e-9 * std::max(std::abs(sum), 1.0))
      r.fail(r.element(r.child(r.child(p, "frame"), "samples_ms"), i),
             "is " + std::to_string(frame) + " ms, not the sum of the round's phases (" + std::to_string(sum) + " ms)");
  }
  return out;
}

}  // namespace

const std::vector<std::string>& frame_phase_names() {
  static const std::vector<std::string> names{"rsm_replay", "pdf", "vsgl_generation", "ism", "shading"};
  return names;
}

std::string frame_phase_description(const std::string& phase) {
  if (phase == "rsm_replay")
    return "the recorded RSM copied into the device buffer the generators read (a replay: the suite does not "
           "rasterize; not the paper's RSM rendering)";
  if (phase == "pdf")
    return "the BRSM PDF built on the device as `record` builds it (camera-view fis_modified + the BRSM pass)";
  if (phase == "vsgl_generation")
    return "the generator's N light-view VSGLs: all its phases as one interval (full barriers where `tables` writes "
           "timestamps)";
  if (phase == "ism")
    return "an imperfect shadow map per VSGL, splatted from the capture's points and filled by pull-push";
  if (phase == "shading") return "the camera view shaded with the N VSGLs and their maps (visibility ism)";
  throw std::invalid_argument("no frame phase '" + phase + "'");
}

double frame_phase_share(const FrameGeneratorTiming& g, std::size_t phase) {
  const auto& s = g.phases.at(phase).stats.samples_ms;
  std::vector<double> shares(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) shares[i] = s[i] / g.frame.samples_ms.at(i);
  std::sort(shares.begin(), shares.end());
  return quantile_sorted(shares, 0.5);
}

nlohmann::ordered_json to_json(const FrameModel& m) {
  ojson doc;
  doc["schema_version"] = m.schema_version;
  doc["kind"] = "frame";
  doc["unit"] = "ms";
  doc["device"] = to_json(m.device);
  doc["build"] = to_json(m.build);
  doc["run"] = to_json(m.run);
  doc["capture"] = ojson{{"scene", m.capture.scene},
                         {"dir", m.capture.dir},
                         {"gbuffer", {m.capture.gbuffer_width, m.capture.gbuffer_height}},
                         {"rsm", {m.capture.rsm_width, m.capture.rsm_height}},
                         {"visibility_points", m.capture.visibility_points}};
  doc["config"] =
      ojson{{"light_vsgls", m.config.light_vsgls}, {"pdf_camera_vsgls", m.config.pdf_camera_vsgls},
            {"ism_side", m.config.ism_side},       {"ism_points_per_map", m.config.ism_points_per_map},
            {"stride", m.config.stride},           {"shaded", {m.config.shaded_width, m.config.shaded_height}},
            {"paper_sizes", m.config.paper_sizes}, {"sizes_note", m.config.sizes_note}};
  ojson phases = ojson::array();
  for (const auto& n : frame_phase_names()) phases.push_back(ojson{{"name", n}, {"times", frame_phase_description(n)}});
  doc["phases"] = phases;
  doc["timing"] = ojson{{"repetitions", m.timing.repetitions},
                        {"timed_seconds", m.timing.timed_seconds},
                        {"stop_reason", m.timing.stop_reason},
                        {"worst_relative_iqr", m.timing.worst_relative_iqr}};
  ojson gens = ojson::array();
  for (const auto& g : m.generators) {
    ojson phase_stats = ojson::object();
    for (const auto& p : g.phases) phase_stats[p.phase] = stats_json(p.stats);
    gens.push_back(ojson{{"name", g.name},
                         {"phases", phase_stats},
                         {"frame", stats_json(g.frame)},
                         {"dispatch_calls", g.dispatch_calls}});
  }
  doc["generators"] = gens;
  return doc;
}

FrameModel frame_model_from_json(const nlohmann::ordered_json& doc, const std::string& what) {
  const JsonReader r(what, JsonPathStyle::kPointer);
  if (!doc.is_object()) r.fail("", "is not a JSON object");
  r.only_keys(doc, "",
              {"schema_version", "kind", "unit", "device", "build", "run", "capture", "config", "phases", "timing",
               "generators"});
  FrameModel m;
  const ojson& version = r.member(doc, "", "schema_version");
  if (!version.is_number_integer() || version.get<int>() != kFrameSchemaVersion)
    r.fail("/schema_version", "is " + version.dump() + ", not " + std::to_string(kFrameSchemaVersion));
  if (r.string(doc, "", "kind") != "frame") r.fail("/kind", "is not \"frame\"");
  if (r.string(doc, "", "unit") != "ms") r.fail("/unit", "is not \"ms\"");
  m.device = device_record_from_json(r, r.object(doc, "", "device"), "/device");
  m.build = build_record_from_json(r, r.object(doc, "", "build"), "/build");
  m.run = run_record_from_json(r, r.object(doc, "", "run"), "/run");

  const ojson& c = r.object(doc, "", "capture");
  r.only_keys(c, "/capture", {"scene", "dir", "gbuffer", "rsm", "visibility_points"});
  m.capture.scene = r.string(c, "/capture", "scene");
  m.capture.dir = r.string(c, "/capture", "dir");
  const auto pair = [&](const ojson& o, const std::string& p, const char* key, uint32_t& a, uint32_t& b) {
    const ojson& v = r.array(o, p, key, 2);
    a = static_cast<uint32_t>(r.uint64(v[0], r.element(r.child(p, key), 0)));
    b = static_cast<uint32_t>(r.uint64(v[1], r.element(r.child(p, key), 1)));
  };
  pair(c, "/capture", "gbuffer", m.capture.gbuffer_width, m.capture.gbuffer_height);
  pair(c, "/capture", "rsm", m.capture.rsm_width, m.capture.rsm_height);
  m.capture.visibility_points = r.uint64(c, "/capture", "visibility_points");

  const ojson& k = r.object(doc, "", "config");
  const std::string kp = "/config";
  r.only_keys(k, kp,
              {"light_vsgls", "pdf_camera_vsgls", "ism_side", "ism_points_per_map", "stride", "shaded", "paper_sizes",
               "sizes_note"});
  m.config.light_vsgls = r.uint32(k, kp, "light_vsgls");
  m.config.pdf_camera_vsgls = r.uint32(k, kp, "pdf_camera_vsgls");
  m.config.ism_side = r.uint32(k, kp, "ism_side");
  m.config.ism_points_per_map = r.uint32(k, kp, "ism_points_per_map");
  m.config.stride = r.uint32(k, kp, "stride");
  if (m.config.stride == 0) r.fail("/config/stride", "is 0, not a stride");
  pair(k, kp, "shaded", m.config.shaded_width, m.config.shaded_height);
  m.config.paper_sizes = r.boolean(k, kp, "paper_sizes");
  m.config.sizes_note = r.string(k, kp, "sizes_note");

  // The phases' descriptions are the program's (written for a reader of the file); the names are checked.
  const ojson& phases = r.array(doc, "", "phases", frame_phase_names().size());
  for (std::size_t i = 0; i < phases.size(); ++i) {
    const std::string pp = r.element("/phases", i);
    if (!phases[i].is_object()) r.wrong_type(phases[i], pp, "an object");
    if (r.string(phases[i], pp, "name") != frame_phase_names()[i])
      r.fail(r.child(pp, "name"), "is not the frame's phase " + frame_phase_names()[i]);
    r.string(phases[i], pp, "times");
  }

  const ojson& t = r.object(doc, "", "timing");
  m.timing =
      FrameTimingStop{r.uint64(t, "/timing", "repetitions"),
                      r.non_negative(r.member(t, "/timing", "timed_seconds"), "/timing/timed_seconds"),
                      r.string(t, "/timing", "stop_reason"),
                      r.non_negative(r.member(t, "/timing", "worst_relative_iqr"), "/timing/worst_relative_iqr")};

  const ojson& gens = r.nonempty_array(doc, "", "generators");
  for (std::size_t i = 0; i < gens.size(); ++i)
    m.generators.push_back(read_generator(r, gens[i], r.element("/generators", i)));
  for (const auto& g : m.generators)
    if (g.frame.samples_ms.size() != m.timing.repetitions)
      r.fail("/timing/repetitions", "is " + std::to_string(m.timing.repetitions) + ", but generator " + g.name +
                                        " has " + std::to_string(g.frame.samples_ms.size()) + " rounds");
  return m;
}

std::string frame_markdown(const FrameModel& m) {
  std::ostringstream os;
  os << "# The frame on " << m.device.name << ": " << m.capture.scene << "\n\n";
  os << "Device: " << m.device.name << " (" << m.device.type << "), driver " << m.device.driver_name << " "
     << m.device.driver_info << ", Vulkan " << m.device.api_version << ". Build: vsgl-bench "
     << m.build.vsgl_bench_version << " (" << m.build.git_commit << (m.build.git_dirty ? ", dirty" : "") << ", "
     << m.build.compiler << "). Run: " << m.run.started_utc << (m.run.validation_layer ? ", validation layer on" : "")
     << (m.run.quick ? ", --quick (3 repetitions: not the DESIGN.md §9 protocol)" : "")
     << (m.run.clocks_locked_claimed ? ", clocks claimed locked" : ", clocks not claimed locked") << ".\n\n";
  os << "Capture " << m.capture.scene << " (" << m.capture.dir << "): G-buffer " << m.capture.gbuffer_width << "x"
     << m.capture.gbuffer_height << ", RSM " << m.capture.rsm_width << "x" << m.capture.rsm_height << ", "
     << m.capture.visibility_points << " visibility points. N = " << m.config.light_vsgls << " light-view VSGLs, ISM "
     << m.config.ism_side << "x" << m.config.ism_side << " (" << m.config.ism_points_per_map
     << " points per map), shading stride " << m.config.stride << " (" << m.config.shaded_width << "x"
     << m.config.shaded_height << " pixels shaded), BRSM PDF from " << m.config.pdf_camera_vsgls
     << " camera-view VSGLs. "
     << (m.config.paper_sizes ? "These are the paper's sizes." : "Not the paper's sizes: " + m.config.sizes_note + ".")
     << "\n\n";
  os << "Phases (each between two Vulkan timestamps, in one command buffer per frame, DESIGN.md §9.2):\n\n";
  for (const auto& n : frame_phase_names()) os << "- `" << n << "`: " << frame_phase_description(n) << "\n";
  os << "\nMedian of " << m.timing.repetitions << " rounds (stop: " << m.timing.stop_reason << ", worst IQR/median "
     << fixed_text(m.timing.worst_relative_iqr) << ", " << fixed_text(m.timing.timed_seconds, 1)
     << " s timed); the interval is the interquartile range [q1, q3]; the share is the median over the rounds of "
        "phase / frame. `frame` is the sum of the five phases in each round.\n";
  for (const auto& g : m.generators) {
    os << "\n## " << g.name << "\n\n";
    os << "| phase | median (ms) | interval [q1, q3] (ms) | share of frame |\n|---|---:|---:|---:|\n";
    for (std::size_t p = 0; p < g.phases.size(); ++p) {
      const TimingStatistics& s = g.phases[p].stats;
      os << "| " << g.phases[p].phase << " | " << fixed_text(s.median_ms) << " | [" << fixed_text(s.q1_ms) << ", "
         << fixed_text(s.q3_ms) << "] | " << fixed_text(100 * frame_phase_share(g, p), 1) << " % |\n";
    }
    os << "| **frame** | **" << fixed_text(g.frame.median_ms) << "** | [" << fixed_text(g.frame.q1_ms) << ", "
       << fixed_text(g.frame.q3_ms) << "] | 100 % |\n";
    os << "\n" << g.dispatch_calls << " dispatches per frame.\n";
  }
  return os.str();
}

}  // namespace vsgl
