#include "harness/sweep/sweep_point_timing.hpp"

#include <string>

#include "harness/core/error.hpp"
#include "harness/generators/device_view.hpp"
#include "harness/quality/quality_metrics.hpp"
#include "harness/reference/fis_reference.hpp"
#include "harness/report/capture_scene_identity.hpp"
#include "harness/report/run_context.hpp"
#include "harness/report/table_timing.hpp"
#include "harness/sweep/pdf_sharpening.hpp"
#include "harness/vk/device.hpp"

namespace vsgl {
namespace {

using ojson = nlohmann::ordered_json;

PointPdfFrequency frequency_of(const Capture& capture, ViewKind kind) {
  const ViewImage& view = capture.view(kind);
  const glm::vec3 source = kind == ViewKind::kCamera ? capture.meta.camera.position : capture.meta.light.position;
  const auto moments = reference_moments(view, source);
  const PdfFrequency f = pdf_frequency(MipPyramid::build(moments[2], view.width, view.height));
  return PointPdfFrequency{f.relative_variance, f.fine_share};
}

// The point's record of the capture it timed: hashes, sizes, and whether γ altered it.
ojson capture_json(const Capture& capture, bool altered) {
  ojson j{{"hashes", capture_hashes_json(capture)},
          {"gbuffer", ojson{{"width", capture.gbuffer.width}, {"height", capture.gbuffer.height}}},
          {"rsm", ojson{{"width", capture.rsm.width}, {"height", capture.rsm.height}}},
          {"pdf_altered_in_memory", altered}};
  if (capture.meta.brsm_pyramid) j["brsm_pyramid"] = pyramid_path_name(*capture.meta.brsm_pyramid);
  return j;
}

// The point's timing, its capture altered to γ first; cases the device cannot hold are added to
// `out.beyond_device`.
SweepPointResult timed_point(Device& device, const Capture& held, const std::string& capture_dir,
                             const SweepPointSetup& setup, const SweepLog& log, SweepPointOutcome& out) {
  SweepPointResult r;
  r.value_index = setup.value_index;
  r.time_cap_s = setup.tables.timing.time_cap_s;
  r.capture_dir = capture_dir;
  std::optional<Capture> altered;
  if (setup.gamma) {
    altered = sharpened_pdf_capture(held, *setup.gamma);
    r.pdf_sharpness = setup.gamma;
    for (ViewKind k : {ViewKind::kCamera, ViewKind::kLight}) r.pdf_frequency[view_name(k)] = frequency_of(*altered, k);
  }
  const Capture& capture = altered ? *altered : held;
  r.capture = capture_json(capture, altered.has_value());
  r.config = config_json(setup.tables, capture, device.info());
  log.say(log.point_prefix(setup.point) + setup.where + " (" + std::to_string(2 * setup.tables.generators.size()) +
              " cases)",
          setup.point);
  std::vector<CaseBeyondDevice> cases_beyond;
  r.timing = time_capture(
      device, setup.tables, capture, [&](const TimingProgress& p) { log.progress(p, setup.point); }, &cases_beyond);
  for (CaseBeyondDevice& c : cases_beyond) {
    log.say(log.point_prefix(setup.point) + setup.where + ", " + c.generator + " " + c.view +
                " is beyond the device: " + c.reason,
            setup.point);
    out.beyond_device.push_back(BeyondDevicePoint{setup.value_index, c.generator, c.view, c.reason});
  }
  return r;
}

}  // namespace

SweepPointOutcome time_sweep_point(Device& device, SweepCaptureCache& captures, const SweepPointSetup& setup,
                                   const SweepLog& log) {
  SweepPointOutcome out;
  try {
    const Capture& held = captures.at(setup.sizes, setup.point, log);
    out.scene = capture_scene_identity(held.meta);
    out.paper_table = paper_table_of(held.meta);
    out.timed = timed_point(device, held, captures.dir(setup.sizes), setup, log, out);
  } catch (const DeviceLimitError& e) {
    // A size the device cannot hold ends this point only: the device is unharmed (DESIGN.md §10.1).
    log.say(log.point_prefix(setup.point) + setup.where + " is beyond the device: " + e.what(), setup.point);
    out.beyond_device.push_back(BeyondDevicePoint{setup.value_index, "", "", e.what()});
  }
  return out;
}

}  // namespace vsgl
