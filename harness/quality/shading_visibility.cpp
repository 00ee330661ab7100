#include "harness/quality/shading_visibility.hpp"

#include <cmath>
#include <sstream>
#include <utility>

#include "harness/core/error.hpp"
#include "harness/generators/device_view.hpp"
#include "harness/visibility/imperfect_shadow_maps.hpp"
#include "harness/visibility/segment_query.hpp"
#include "harness/vk/device.hpp"

namespace vsgl {

std::string shading_visibility_name(ShadingVisibility mode) {
  switch (mode) {
    case ShadingVisibility::kIsm: return "ism";
    case ShadingVisibility::kExact: return "exact";
    case ShadingVisibility::kNone: break;
  }
  return "none";
}

ShadingVisibility parse_shading_visibility(const std::string& name) {
  for (ShadingVisibility m : {ShadingVisibility::kNone, ShadingVisibility::kIsm, ShadingVisibility::kExact})
    if (shading_visibility_name(m) == name) return m;
  throw InputError("visibility '" + name + "' is none of none, ism, exact");
}

std::string shading_visibility_text(const ShadingVisibilitySettings& s) {
  std::ostringstream out;
  switch (s.mode) {
    case ShadingVisibility::kNone: out << "no visibility (indirect light only)"; break;
    case ShadingVisibility::kIsm:
      out << "visibility ism (imperfect shadow maps of " << s.ism.side << "x" << s.ism.side << ", "
          << s.ism.points_per_map << " points per map, depth bias " << s.ism.depth_bias << ", normal offset "
          << s.ism.normal_offset << " texels, PCF radius " << s.ism.pcf_radius << ")";
      break;
    case ShadingVisibility::kExact:
      out << "visibility exact (the segment to each VSGL's mean through a BVH of the scene's triangles, epsilon "
          << kExactVisibilityEpsilon << " of the scene's diagonal)";
      break;
  }
  return out.str();
}

TriangleSoup visibility_soup(const VisibilityGeometry& geometry) { return TriangleSoup{geometry.triangle_vertices}; }

float exact_visibility_epsilon(const TriangleSoup& soup) {
  if (soup.vertices.empty()) return 0.0f;
  glm::vec3 lo = soup.vertices.front(), hi = lo;
  for (const glm::vec3& v : soup.vertices) {
    lo = glm::min(lo, v);
    hi = glm::max(hi, v);
  }
  return kExactVisibilityEpsilon * glm::length(hi - lo);
}

ShadingOccluders::ShadingOccluders(Device& device, TriangleSoup soup)
    : ShadingOccluders(device, std::move(soup), visibility_limits(device.info())) {}

ShadingOccluders::ShadingOccluders(Device& device, TriangleSoup soup, const VisibilityLimits& limits)
    : soup_(std::move(soup)), bvh_(build_bvh(soup_)), epsilon_(exact_visibility_epsilon(soup_)) {
  const std::vector<gpu::BvhTriangle> triangles = bvh_triangles(bvh_, soup_);
  require_bvh_buffers_fit(limits, bvh_.nodes.size() * sizeof(gpu::BvhNode), triangles.size() * sizeof(gpu::BvhTriangle),
                          device.info().name);
  rays_.emplace(device, bvh_, soup_, limits);
}

VsglVisibility exact_visibility_reference(const ShadingOccluders& occluders, const std::vector<VsglRecord>& vsgls) {
  return [&occluders, &vsgls](uint32_t n, glm::vec3 P, glm::vec3) {
    const gpu::SegmentQuery q = make_segment_query(P, vsgls.at(n).mu(), occluders.epsilon());
    return segment_occluded(occluders.bvh(), occluders.soup(), q) ? 0.0f : 1.0f;
  };
}

VisibleShading::VisibleShading(Device& device, const ShadingVisibilitySettings& settings,
                               const VisibilityGeometry* geometry)
    : device_(device), settings_(settings), geometry_(geometry) {
  if (settings_.mode == ShadingVisibility::kNone) return;
  if (geometry_ == nullptr)
    throw InputError("shading with visibility " + shading_visibility_name(settings_.mode) +
                     " needs the capture's visibility geometry (record it with --visibility-points above 0, or "
                     "shade with --visibility none)");
  if (settings_.mode == ShadingVisibility::kExact) occluders_.emplace(device_, visibility_soup(*geometry_));
}

void VisibleShading::require_maps_fit(uint32_t map_count) const {
  if (settings_.mode != ShadingVisibility::kIsm) return;
  if (settings_.ism.points_per_map > geometry_->points.size())
    throw InputError("imperfect shadow maps: " + std::to_string(settings_.ism.points_per_map) +
                     " points per map, but the capture holds " + std::to_string(geometry_->points.size()) +
                     " (record it with more --visibility-points, or give fewer --ism-points-per-map)");
  const gpu::IsmParams params = ism_params(settings_.ism, static_cast<uint32_t>(geometry_->points.size()), map_count);
  require_ism_fits(device_.info().limits, params, device_.info().name);
}

RadianceImage VisibleShading::shade(const DeviceView& camera, const Buffer& vsgls, uint32_t vsgl_count, uint32_t stride,
                                    uint32_t vsgls_per_dispatch) {
  ShadeVisibility visibility;
  visibility.mode = settings_.mode;
  if (settings_.mode == ShadingVisibility::kExact) {
    visibility.occluders = &*occluders_;
    return shade_camera_view(device_, camera, vsgls, vsgl_count, stride, visibility, vsgls_per_dispatch);
  }
  if (settings_.mode == ShadingVisibility::kIsm) {
    if (vsgls.size() < VkDeviceSize{vsgl_count} * sizeof(VsglRecord))
      throw InputError("shading pass: the VSGL buffer '" + vsgls.name() + "' holds fewer than " +
                       std::to_string(vsgl_count) + " records");
    // The maps of exactly these VSGLs, in their order (map n about VSGL n's mean and filtered normal).
    const std::vector<VsglRecord> records = download_vector<VsglRecord>(device_, vsgls, vsgl_count);
    const ImperfectShadowMaps maps(device_, geometry_->points, map_origins(records), settings_.ism);
    visibility.maps = &maps;
    return shade_camera_view(device_, camera, vsgls, vsgl_count, stride, visibility, vsgls_per_dispatch);
  }
  return shade_camera_view(device_, camera, vsgls, vsgl_count, stride, visibility, vsgls_per_dispatch);
}

}  // namespace vsgl
