#pragma once
// A measured sweep from made-up samples (harness/sweep/measured_sweep.hpp), for the suites that
// read what `vsgl-bench sweep` writes (the sweep model, the dashboard's scaling section) without a
// device: FIS's filtered sampling linear in N on the camera view and, deliberately wrong,
// quadratic on the light view (a flagged fit); k-means' phases flat.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/sweep/measured_sweep.hpp"
#include "harness/sweep/sweep_axis.hpp"
#include "harness/sweep/sweep_document.hpp"
#include "synthetic_header.hpp"

namespace vsgl::test {

// Five rounds around `ms`, spread by ±1 % so the statistics and the bootstrap have noise to see.
inline std::vector<double> sweep_rounds(double ms) { return {ms * 0.99, ms * 1.0, ms * 1.01, ms * 0.995, ms * 1.005}; }

inline CaseTiming synthetic_sweep_case(const std::string& generator, const std::string& view, double n) {
  CaseTiming c;
  c.generator = generator;
  c.view = view;
  if (generator.rfind("kmeans", 0) == 0) {
    c.phases = {"cluster_assignment", "sort", "sum"};
    c.phase_ms = {sweep_rounds(4.0), sweep_rounds(1.0), sweep_rounds(2.0)};
    c.total_ms = sweep_rounds(7.0);
    c.dispatch_count = 40;
    return c;
  }
  c.phases = {"additional", "mipmapping", "filtered_sampling"};
  const double fs = view == "camera_view" ? 0.001 * n : 0.0001 * n * n;
  c.phase_ms = {sweep_rounds(0.5), sweep_rounds(0.25), sweep_rounds(fs)};
  c.total_ms = sweep_rounds(0.75 + fs);
  c.dispatch_count = 5;
  return c;
}

inline MeasuredSweep synthetic_sweep(const std::vector<SweepAxis>& axes,
                                     const std::vector<std::string>& generators = {"fis_modified"}) {
  MeasuredSweep s;
  s.axes = axes;
  s.generators = generators;
  s.scene = SceneIdentity{"tiny", SceneKind::kProcedural};
  s.time_budget_s = 12.0;
  for (const auto& index : axis_product(axes)) {
    SweepPointResult p;
    p.value_index = index;
    double n = 64, k = 1;
    for (std::size_t a = 0; a < axes.size(); ++a) {
      const double v = axes[a].values[index[a]].value;
      if (axes[a].parameter == SweepParameter::kVsgls) n = v;
      if (axes[a].parameter == SweepParameter::kK) k = v;
      if (axes[a].parameter == SweepParameter::kPdfSharpness) {
        p.pdf_sharpness = v;
        p.pdf_frequency["camera_view"] = PointPdfFrequency{0.5 * v, {0.1, 0.2}};
        p.pdf_frequency["light_view"] = PointPdfFrequency{v, {0.2, 0.3}};
      }
    }
    p.capture_dir = "captures/sweep/tiny-g96x64-r64";
    p.capture = nlohmann::ordered_json{{"hashes", nlohmann::ordered_json::object()},
                                       {"gbuffer", {{"width", 96}, {"height", 64}}},
                                       {"rsm", {{"width", 64}, {"height", 64}}},
                                       {"pdf_altered_in_memory", p.pdf_sharpness.has_value()}};
    p.config = nlohmann::ordered_json{{"views", nlohmann::ordered_json::object()},
                                      {"K", k},
                                      {"kmeans_iterations", 4},
                                      {"timing", nlohmann::ordered_json::object()}};
    p.time_cap_s = 2.0;
    for (const std::string& g : generators)
      for (const char* view : {"camera_view", "light_view"}) p.timing.cases.push_back(synthetic_sweep_case(g, view, n));
    p.timing.repetitions = 5;
    p.timing.timed_seconds = 0.1;
    p.timing.stop_reason = "max_repetitions";
    p.timing.worst_noise = 0.01;
    s.points.push_back(std::move(p));
  }
  return s;
}

inline SweepContext synthetic_sweep_context(const std::string& device = "synthetic",
                                            const std::string& started_utc = "2026-01-01T00:00:00Z") {
  SweepContext c;
  c.device = synthetic_device(device);
  c.build = synthetic_build();
  c.run = synthetic_run(started_utc);
  return c;
}

// The sweep's document as `vsgl-bench sweep` fills it, and its JSON as it writes it.
inline SweepModel synthetic_sweep_document(const MeasuredSweep& s,
                                           const SweepContext& context = synthetic_sweep_context()) {
  return sweep_document(s, sweep_fits(s), context);
}
inline nlohmann::ordered_json synthetic_sweep_json(const MeasuredSweep& s,
                                                   const SweepContext& context = synthetic_sweep_context()) {
  return to_json(synthetic_sweep_document(s, context));
}

// A claim object of the shape the sweep writes for its pdf-sharpness axis.
inline nlohmann::ordered_json synthetic_sweep_claim(const nlohmann::ordered_json& holds, const std::string& note) {
  return nlohmann::ordered_json{{"id", "pdf_independence"},
                                {"text", "FIS cost is almost independent of the PDF, k-means cost is not"},
                                {"axis", "pdf-sharpness"},
                                {"slice", nlohmann::ordered_json::object()},
                                {"criterion", "every FIS change within ±10 % <at every γ>"},
                                {"reference_gamma", 1.0},
                                {"band", 0.1},
                                {"measured", nlohmann::ordered_json::array()},
                                {"holds", holds},
                                {"note", note},
                                {"informative", true}};
}

}  // namespace vsgl::test
