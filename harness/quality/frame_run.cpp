#include "harness/quality/frame_run.hpp"

#include <ctime>
#include <memory>
#include <stdexcept>

#include "harness/capture/capture_files.hpp"
#include "harness/capture/visibility_geometry.hpp"
#include "harness/core/atomic_file.hpp"
#include "harness/core/text_format.hpp"
#include "harness/core/embedded_files.hpp"
#include "harness/core/error.hpp"
#include "harness/core/json_schema_subset.hpp"
#include "harness/core/path_text.hpp"
#include "harness/generators/device_view.hpp"
#include "harness/generators/generator_registry.hpp"
#include "harness/quality/shading_pass.hpp"
#include "harness/quality/shading_visibility.hpp"
#include "harness/scene/brsm_pdf.hpp"
#include "harness/visibility/imperfect_shadow_maps.hpp"
#include "harness/vk/buffer.hpp"
#include "harness/vk/command_stream.hpp"
#include "harness/vk/device.hpp"
#include "harness/vk/device_info.hpp"

namespace vsgl {
namespace {

// One generator's frame as the timing runner sees a generator: five phases recorded into one
// command buffer, the runner's boundary (a timestamp between full barriers) between them
// (DESIGN.md §9.2). The generator's own phase boundaries become full barriers: its phases are one
// interval here, the tables time them one by one.
class FrameCase final : public VsglGenerator {
 public:
  FrameCase(Device& device, std::unique_ptr<VsglGenerator> generator, const LayeredTexels& recorded_rsm,
            const DeviceView& light, const DeviceView& camera, BrsmPdfPass& pdf,
            const std::vector<SurfacePoint>& points, const IsmSettings& ism, uint32_t stride)
      : generator_(std::move(generator)), recorded_rsm_(recorded_rsm), light_(light), pdf_(pdf) {
    // The maps' origins are the means and filtered normals of this generator's VSGLs from an
    // untimed run on the same inputs: the frame rebuilds the maps from them (DESIGN.md §9.2).
    run_untimed(device, *generator_);
    const auto records = download_vector<VsglRecord>(device, generator_->vsgls(), generator_->vsgl_count());
    maps_ = std::make_unique<ImperfectShadowMaps>(device, points, map_origins(records), ism);
    ShadeVisibility visibility;
    visibility.mode = ShadingVisibility::kIsm;
    visibility.maps = maps_.get();
    shading_ = std::make_unique<ShadingRecording>(device, camera, generator_->vsgls(), generator_->vsgl_count(), stride,
                                                  visibility);
  }

  std::string name() const override { return generator_->name(); }
  std::vector<std::string> phases() const override { return frame_phase_names(); }
  const Buffer& vsgls() const override { return generator_->vsgls(); }
  uint32_t vsgl_count() const override { return generator_->vsgl_count(); }
  const ShadingRecording& shading() const { return *shading_; }

  void record(CommandStream& stream, const std::function<void(VkCommandBuffer)>& boundary) override {
    VkCommandBuffer cmd = stream.get();
    boundary(cmd);
    // rsm_replay: the recorded RSM (its four layers, the recorded PDF among them) into the buffer
    // the BRSM pass and the generators read.
    const VkBufferCopy region{0, 0, recorded_rsm_.buffer.size()};
    vkCmdCopyBuffer(cmd, recorded_rsm_.buffer.get(), light_.texels.buffer.get(), 1, &region);
    boundary(cmd);
    pdf_.record(stream);  // pdf
    boundary(cmd);
    generator_->record(stream, [&stream](VkCommandBuffer) { stream.full_barrier(); });  // vsgl_generation
    boundary(cmd);
    maps_->record_build(stream);  // ism
    boundary(cmd);
    shading_->record(stream);  // shading
    boundary(cmd);
  }

