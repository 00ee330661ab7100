#pragma once
// Imperfect shadow maps (DESIGN.md §8a.2; Ritschel et al. 2008), built in compute: one paraboloid
// depth map per VSGL about its mean position and filtered normal, each splatted from its own
// subset of a point sampling of the scene and its holes filled by pull-push. Kernels:
// kernels/ism_splat.comp, ism_pull.comp, ism_push.comp; the lookup that shading reads them with:
// kernels/include/ism_lookup.glsl. All maps live in one storage buffer (interface/ism.h's layout),
// which every Vulkan device binds, including lavapipe and SwiftShader.
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "harness/math/vsgl_math.hpp"
#include "harness/visibility/ism_settings.hpp"
#include "harness/visibility/point_sampling.hpp"
#include "harness/vk/buffer.hpp"
#include "kernels/include/interface/ism.h"

namespace vsgl {

class CommandStream;
class Device;

// Where a map looks from: a point and the axis of its hemisphere.
struct IsmMapOrigin {
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f, 0.0f, 1.0f};
};

// A VSGL's map origin: its mean position and its filtered normal (DESIGN.md §7).
std::vector<IsmMapOrigin> map_origins(const std::vector<VsglRecord>& vsgls);

class ImperfectShadowMaps {
 public:
  // Uploads the points and origins, checks the sizes against the device (ism_settings.hpp), and
  // builds every map: clear, splat, and unless settings.fill_holes is false pull-push, in one
  // submission. Throws InputError for unusable settings or origins (a non-finite position, a
  // normal that is not unit length), DeviceLimitError where the maps do not fit the device.
  ImperfectShadowMaps(Device& device, const std::vector<SurfacePoint>& points, const std::vector<IsmMapOrigin>& origins,
                      const IsmSettings& settings = {});
  ~ImperfectShadowMaps();
  ImperfectShadowMaps(ImperfectShadowMaps&&) noexcept;
  ImperfectShadowMaps& operator=(ImperfectShadowMaps&&) noexcept;

  // Records the build again into `stream` (clear, splat, pull-push as the constructor ran it),
  // after a full barrier: `frame` times it as the frame's ism phase (DESIGN.md §9.2).
  void record_build(CommandStream& stream) const;

  const gpu::IsmParams& params() const { return params_; }
  const Buffer& maps() const { return maps_; }        // map_count x map_stride uints (interface/ism.h)
  const Buffer& origins() const { return origins_; }  // map_count gpu::IsmOrigin
  uint32_t map_count() const { return params_.map_count; }
  uint32_t side() const { return params_.side; }
  uint32_t dispatch_count() const { return dispatches_; }  // the build's dispatches (1 + 2 log2(side) with fill)

  // Level 0 of every map read back, map after map, row-major (y * side + x): the distance to the
  // map's origin, +infinity where the texel is empty.
  std::vector<float> read_level0() const;

 private:
  struct Kernels;  // the build's pipelines and binding sets, kept for record_build

  Device* device_;
  gpu::IsmParams params_{};
  Buffer points_;
  Buffer origins_;
  Buffer maps_;
  uint32_t dispatches_ = 0;
  bool fill_holes_ = true;
  std::unique_ptr<Kernels> kernels_;
};

}  // namespace vsgl
