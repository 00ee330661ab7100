#include "harness/sweep/sweep_capture_cache.hpp"

#include "harness/core/path_text.hpp"
#include "harness/capture/capture_files.hpp"

namespace vsgl {
namespace {

bool same_sizes(const RecordSizes& a, const RecordSizes& b) {
  return a.gbuffer_width == b.gbuffer_width && a.gbuffer_height == b.gbuffer_height && a.rsm_size == b.rsm_size;
}

}  // namespace

std::filesystem::path sweep_capture_dir(const std::filesystem::path& root, const std::string& scene,
                                        const RecordSizes& s) {
  return root / (scene + "-g" + std::to_string(s.gbuffer_width) + "x" + std::to_string(s.gbuffer_height) + "-r" +
                 std::to_string(s.rsm_size));
}

SweepCaptureCache::SweepCaptureCache(Device& device, const SweepOptions& options) : device_(device), options_(options) {
  if (!options.scene.empty()) scene_ = load_named_scene(options.scene, options.scenes);
}

const Capture& SweepCaptureCache::at(const RecordSizes& sizes, std::size_t point, const SweepLog& log) {
  if (held_sizes_ && same_sizes(*held_sizes_, sizes)) return held_.capture;
  held_sizes_.reset();  // until this size's capture is held
  if (options_.capture) {
    held_ = ProvidedCapture{load_capture(*options_.capture), false, {}};  // every hash checked
  } else {
    const std::filesystem::path dir = sweep_capture_dir(options_.captures_dir, options_.scene, sizes);
    held_ = provide_capture(device_, *scene_, sizes, dir);
    if (!held_.stale_because.empty())
      log.say("re-recorded the stale capture " + path_text(dir) + ": " + held_.stale_because, point);
    else if (held_.recorded) log.say("recorded the capture " + path_text(dir), point);
  }
  held_sizes_ = sizes;
  return held_.capture;
}

std::string SweepCaptureCache::dir(const RecordSizes& sizes) const {
  return options_.capture ? options_.capture->string()
                          : sweep_capture_dir(options_.captures_dir, options_.scene, sizes).string();
}

}  // namespace vsgl
