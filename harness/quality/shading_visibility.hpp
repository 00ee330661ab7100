#pragma once
// Visibility for the shading pass (DESIGN.md §8.1): the glue between
// a capture's stored visibility geometry (capture/visibility_geometry.hpp: its triangles and their
// point sampling) and the visibility layer (§8a), which may not use the capture layer. ism: one
// imperfect shadow map per VSGL shaded, about its mean and filtered normal, splatted from the
// capture's points; exact (the control): the capture's triangles in a BVH on the device, traced by
// the shading kernel from each pixel to each VSGL's mean.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "harness/capture/visibility_geometry.hpp"
#include "harness/quality/shading_pass.hpp"
#include "harness/visibility/bvh.hpp"
#include "harness/visibility/ism_settings.hpp"
#include "harness/visibility/ray_visibility.hpp"
#include "harness/visibility/triangle_soup.hpp"
#include "harness/vk/buffer.hpp"

namespace vsgl {

class Device;
struct DeviceView;

// "none", "ism", "exact": the names `shade --visibility` takes.
std::string shading_visibility_name(ShadingVisibility mode);
// The mode of a name; InputError naming the three for any other.
ShadingVisibility parse_shading_visibility(const std::string& name);

struct ShadingVisibilitySettings {
  ShadingVisibility mode = ShadingVisibility::kNone;
  IsmSettings ism;  // kIsm: the maps' side, points per map, biases and PCF (defaults: interface/ism.h)
};

// What every output that shades says of its visibility: "no visibility (indirect light only)",
// "visibility ism (...: its settings)" or "visibility exact (...)".
std::string shading_visibility_text(const ShadingVisibilitySettings& settings);

// The capture's triangles as the visibility layer's soup.
TriangleSoup visibility_soup(const VisibilityGeometry& geometry);

// Exact visibility ignores crossings within epsilon of either end of a segment (§8a.1) so that a
// receiver, or a VSGL's mean, lying on a surface does not shadow itself: epsilon is this fraction
// of the diagonal of the soup's bounding box (a scene in any unit gets the same relative margin),
// far above the rounding of rasterized positions (a few 1e-7 of the coordinates).
inline constexpr float kExactVisibilityEpsilon = 1e-4f;
// kExactVisibilityEpsilon times the soup's bounding-box diagonal (0 for an empty soup).
float exact_visibility_epsilon(const TriangleSoup& soup);

// The occluders of the exact variant on the device: the BVH over the soup, its nodes and triangles
// uploaded once (in a RayVisibility), for every shading pass of a run. The shading pass asks it
// which of its pixel-to-mean segments are blocked, chunk by chunk (shading_pass.cpp), with queries
// the host makes as the CPU twin does: the BVH walk inlined in the shading kernel was miscompiled
// by lavapipe (ShadeVisibilityTest.ExactWithManyReferenceVplsMatchesTheCpuTwin), the separate
// segment kernel answers as the CPU does, bit for bit.
class ShadingOccluders {
 public:
  // Builds the BVH, checks its buffers against the device's limits (require_bvh_buffers_fit:
  // DeviceLimitError naming the limit, before anything is allocated), then uploads them.
  ShadingOccluders(Device& device, TriangleSoup soup);
  ShadingOccluders(Device& device, TriangleSoup soup, const VisibilityLimits& limits);

  const TriangleSoup& soup() const { return soup_; }
  const Bvh& bvh() const { return bvh_; }
  float epsilon() const { return epsilon_; }
  uint32_t node_count() const { return static_cast<uint32_t>(bvh_.nodes.size()); }  // 0: nothing occludes
  // 1 where segment n is clear, 0 where a triangle blocks it (RayVisibility::visible).
  std::vector<uint32_t> visible(std::span<const gpu::SegmentQuery> queries) const { return rays_->visible(queries); }

 private:
  TriangleSoup soup_;
  Bvh bvh_;
  float epsilon_ = 0.0f;
  mutable std::optional<RayVisibility> rays_;
};

// The CPU twin's exact visibility (shade_pixel_reference): 0 where segment_occluded finds a triangle
// of the occluders' soup on the segment from the receiver to VSGL n's mean (with their epsilon), 1
// elsewhere; the shading pass asks the segment kernel the same queries (make_segment_query).
VsglVisibility exact_visibility_reference(const ShadingOccluders& occluders, const std::vector<VsglRecord>& vsgls);

// Shades camera views with one visibility mode, holding what it needs across the views and VSGL
// sets of a run: for kExact the occluders (built once), for kIsm the capture's points (each set of
// VSGLs gets its own maps).
class VisibleShading {
 public:
  // kNone ignores `geometry` (it may be null); kIsm and kExact need it (InputError otherwise).
  // kExact builds and uploads the BVH here (DeviceLimitError where it does not fit).
  VisibleShading(Device& device, const ShadingVisibilitySettings& settings, const VisibilityGeometry* geometry);

  // kIsm: checks the maps of `map_count` VSGLs against the settings and the capture's points
  // (InputError; more points per map than the capture holds names the options of `record` and
  // `shade` that set them) and against the device's limits (DeviceLimitError) without building them.
  void require_maps_fit(uint32_t map_count) const;

  // shade_camera_view with the first `vsgl_count` records of `vsgls` and this visibility; kIsm
  // builds their maps first (from the records read back: their means and filtered normals).
  RadianceImage shade(const DeviceView& camera, const Buffer& vsgls, uint32_t vsgl_count, uint32_t stride,
                      uint32_t vsgls_per_dispatch = 0);

  const ShadingVisibilitySettings& settings() const { return settings_; }
  const ShadingOccluders* occluders() const { return occluders_ ? &*occluders_ : nullptr; }

 private:
  Device& device_;
  ShadingVisibilitySettings settings_;
  const VisibilityGeometry* geometry_ = nullptr;
  std::optional<ShadingOccluders> occluders_;
};

}  // namespace vsgl
