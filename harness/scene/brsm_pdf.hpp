#pragma once
// The BRSM PDF of a capture's RSM (DESIGN.md §8, [REH*11] with the VSGL evaluation of [Tok15]):
// camera-view VSGLs made by fis_modified from the G-buffer (power = reflectance) light every RSM
// texel as shading lights a pixel (Tok15 Eq. 3), the texel's flux standing for its albedo. Built
// once when a capture is recorded, so every light-view generator consumes the same PDF.
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "harness/capture/capture.hpp"
#include "harness/math/fis_params.hpp"
#include "harness/math/vsgl_math.hpp"
#include "harness/vk/buffer.hpp"
#include "harness/vk/compute_pipeline.hpp"

namespace vsgl {

class CommandStream;
class Device;
struct DeviceView;

inline constexpr uint32_t kBrsmCameraVsgls = kPaperCameraVsgls;  // the paper's N for the camera view

struct BrsmBuild {
  double gpu_ms = 0;        // camera-view fis_modified + the BRSM pass, from timestamps
  uint32_t camera_vsgls = 0;
};

// The build's work on the device, set up once and recorded where the caller wants it: record
// submits it once; `frame` records it into every frame it times (DESIGN.md §9.2). `camera` is the
// capture's G-buffer uploaded, `rsm_layers` the RSM's four layers as a kernel binds them
// (DeviceView::layers, LayeredTexels::layers); both must outlive the pass.
class BrsmPdfPass {
 public:
  // min(camera_vsgls, samplable G-buffer texels) camera VSGLs, on the buffer path (bit-exact with
  // the CPU reference), else, where the device cannot bind its pyramid, the texture path (said on
  // stderr).
  BrsmPdfPass(Device& device, const Capture& capture, const DeviceView& camera, std::vector<BufferBinding> rsm_layers,
              uint32_t camera_vsgls = kBrsmCameraVsgls);
  ~BrsmPdfPass();
  BrsmPdfPass(const BrsmPdfPass&) = delete;
  BrsmPdfPass& operator=(const BrsmPdfPass&) = delete;

  // The camera view's fis_modified (its phases with full barriers between), then the BRSM pass
  // writing pdf(): one float per RSM texel, row-major.
  void record(CommandStream& stream);
  const Buffer& pdf() const;
  uint32_t camera_vsgls() const;
  PyramidPath pyramid() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// Fills capture.rsm's PDF plane (has_pdf = true), capture.meta.brsm_build_ms and brsm_pyramid. Uses
// min(kBrsmCameraVsgls, samplable G-buffer texels) camera VSGLs. Throws InputError when the
// result is all zero (no lit texel is seen by the camera).
BrsmBuild build_brsm_pdf(Device& device, Capture& capture, uint32_t camera_vsgls = kBrsmCameraVsgls);

// The CPU twin of one texel's weight (kernels/include/brsm_importance.glsl), for tests and verify.
float brsm_texel_weight(const ViewImage& rsm, uint32_t x, uint32_t y, glm::vec3 light_position,
                        const std::vector<VsglRecord>& camera_vsgls);

}  // namespace vsgl
