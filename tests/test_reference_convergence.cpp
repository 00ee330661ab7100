// The VPL reference converges (DESIGN.md §11a): a synthetic RSM of a lit floor and wall, made the
// way the recorder makes one (flux = I dOmega rho, dOmega = texel area on the unit image plane x
// cos^3), turned into single-texel VSGLs by reference_vpls() and shaded on the CPU twin of the
// shading pass at fixed receivers on both surfaces. Over four differences of five rungs, each
// doubling of the RSM side must shrink the difference to the next rung, by 0.6 or less per
// doubling on average. With the cosines as SGs that stay
// non-zero at 90 degrees (the suite before Tok15 Eq. 3), a lit plane lit itself with a 1/d^2 tail
// and the difference fell only about 0.9 per doubling.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "harness/capture/view_matrices.hpp"
#include "harness/math/vsgl_math.hpp"
#include "harness/quality/quality_reference.hpp"

namespace vsgl {
namespace {

// The corner of a floor (y = 0, x in [0, 4], z in [-3, 3]) and a wall (x = 0, y in [0, 4]), lit by a
// spot above the floor aimed at the corner. Its intensity falls smoothly to zero at the cone's
// edge, so that the test measures the near field of the corner, not the aliasing of a hard edge.
SpotLightDesc corner_light() {
  SpotLightDesc l;
  l.position = {1.6f, 1.8f, 0.0f};
  l.direction = glm::normalize(glm::vec3(-0.55f, -1.0f, 0.0f));
  l.up = {0.0f, 0.0f, -1.0f};
  l.cone_half_angle_deg = 55.0f;
  l.intensity = glm::vec3(10.0f);
  return l;
}

// The RSM of the corner at side n: each texel's ray from the spot through its image-plane centre,
// hitting the floor or the wall (whichever is nearer and inside the room's bounds).
ViewImage corner_rsm(const SpotLightDesc& l, uint32_t n) {
  ViewImage v;
  v.resize(ViewKind::kLight, n, n);
  v.has_pdf = false;
  const glm::vec3 f = glm::normalize(l.direction);
  const glm::vec3 right = glm::normalize(glm::cross(f, l.up));
  const glm::vec3 up = glm::cross(right, f);
  const float t = std::tan(glm::radians(l.cone_half_angle_deg));
  const float texel = rsm_texel_area(l, n);
  for (uint32_t y = 0; y < n; ++y)
    for (uint32_t x = 0; x < n; ++x) {
      const float u = (2.0f * (static_cast<float>(x) + 0.5f) / static_cast<float>(n) - 1.0f) * t;
      const float w = (1.0f - 2.0f * (static_cast<float>(y) + 0.5f) / static_cast<float>(n)) * t;
      const glm::vec3 ray = f + u * right + w * up;
      const glm::vec3 dir = glm::normalize(ray);
      float best = 1e30f;
      glm::vec3 P(0.0f), N(0.0f);
      glm::vec3 albedo(0.0f);
      if (dir.y < 0.0f) {  // the floor
        const float s = -l.position.y / dir.y;
        const glm::vec3 h = l.position + s * dir;
        if (h.x >= 0.0f && h.x <= 4.0f && std::abs(h.z) <= 3.0f && s < best) {
          best = s, P = h, N = {0.0f, 1.0f, 0.0f}, albedo = {0.7f, 0.6f, 0.5f};
        }
      }
      if (dir.x < 0.0f) {  // the wall
        const float s = -l.position.x / dir.x;
        const glm::vec3 h = l.position + s * dir;
        if (h.y >= 0.0f && h.y <= 4.0f && std::abs(h.z) <= 3.0f && s < best) {
          best = s, P = h, N = {1.0f, 0.0f, 0.0f}, albedo = {0.3f, 0.6f, 0.8f};
        }
      }
      if (best == 1e30f) continue;
      const float cos_axis = glm::dot(dir, f);
      const float edge = std::acos(std::min(cos_axis, 1.0f)) / glm::radians(l.cone_half_angle_deg);
      if (edge >= 1.0f) continue;
      const float falloff = (1.0f - edge * edge) * (1.0f - edge * edge);
      const glm::vec3 flux =
          l.intensity * falloff * texel * cos_axis * cos_axis * cos_axis * std::max(glm::dot(N, -dir), 0.0f);
      v.at(kValid, x, y) = 1.0f;
      v.at(kPX, x, y) = P.x, v.at(kPY, x, y) = P.y, v.at(kPZ, x, y) = P.z;
      v.at(kNX, x, y) = N.x, v.at(kNY, x, y) = N.y, v.at(kNZ, x, y) = N.z;
      v.at(kDR, x, y) = flux.r * albedo.r, v.at(kDG, x, y) = flux.g * albedo.g, v.at(kDB, x, y) = flux.b * albedo.b;
      // A little gloss, so the specular lobes and both branches of the evaluation take part.
      v.at(kSR, x, y) = v.at(kSG, x, y) = v.at(kSB, x, y) = 0.04f * flux.r;
      v.at(kRoughness, x, y) = 0.4f;
    }
  return v;
}

struct Receiver {
  glm::vec3 x, n;
};

// Receivers on both surfaces, clear of the corner by 0.1 and more (the rungs resolve them).
std::vector<Receiver> receivers() {
  std::vector<Receiver> out;
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 8; ++k) {
      const float a = 0.1f + 0.2f * static_cast<float>(i), b = -0.7f + 0.2f * static_cast<float>(k);
      out.push_back({{a, 0.0f, b}, {0.0f, 1.0f, 0.0f}});
      out.push_back({{0.0f, a, b}, {1.0f, 0.0f, 0.0f}});
    }
  return out;
}

std::vector<glm::dvec3> shade(const std::vector<VsglRecord>& vpls, const std::vector<Receiver>& at) {
  const glm::vec3 eye(3.0f, 1.5f, 0.3f);
  std::vector<glm::dvec3> out;
  for (const Receiver& r : at) {
    glm::dvec3 sum(0.0);
    const glm::vec3 wo = glm::normalize(eye - r.x);
    for (const VsglRecord& v : vpls)
      sum += glm::dvec3(vsgl_radiance_surface(v, r.x, r.n, wo, glm::vec3(0.5f), glm::vec3(0.04f), 0.3f));
    out.push_back(sum);
  }
  return out;
}

double relative_rmse(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
  double num = 0, den = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const glm::dvec3 d = a[i] - b[i];
    num += glm::dot(d, d);
    den += glm::dot(b[i], b[i]);
  }
  return std::sqrt(num / den);
}

