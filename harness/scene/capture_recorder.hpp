#pragma once
// Records a capture (DESIGN.md §3) with a real Vulkan graphics pipeline: scene.vert + capture.frag,
// depth test, five RGBA32F render targets, one pass from the camera (G-buffer) and one from the
// spot light (RSM). Deterministic: the same scene and sizes give identical bytes on one device.
#include <cstdint>
#include <string>

#include "harness/capture/capture.hpp"
#include "harness/scene/scene.hpp"

namespace vsgl {

class Device;

struct RecordSizes {
  uint32_t gbuffer_width = 1920;
  uint32_t gbuffer_height = 1088;
  uint32_t rsm_size = 512;
};

class CaptureRecorder {
 public:
  explicit CaptureRecorder(Device& device);
  // The RSM has no BRSM PDF yet (has_pdf = false): it is built from camera VSGLs afterwards.
  Capture record(const Scene& scene, const RecordSizes& sizes, uint32_t frame, uint32_t frames);

 private:
  Device& device_;
};

}  // namespace vsgl
