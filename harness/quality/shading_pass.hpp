#pragma once
// The shading pass (DESIGN.md §8 (a)): the camera view lit by a set of VSGLs, as a linear radiance
// image, so a user can look at what a generator produces (the 2016 paper's Fig. 5). Indirect light
// only: the spot light's direct contribution is left out. Visibility is one of three modes
// (ShadingVisibility): none (every VSGL reaches every receiver), the VSGLs' imperfect shadow maps,
// or exact visibility from each VSGL's mean through a BVH (the control).
//
// Output pixel (i, j) shades G-buffer texel (i k, j k) for an integer stride k >= 1 (k > 1: a
// quick preview of ceil(W / k) x ceil(H / k) pixels, for CPU drivers such as lavapipe). Its
// radiance toward the camera is sum_n V_n vsgl_radiance_surface(vsgl_n, P, N, wo, rho_d, rho_s,
// alpha) with wo = normalize(camera - P), summed in VSGL index order (V_n = 1 without visibility);
// pixels without geometry are black. GPU kernels: kernels/shade_vsgls*.comp; CPU twin:
// shade_pixel_reference() (same order, float32).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "harness/capture/capture.hpp"
#include "harness/math/vsgl_math.hpp"
#include "harness/quality/radiance_image.hpp"
#include "harness/vk/buffer.hpp"
#include "harness/vk/compute_pipeline.hpp"
#include "kernels/include/interface/shading.h"

namespace vsgl {

class CommandStream;
class Device;
class ImperfectShadowMaps;
class ShadingOccluders;
struct DeviceView;

// What the shading pass multiplies each VSGL's contribution by (DESIGN.md §8.1).
enum class ShadingVisibility {
  kNone,   // nothing: every VSGL reaches every receiver (kernels/shade_vsgls.comp)
  kIsm,    // the lookup of the VSGL's imperfect shadow map (shade_vsgls_ism.comp)
  kExact,  // the segment from the receiver to the VSGL's mean, traced through a BVH (shade_vsgls_exact.comp)
};

// What one shading pass applies visibility with: for kIsm the maps of exactly the VSGLs shaded,
// map n for VSGL n (shading_visibility.hpp builds them); for kExact the occluders on the device.
struct ShadeVisibility {
  ShadingVisibility mode = ShadingVisibility::kNone;
  const ImperfectShadowMaps* maps = nullptr;
  const ShadingOccluders* occluders = nullptr;
};

// The output extent for a G-buffer side and a stride: ceil(side / stride).
uint32_t shaded_extent(uint32_t side, uint32_t stride);

// At most this many VSGL evaluations (pixels x VSGLs) per dispatch. lavapipe on 2 loaded cores
// evaluates about 2e7 per second (the quality run's reference, DESIGN.md §11a), so a chunk takes
// 1-2 s there (a CPU driver has no watchdog); a discrete GPU does 1e10 or more, a few ms, far below
// the 2 s a Windows driver allows one submission (TDR), for any number of VSGLs (the converged
// reference has 10^5).
inline constexpr uint64_t kShadeEvaluationsPerDispatch = uint64_t{1} << 25;
// How many evaluations without visibility one evaluation with it may cost, by which its chunk is
// divided (DESIGN.md §8.1): an ISM lookup reads (2r + 1)^2 taps of the map (9 at the default r = 1);
// an exact one traverses the BVH, a few hundred box and triangle tests in a scene of 10^5
// triangles, each read from memory, where the closed form of sg_eval.glsl is a few hundred
// arithmetic operations on shared memory.
inline constexpr uint32_t kShadeIsmCostFactor = 4;
inline constexpr uint32_t kShadeExactCostFactor = 64;
uint32_t shade_cost_factor(ShadingVisibility mode);  // 1 for kNone
// VSGLs per dispatch for an image of `pixels`: kShadeEvaluationsPerDispatch / pixels rounded down
// to a whole tile of the kernel (kShadeGroupSize^2), at least one tile.
uint32_t shade_chunk_vsgls(uint64_t pixels);
// With visibility: kShadeEvaluationsPerDispatch / (pixels x the mode's cost factor), whole tiles
// where that is one or more, else as many VSGLs as fit, at least one (a traversal costs so much
// more than a tile's shared-memory load that a partial tile wastes nothing). kNone: as above.
uint32_t shade_chunk_vsgls(uint64_t pixels, ShadingVisibility mode);

// Shades the uploaded camera view (`camera.kind` must be kCamera; the camera position is its
// source_position) with the first `vsgl_count` records of `vsgls`, in chunks of
// `vsgls_per_dispatch` VSGLs (0: shade_chunk_vsgls), one submission each; the sum keeps the index
// order, so the image does not depend on the chunking. The records are bound `vsgls_per_binding`
// at a time (0: binding_window_vsgls's choice), so a reference of more VPLs than one binding of
// maxStorageBufferRange holds (2 million on lavapipe) still shades, to the same image. Throws
// InputError for a stride of 0, a light view, or a buffer holding fewer than `vsgl_count` records.
RadianceImage shade_camera_view(Device& device, const DeviceView& camera, const Buffer& vsgls, uint32_t vsgl_count,
                                uint32_t stride, uint32_t vsgls_per_dispatch = 0, uint32_t vsgls_per_binding = 0);
// The same with `visibility` (DESIGN.md §8.1): kNone is the call above, bit for bit. kIsm needs
// `visibility.maps` with one map per VSGL of the buffer (at least `vsgl_count`), kExact
// `visibility.occluders`; InputError otherwise. vsgls_per_dispatch 0: shade_chunk_vsgls(pixels, mode).
RadianceImage shade_camera_view(Device& device, const DeviceView& camera, const Buffer& vsgls, uint32_t vsgl_count,
                                uint32_t stride, const ShadeVisibility& visibility, uint32_t vsgls_per_dispatch = 0,
                                uint32_t vsgls_per_binding = 0);

// The shading pass set up once and recorded where the caller wants it: shade_camera_view submits
// each chunk on its own; `frame` records every chunk into its frame's command buffer (DESIGN.md
// §9.2). The arguments and their checks are shade_camera_view's; the VSGL buffer, the view and the
// maps must outlive it.
class ShadingRecording {
 public:
  ShadingRecording(Device& device, const DeviceView& camera, const Buffer& vsgls, uint32_t vsgl_count, uint32_t stride,
                   const ShadeVisibility& visibility, uint32_t vsgls_per_dispatch = 0, uint32_t vsgls_per_binding = 0);
  ~ShadingRecording();
  ShadingRecording(const ShadingRecording&) = delete;
  ShadingRecording& operator=(const ShadingRecording&) = delete;

