#include "harness/report/table_timing.hpp"

#include <cstdio>
#include <filesystem>
#include <vector>

#include "harness/report/run_context.hpp"
#include "harness/capture/capture_files.hpp"
#include "harness/report/capture_scene_identity.hpp"
#include "harness/timing/copy_bandwidth.hpp"
#include "harness/vk/device.hpp"

namespace vsgl {

ProvidedCapture provide_input_capture(Device& device, const TablesOptions& o, const TableInput& input,
                                      const std::function<void(const std::string&)>& say) {
  if (input.record_if_missing)
    return provide_table_capture(device, input.scene, o.scenes, input.capture_dir, o.record_sizes, say);
  ProvidedCapture provided;
  provided.capture = load_capture(input.capture_dir);  // every hash checked
  return provided;
}

TimingResult time_capture(Device& device, const TablesOptions& o, const Capture& capture,
                          const std::function<void(const TimingProgress&)>& progress,
                          std::vector<CaseBeyondDevice>* beyond) {
  CaptureCases cases(device, o, capture, beyond);
  return cases.runner().run(progress);
}

TableMeasurement measure_table(Device& device, const TablesOptions& o, const TableInput& input,
                               const std::function<void(const TablesEvent&)>& on_event) {
  const int number = input.paper_table;
  using ojson = nlohmann::ordered_json;
  const auto say = [&](const std::string& msg) {
    if (on_event) on_event(TablesEvent{msg, nullptr, number});
  };
  TableMeasurement out;
  MeasuredTable& t = out.table;
  t.number = number;
  t.generators = o.generators;
  const std::filesystem::path& dir = input.capture_dir;
  t.capture_dir = dir.string();
  const ProvidedCapture provided = provide_input_capture(device, o, input, say);
  t.recorded_now = provided.recorded;
  const Capture& capture = provided.capture;
  t.scene = capture.meta.scene;
  t.identity = capture_scene_identity(capture.meta);
  t.capture = ojson{{"hashes", capture_hashes_json(capture)},
                    {"frame", capture.meta.frame},
                    {"recorded_on", capture.meta.device},
                    {"tool_version", capture.meta.tool_version},
                    {"brsm_build_ms", capture.meta.brsm_build_ms}};
  if (capture.meta.brsm_pyramid) t.capture["brsm_pyramid"] = pyramid_path_name(*capture.meta.brsm_pyramid);
  if (capture.meta.source) {
    const SceneSource& src = *capture.meta.source;
    t.capture["source"] =
        ojson{{"format", src.format},       {"file", src.file},     {"content_hash", src.content_hash},
              {"triangles", src.triangles}, {"camera", src.camera}, {"light", src.light}};
  }
  out.config = config_json(o, capture, device.info());
  t.views["camera_view"] = ViewExtent{capture.gbuffer.width, capture.gbuffer.height};
  t.views["light_view"] = ViewExtent{capture.rsm.width, capture.rsm.height};

  // The copy bandwidth first, while no view or pyramid holds device memory (its buffers are
  // freed before the uploads), so a small device falls back as little as possible.
  const auto mib = [](uint64_t bytes) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g MiB", static_cast<double>(bytes) / (1 << 20));
    return std::string(buf);
  };
  say("measuring copy bandwidth (two device-local buffers of " + mib(o.copy_bandwidth.bytes) + ")");
  t.copy_bandwidth = measure_copy_bandwidth(device, o.copy_bandwidth);
  if (!t.copy_bandwidth.reduced_because.empty())
    say("copy bandwidth measured with buffers of " + mib(t.copy_bandwidth.bytes) + ": " +
        t.copy_bandwidth.reduced_because);

  say("timing " + (number != 0 ? "table " + std::to_string(number) + " (" + t.scene + ")" : "capture " + t.scene) +
      ": " + std::to_string(2 * o.generators.size()) + " cases");
  t.timing = time_capture(device, o, capture, [&](const TimingProgress& p) {
    if (on_event) on_event(TablesEvent{"", &p, number});
  });
  return out;
}

}  // namespace vsgl