TEST(ReferenceConvergence, LitFloorAndWallConvergeFasterThan06PerDoubling) {
  const SpotLightDesc light = corner_light();
  const std::vector<Receiver> at = receivers();
  std::vector<std::vector<glm::dvec3>> rungs;
  for (uint32_t n : {24u, 48u, 96u, 192u, 384u})
    rungs.push_back(shade(reference_vpls(corner_rsm(light, n), light, 1, VplExtent::kTexelFootprint), at));
  // The light reaches both surfaces' receivers.
  double mean = 0;
  for (const glm::dvec3& L : rungs.back()) mean += L.r + L.g + L.b;
  ASSERT_GT(mean, 0.0);
  std::vector<double> own;  // each rung against the next
  for (std::size_t k = 0; k + 1 < rungs.size(); ++k) own.push_back(relative_rmse(rungs[k], rungs[k + 1]));
  // Every doubling brings the rungs closer, and the rate per doubling over the four differences --
  // their geometric mean, the rate DESIGN.md §11a's rule reads -- is below 0.6. Single ratios
  // scatter (measured 0.38, 0.71, 0.14): where the texel centres fall against the receivers
  // changes from rung to rung.
  for (std::size_t k = 0; k + 1 < own.size(); ++k) {
    SCOPED_TRACE("rung " + std::to_string(k));
    EXPECT_GT(own[k], 0.0);
    EXPECT_LT(own[k + 1], own[k]);
  }
  const double rate = std::pow(own.back() / own.front(), 1.0 / static_cast<double>(own.size() - 1));
  EXPECT_LT(rate, 0.6) << "differences " << own[0] << ", " << own[1] << ", " << own[2] << ", " << own[3];
}

}  // namespace
}  // namespace vsgl
