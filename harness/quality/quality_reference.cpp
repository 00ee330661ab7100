#include "harness/quality/quality_reference.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "harness/vk/command_stream.hpp"
#include "harness/vk/device.hpp"
#include "harness/core/error.hpp"
#include "harness/capture/view_matrices.hpp"

namespace vsgl {

float rsm_texel_world_area(const ViewImage& rsm, const SpotLightDesc& light, uint32_t x, uint32_t y, uint32_t stride) {
  const glm::vec3 P(rsm.at(kPX, x, y), rsm.at(kPY, x, y), rsm.at(kPZ, x, y));
  const glm::vec3 N(rsm.at(kNX, x, y), rsm.at(kNY, x, y), rsm.at(kNZ, x, y));
  const glm::vec3 to_texel = P - light.position;
  const float d2 = glm::dot(to_texel, to_texel);
  const glm::vec3 dir = to_texel / std::sqrt(d2);
  const float cos_axis = std::max(glm::dot(dir, glm::normalize(light.direction)), 0.0f);
  const float solid_angle = rsm_texel_area(light, rsm.width) * static_cast<float>(stride) * static_cast<float>(stride) *
                            cos_axis * cos_axis * cos_axis;
  const float cos_surface = std::max(std::abs(glm::dot(N, dir)), 0.1f);
  return solid_angle * d2 / cos_surface;
}

std::vector<VsglRecord> reference_vpls(const ViewImage& rsm, const SpotLightDesc& light, uint32_t stride,
                                       VplExtent extent, VplSet set) {
  const glm::vec3 light_position = light.position;
  if (stride == 0) throw InputError("reference: the RSM stride must be at least 1");
  if (rsm.kind != ViewKind::kLight) throw InputError("reference: VPLs come from the RSM (light view)");
  const float area = static_cast<float>(stride) * static_cast<float>(stride);
  std::vector<VsglRecord> vpls;
  for (uint32_t y = 0; y < rsm.height; y += stride)
    for (uint32_t x = 0; x < rsm.width; x += stride) {
      if (rsm.at(kValid, x, y) <= 0.5f) continue;
      if (set == VplSet::kPdfSupport && !(rsm.at(kPdf, x, y) > 0.0f)) continue;
      const glm::vec3 P(rsm.at(kPX, x, y), rsm.at(kPY, x, y), rsm.at(kPZ, x, y));
      const glm::vec3 N(rsm.at(kNX, x, y), rsm.at(kNY, x, y), rsm.at(kNZ, x, y));
      const glm::vec3 d(rsm.at(kDR, x, y), rsm.at(kDG, x, y), rsm.at(kDB, x, y));
      const glm::vec3 s(rsm.at(kSR, x, y), rsm.at(kSG, x, y), rsm.at(kSB, x, y));
      const glm::vec3 flux = d + s;
      if (!(flux.r + flux.g + flux.b > 0.0f)) continue;
      const TexelMoments m =
          texel_moments(true, P, N, d, s, rsm.at(kRoughness, x, y), 1.0f, light_position, /*camera_view=*/false);
      const glm::vec2 centre((static_cast<float>(x) + 0.5f) / static_cast<float>(rsm.width),
                             (static_cast<float>(y) + 0.5f) / static_cast<float>(rsm.height));
      VsglRecord v = vsgl_from_moments(m, area, 0.0f, centre, 1.0f, 1.0f);
      // Tok15's sigma^2 = E|x|^2 - |E x|^2 of a uniform square of area A: A / 12 on each of its two axes.
      const float sigma2 = extent == VplExtent::kPoint
                               ? kMinVariance
                               : std::max(rsm_texel_world_area(rsm, light, x, y, stride) / 6.0f, kMinVariance);
      v.position_variance = glm::vec4(P, sigma2);
      vpls.push_back(v);
    }
  if (vpls.empty())
    throw InputError(std::string("reference: the RSM has no ") +
                     (set == VplSet::kAllLit ? "lit texel" : "lit texel with PDF > 0") + " at stride " +
                     std::to_string(stride));
  return vpls;
}

uint32_t reference_stride(const ViewImage& rsm, uint32_t side) {
  const uint32_t longest = rsm.width > rsm.height ? rsm.width : rsm.height;
  return side == 0 || longest <= side ? 1u : longest / side;
}

bool reference_decides(double reference_own_error, double judged_difference) {
  if (!std::isfinite(reference_own_error) || !std::isfinite(judged_difference)) return false;
  return kReferenceErrorFactor * reference_own_error < std::abs(judged_difference);
}

FixedVsglGenerator::FixedVsglGenerator(Device& device, const std::vector<VsglRecord>& vsgls, std::string name)
    : name_(std::move(name)), count_(static_cast<uint32_t>(vsgls.size())) {
  if (vsgls.empty()) throw InputError(name_ + ": no VSGLs");
  buffer_ = Buffer(device, vsgls.size() * sizeof(VsglRecord), MemoryUsage::kDeviceLocal, name_ + ".vsgls");
  upload(device, buffer_, vsgls.data(), vsgls.size() * sizeof(VsglRecord));
}

void FixedVsglGenerator::record(CommandStream& stream, const std::function<void(VkCommandBuffer)>& boundary) {
  boundary(stream.get());  // no phase: the records were uploaded at construction
}

}  // namespace vsgl