 private:
  std::unique_ptr<VsglGenerator> generator_;
  const LayeredTexels& recorded_rsm_;
  const DeviceView& light_;
  BrsmPdfPass& pdf_;
  std::unique_ptr<ImperfectShadowMaps> maps_;
  std::unique_ptr<ShadingRecording> shading_;
};

// What differs from the paper's frame sizes (N 1024, ISM 64^2, RSM 512^2, G-buffer 1920x1088, every pixel).
std::string sizes_note(const Capture& capture, const FrameOptions& o) {
  std::string note;
  const auto add = [&note](const std::string& s) { note += (note.empty() ? "" : "; ") + s; };
  if (o.light_vsgls != kPaperLightVsgls) add("N " + std::to_string(o.light_vsgls) + ", not 1024");
  if (o.ism.side != 64) add("ISM " + std::to_string(o.ism.side) + "^2, not 64^2");
  if (capture.rsm.width != 512 || capture.rsm.height != 512)
    add("RSM " + std::to_string(capture.rsm.width) + "x" + std::to_string(capture.rsm.height) + ", not 512x512");
  if (capture.gbuffer.width != 1920 || capture.gbuffer.height != 1088)
    add("G-buffer " + std::to_string(capture.gbuffer.width) + "x" + std::to_string(capture.gbuffer.height) +
        ", not 1920x1088");
  if (o.stride != 1)
    add("shading stride " + std::to_string(o.stride) + ": every " + std::to_string(o.stride) +
        "-th pixel per axis, not every pixel");
  return note;
}

}  // namespace

FrameOutcome run_frame(Device& device, const FrameOptions& o,
                       const std::function<void(const TimingProgress&)>& progress) {
  if (o.generators.empty()) throw UsageError("frame: no generator to time");
  if (o.stride == 0) throw UsageError("frame: the stride must be at least 1");
  if (o.light_vsgls == 0) throw UsageError("frame: at least one VSGL is needed");
  o.timing.check();
  require_timestamps(device.info());
  for (const auto& g : o.generators) (void)generator_descriptor(g);  // InputError listing the names
  const nlohmann::ordered_json schema =
      json_file_or_built_in(o.schema, kFrameSchemaFile, "the frame schema", " (use --schema FILE)");

  Capture capture = load_capture(o.capture_dir);
  if (!capture.meta.visibility_geometry)
    throw InputError(path_text(o.capture_dir) +
                     ": the capture has no visibility geometry, and the frame's imperfect shadow maps splat its "
                     "points; record it again with `vsgl-bench record` and --visibility-points above 0 (the "
                     "default stores 2^20 points)");
  const VisibilityGeometry geometry = load_visibility_geometry(o.capture_dir, capture.meta);
  // The maps' settings against the capture's points and the device's limits, before anything runs.
  ShadingVisibilitySettings visibility;
  visibility.mode = ShadingVisibility::kIsm;
  visibility.ism = o.ism;
  VisibleShading(device, visibility, &geometry).require_maps_fit(o.light_vsgls);

  const DeviceView camera = upload_view(device, capture, ViewKind::kCamera);
  const DeviceView light = upload_view(device, capture, ViewKind::kLight);
  const LayeredTexels recorded_rsm = upload_layers(device, capture.rsm, "frame.recorded_rsm");
  BrsmPdfPass pdf(device, capture, camera, light.layers());

  std::vector<std::unique_ptr<FrameCase>> cases;
  for (const auto& name : o.generators) {
    GeneratorConfig config = o.generator;
    config.vsgl_count = o.light_vsgls;
    cases.push_back(std::make_unique<FrameCase>(device, make_generator(name, device, light, config), recorded_rsm,
                                                light, camera, pdf, geometry.points, o.ism, o.stride));
  }
  TimingRunner runner(device, o.timing);
  for (const auto& c : cases) runner.add({c->name(), "frame", c.get()});
  const TimingResult result = runner.run(progress);

  FrameOutcome out;
  FrameModel& m = out.model;
  m.device = device_record(device.info());
  m.build = this_build();
  m.run.started_utc = utc_now_text();
  m.run.validation_layer = o.validation;
  m.run.quick = o.quick;
  m.run.protocol_compliant = o.timing.warmup >= 2 && o.timing.min_repetitions >= 10;
  m.run.clocks_locked_claimed = o.clocks_locked;
  m.run.clocks_note =
      "Vulkan cannot lock GPU clocks: lock them outside (e.g. `nvidia-smi -lgc <MHz>` on NVIDIA) and pass "
      "--clocks-locked";
  m.capture = {capture.meta.scene, path_text(o.capture_dir), capture.gbuffer.width, capture.gbuffer.height,
               capture.rsm.width,  capture.rsm.height,       geometry.points.size()};
  m.config.light_vsgls = o.light_vsgls;
  m.config.pdf_camera_vsgls = pdf.camera_vsgls();
  m.config.ism_side = o.ism.side;
  m.config.ism_points_per_map = o.ism.points_per_map;
  m.config.stride = o.stride;
  m.config.shaded_width = cases.front()->shading().width();
  m.config.shaded_height = cases.front()->shading().height();
  m.config.sizes_note = sizes_note(capture, o);
  m.config.paper_sizes = m.config.sizes_note.empty();
  m.timing = {result.repetitions, result.timed_seconds, result.stop_reason, result.worst_noise};
  for (std::size_t i = 0; i < result.cases.size(); ++i) {
    const CaseTiming& t = result.cases[i];
    FrameGeneratorTiming g;
    g.name = t.generator;
    for (std::size_t p = 0; p < t.phases.size(); ++p)
      g.phases.push_back({t.phases[p], timing_statistics(t.phase_ms[p])});
    g.frame = timing_statistics(t.total_ms);  // per round, the sum of its phases (timing_runner.cpp)
    g.dispatch_calls = t.dispatch_count;
    m.generators.push_back(std::move(g));
  }

  nlohmann::ordered_json doc = to_json(m);
  try {
    require_finite_numbers(doc);
  } catch (const std::invalid_argument& e) {
    throw DeviceError(std::string("frame: ") + e.what());
  }
  require_conforming(doc, schema, "frame.json", file_or_built_in_name(o.schema, kFrameSchemaFile));
  out.markdown = frame_markdown(m);
  std::vector<std::pair<std::filesystem::path, std::string>> files{{o.out_dir / "frame.json", doc.dump(2) + "\n"}};
  if (!o.json_only) files.emplace_back(o.out_dir / "frame.md", out.markdown);
  std::error_code ec;
  std::filesystem::create_directories(o.out_dir, ec);
  if (ec) throw InputError(path_text(o.out_dir) + ": cannot create the output directory (" + ec.message() + ")");
  for (const auto& [path, text] : files) {
    write_text_atomic(path, text);
    out.written.push_back(path);
  }
  return out;
}

}  // namespace vsgl
