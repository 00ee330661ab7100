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
  // Points of the visibility geometry the capture stores (DESIGN.md §3, §8a): 0 stores none. The
  // library records none unless asked; `record` asks for kDefaultVisibilityPoints.
  uint32_t visibility_points = 0;
};

// 2^20 points (28 MiB in the capture): 128 disjoint subsets of the ISM's 8192 points per map, so
// the paper's 1024 maps share each subset among 8 (DESIGN.md §8a.2).
inline constexpr uint32_t kDefaultVisibilityPoints = 1u << 20;
// The seed every capture's point sampling is drawn with: the same scene gives the same points.
inline constexpr uint64_t kVisibilityPointSeed = 0x5653474c56495331ull;

class CaptureRecorder {
 public:
  explicit CaptureRecorder(Device& device);
  // The RSM has no BRSM PDF yet (has_pdf = false): it is built from camera VSGLs afterwards.
  Capture record(const Scene& scene, const RecordSizes& sizes, uint32_t frame, uint32_t frames);

 private:
  Device& device_;
};

}  // namespace vsgl