  std::size_t chunk_count() const { return chunks_.size(); }
  // Exact visibility: answers chunk `index`'s segments (every pixel with a surface to each of its
  // VSGLs' means, RayVisibility) into the buffer its dispatch reads; call it before recording the
  // chunk, and submit the chunk before preparing the next. Nothing for the other modes.
  void prepare_chunk(std::size_t index) const;
  // A full barrier, then chunk `index`'s dispatch (the first chunk overwrites the image, the others add).
  void record_chunk(CommandStream& stream, std::size_t index) const;
  // Every chunk in order; InputError for exact visibility, whose chunks are prepared one by one.
  void record(CommandStream& stream) const;
  // The image the last recorded pass wrote, read back.
  RadianceImage read() const;
  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }

 private:
  struct Chunk {
    std::size_t set = 0;  // index into sets_
    gpu::ShadeVisibilityPush push;
    uint32_t first = 0, count = 0;  // its VSGLs, first..first + count - 1 of the buffer
  };
  Device* device_;
  ShadingVisibility mode_ = ShadingVisibility::kNone;
  uint32_t width_ = 0, height_ = 0;
  Buffer radiance_;
  // Exact visibility: the occluders, each output pixel's (position, valid), the VSGLs, and the
  // answers of the chunk being shaded.
  const ShadingOccluders* occluders_ = nullptr;
  std::vector<glm::vec4> positions_;
  std::vector<VsglRecord> records_;
  Buffer visible_;
  std::optional<ComputePipeline> pipeline_;
  std::vector<BindingSet> sets_;
  std::vector<Chunk> chunks_;
};

// VSGLs per binding of the shading pass: all `vsgl_count` where they fit `vsgls_per_binding` (0: the
// device's maxStorageBufferRange), else the most whole `chunk`s that fit and start at an offset the
// device can bind. Throws DeviceLimitError when not one chunk fits.
uint32_t binding_window_vsgls(const Device& device, uint32_t vsgl_count, uint32_t chunk, uint32_t vsgls_per_binding);

// The CPU twin of one output pixel: G-buffer texel (x, y) of `gbuffer`, seen from `camera_position`.
glm::vec4 shade_pixel_reference(const ViewImage& gbuffer, uint32_t x, uint32_t y, glm::vec3 camera_position,
                                const std::vector<VsglRecord>& vsgls);
// A VSGL's visibility from a receiver for the CPU twin: (VSGL index, receiver position P, its
// normal N) -> [0, 1] (shading_visibility.hpp: exact_visibility_reference).
using VsglVisibility = std::function<float(uint32_t vsgl, glm::vec3 P, glm::vec3 N)>;
// The twin with visibility, as the kernels with it apply it: each VSGL's contribution times
// `visibility`, asked only where the contribution is not zero.
glm::vec4 shade_pixel_reference(const ViewImage& gbuffer, uint32_t x, uint32_t y, glm::vec3 camera_position,
                                const std::vector<VsglRecord>& vsgls, const VsglVisibility& visibility);

}  // namespace vsgl
