#include "harness/sweep/sweep_run.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "harness/capture/capture_files.hpp"
#include "harness/core/atomic_file.hpp"
#include "harness/core/error.hpp"
#include "harness/core/json_reader.hpp"
#include "harness/core/embedded_files.hpp"
#include "harness/core/json_schema_subset.hpp"
#include "harness/core/text_format.hpp"
#include "harness/generators/device_view.hpp"
#include "harness/generators/generator_registry.hpp"
#include "harness/quality/quality_metrics.hpp"
#include "harness/reference/fis_reference.hpp"
#include "harness/report/capture_scene_identity.hpp"
#include "harness/report/paper_tables.hpp"
#include "harness/report/run_context.hpp"
#include "harness/report/table_measurement.hpp"
#include "harness/scene/capture_provisioning.hpp"
#include "harness/sweep/pdf_sharpening.hpp"
#include "harness/sweep/sweep_report.hpp"
#include "harness/timing/run_provenance.hpp"
#include "harness/vk/device.hpp"
#include "harness/vk/device_info.hpp"

namespace vsgl {
namespace {

using ojson = nlohmann::ordered_json;

bool has_axis(const SweepOptions& o, SweepParameter p) {
  for (const SweepAxis& a : o.axes)
    if (a.parameter == p) return true;
  return false;
}

void check_options(const SweepOptions& o) {
  if (o.out_dir.empty()) throw UsageError("sweep needs an output directory");
  check_axes(o.axes);
  if (o.capture.has_value() == !o.scene.empty())
    throw UsageError("sweep needs exactly one input: --capture DIR or --scene NAME");
  for (SweepParameter p : {SweepParameter::kGbuffer, SweepParameter::kRsm})
    if (has_axis(o, p) && o.capture)
      throw UsageError(std::string("--axis ") + sweep_parameter_name(p) +
                       " records the capture again at each size, which needs --scene NAME, not --capture");
  const TablesOptions& t = o.tables;
  if (t.generators.empty()) throw UsageError("no generator to time");
  const auto known = generator_names();
  std::set<std::string> seen;
  for (const auto& g : t.generators) {
    if (std::find(known.begin(), known.end(), g) == known.end()) generator_sources(g);  // throws naming the known ones
    if (!seen.insert(g).second) throw UsageError("generator " + g + " is asked for twice");
  }
  if (t.camera_vsgls == 0 || t.light_vsgls == 0) throw InputError("N = 0: at least one VSGL is needed");
  t.timing.check();
  if (o.time_budget_s && !(std::isfinite(*o.time_budget_s) && *o.time_budget_s > 0))
    throw UsageError("--time-budget must be a positive number of seconds");
}

PointPdfFrequency frequency_of(const Capture& capture, ViewKind kind) {
  const ViewImage& view = capture.view(kind);
  const glm::vec3 source = kind == ViewKind::kCamera ? capture.meta.camera.position : capture.meta.light.position;
  const auto moments = reference_moments(view, source);
  const PdfFrequency f = pdf_frequency(MipPyramid::build(moments[2], view.width, view.height));
  return PointPdfFrequency{f.relative_variance, f.fine_share};
}

bool same_sizes(const RecordSizes& a, const RecordSizes& b) {
  return a.gbuffer_width == b.gbuffer_width && a.gbuffer_height == b.gbuffer_height && a.rsm_size == b.rsm_size;
}

// The sweep's JSON, complete and schema-valid, or an error; nothing written.
ojson checked_sweep_json(const MeasuredSweep& m, const std::vector<SweepFit>& fits, const SweepContext& ctx,
                         const std::vector<PdfIndependence>& claims, const nlohmann::json& schema,
                         const SweepOptions& o) {
  ojson doc;
  try {
    doc = sweep_json(m, fits, ctx, claims);
    require_finite_numbers(doc);
  } catch (const std::invalid_argument& e) {
    throw DeviceError(std::string("sweep: ") + e.what());
  }
  require_conforming(doc, schema, "the sweep", file_or_built_in_name(o.schema, kSweepSchemaFile));
  return doc;
}

// After each point (DESIGN.md §10.1): OUT/sweep.json with the points so far, "complete": false, the
// fits over those points and no claims (they need every value of γ), so a run cut short keeps
// what it measured. Nothing before the first point is timed.
void write_partial_sweep(const MeasuredSweep& m, const SweepContext& ctx, const nlohmann::json& schema,
                         const SweepOptions& o) {
  if (m.points.empty()) return;
  const ojson doc = checked_sweep_json(m, sweep_fits(m), ctx, {}, schema, o);
  std::filesystem::create_directories(o.out_dir);
  write_text_atomic(o.out_dir / "sweep.json", doc.dump(2) + "\n");
}

}  // namespace

std::filesystem::path sweep_capture_dir(const std::filesystem::path& root, const std::string& scene,
                                        const RecordSizes& s) {
  return root / (scene + "-g" + std::to_string(s.gbuffer_width) + "x" + std::to_string(s.gbuffer_height) + "-r" +
                 std::to_string(s.rsm_size));
}

SweepOutcome run_sweep(Device& device, const SweepOptions& o, const std::function<void(const SweepEvent&)>& on_event) {
  check_options(o);
  require_timestamps(device.info());
  const std::vector<std::vector<std::size_t>> points = axis_product(o.axes);
  const auto say = [&](const std::string& msg, std::size_t point = 0) {
    if (on_event) on_event(SweepEvent{msg, nullptr, point, points.size()});
  };
  // Everything that is not a measurement first, so a bad schema or scene fails in seconds.
  const nlohmann::json schema =
      json_file_or_built_in(o.schema, kSweepSchemaFile, "the sweep schema", " (use --schema FILE)");
  SweepContext ctx;
  ctx.device = to_json(device.info());
  ctx.build = build_json();
  ctx.run = run_json(o.tables);
  ctx.paper = paper_tables_or_built_in(o.tables.paper_tables);
  ctx.informative = device.info().type == VK_PHYSICAL_DEVICE_TYPE_CPU;
  std::optional<NamedScene> scene;
  if (!o.scene.empty()) scene = load_named_scene(o.scene, o.scenes);

  MeasuredSweep m;
  m.axes = o.axes;
  m.generators = o.tables.generators;
  m.time_budget_s = o.time_budget_s;
  m.complete = false;  // until every point is reached
  // The capture of the last point: consecutive points of one size share it.
  bool holding = false;  // whether `held` is the capture of `held_sizes`
  RecordSizes held_sizes{};
  ProvidedCapture held;
  for (std::size_t i = 0; i < points.size(); ++i) {
    TablesOptions t = o.tables;
    RecordSizes sizes = o.record_sizes;
    std::optional<double> gamma;
    const std::string where = point_values_text(o.axes, points[i]);
    for (std::size_t a = 0; a < o.axes.size(); ++a) {
      const AxisValue& v = o.axes[a].values[points[i][a]];
      const auto whole = static_cast<uint32_t>(v.value);
      switch (o.axes[a].parameter) {
        case SweepParameter::kVsgls: t.camera_vsgls = t.light_vsgls = whole; break;
        case SweepParameter::kCameraVsgls: t.camera_vsgls = whole; break;
        case SweepParameter::kLightVsgls: t.light_vsgls = whole; break;
        case SweepParameter::kK: t.generator.K = static_cast<float>(v.value); break;
        case SweepParameter::kKmeansIterations: t.generator.kmeans_iterations = whole; break;
        case SweepParameter::kGbuffer:
          sizes.gbuffer_width = v.width;
          sizes.gbuffer_height = v.height;
          break;
        case SweepParameter::kRsm: sizes.rsm_size = whole; break;
        case SweepParameter::kPdfSharpness: gamma = v.value; break;
      }
    }
    if (o.time_budget_s) t.timing.time_cap_s = *o.time_budget_s / static_cast<double>(points.size());
    SweepPointResult r;
    r.value_index = points[i];
    r.time_cap_s = t.timing.time_cap_s;
    try {
      if (!holding || !same_sizes(held_sizes, sizes)) {
        holding = false;  // until this size's capture is held
        if (o.capture) {
          held = ProvidedCapture{load_capture(*o.capture), false, {}};  // every hash checked
        } else {
          const std::filesystem::path dir = sweep_capture_dir(o.captures_dir, o.scene, sizes);
          held = provide_capture(device, *scene, sizes, dir);
          if (!held.stale_because.empty())
            say("re-recorded the stale capture " + dir.string() + ": " + held.stale_because, i);
          else if (held.recorded) say("recorded the capture " + dir.string(), i);
        }
        held_sizes = sizes;
        holding = true;
      }
      r.capture_dir = o.capture ? o.capture->string() : sweep_capture_dir(o.captures_dir, o.scene, sizes).string();
      if (m.points.empty()) {
        m.scene = capture_scene_identity(held.capture.meta);
        m.paper_table = paper_table_of(held.capture.meta);
      }
      std::optional<Capture> altered;
      if (gamma) {
        altered = sharpened_pdf_capture(held.capture, *gamma);
        r.pdf_sharpness = gamma;
        for (ViewKind k : {ViewKind::kCamera, ViewKind::kLight})
          r.pdf_frequency[view_name(k)] = frequency_of(*altered, k);
      }
      const Capture& capture = altered ? *altered : held.capture;
      r.capture = ojson{{"hashes", capture_hashes_json(capture)},
                        {"gbuffer", ojson{{"width", capture.gbuffer.width}, {"height", capture.gbuffer.height}}},
                        {"rsm", ojson{{"width", capture.rsm.width}, {"height", capture.rsm.height}}},
                        {"pdf_altered_in_memory", altered.has_value()}};
      if (capture.meta.brsm_pyramid) r.capture["brsm_pyramid"] = pyramid_path_name(*capture.meta.brsm_pyramid);
      r.config = config_json(t, capture, device.info());
      say("point " + std::to_string(i + 1) + "/" + std::to_string(points.size()) + ": " + where + " (" +
              std::to_string(2 * t.generators.size()) + " cases)",
          i);
      std::vector<CaseBeyondDevice> cases_beyond;
      r.timing = time_capture(
          device, t, capture,
          [&](const TimingProgress& p) {
            if (on_event) on_event(SweepEvent{"", &p, i, points.size()});
          },
          &cases_beyond);
      for (CaseBeyondDevice& c : cases_beyond) {
        say("point " + std::to_string(i + 1) + "/" + std::to_string(points.size()) + ": " + where + ", " + c.generator +
                " " + c.view + " is beyond the device: " + c.reason,
            i);
        m.beyond_device.push_back(BeyondDevicePoint{points[i], c.generator, c.view, c.reason});
      }
    } catch (const DeviceLimitError& e) {
      // A size the device cannot hold ends this point only: the device is unharmed (DESIGN.md §10.1).
      say("point " + std::to_string(i + 1) + "/" + std::to_string(points.size()) + ": " + where +
              " is beyond the device: " + e.what(),
          i);
      m.beyond_device.push_back(BeyondDevicePoint{points[i], "", "", e.what()});
      write_partial_sweep(m, ctx, schema, o);
      continue;
    }
    m.points.push_back(std::move(r));
    write_partial_sweep(m, ctx, schema, o);
  }
  if (m.points.size() < 2) {
    std::string why;
    for (const BeyondDevicePoint& b : m.beyond_device) why += "\n  " + b.reason;
    throw DeviceError("sweep: only " + std::to_string(m.points.size()) + " of " + std::to_string(points.size()) +
                      " points fit " + device.info().name + ", and a sweep needs 2; the others are beyond it:" + why +
                      (m.points.empty() ? std::string()
                                        : "\n" + (o.out_dir / "sweep.json").string() +
                                              " keeps the point timed, marked \"complete\": false"));
  }

  m.complete = true;
  SweepOutcome out;
  out.fits = sweep_fits(m);
  out.claims = judge_pdf_independence(m, out.fits);
  out.document = checked_sweep_json(m, out.fits, ctx, out.claims, schema, o);
  out.markdown = sweep_markdown(m, out.fits, out.claims);
  // The markdown and plots first, the complete sweep.json last: "complete": true on disk means
  // every file of the sweep is written.
  std::vector<std::pair<std::filesystem::path, std::string>> files;
  files.emplace_back(o.out_dir / "sweep.md", out.markdown);
  for (auto& [name, svg] : sweep_plots(m, out.fits, &ctx.paper)) files.emplace_back(o.out_dir / name, std::move(svg));
  files.emplace_back(o.out_dir / "sweep.json", out.document.dump(2) + "\n");
  // Nothing of the complete sweep is written until every file is complete and valid.
  std::filesystem::create_directories(o.out_dir);
  for (const auto& [path, text] : files) {
    write_text_atomic(path, text);
    out.written.push_back(path);
  }
  out.measured = std::move(m);
  return out;
}

}  // namespace vsgl
