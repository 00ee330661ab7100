// The GLSL VSGL maths (kernels/include/vsgl_math.glsl, sg_eval.glsl, run by the test-only kernel
// kernels/test_vsgl_math.comp) against their C++ twins (harness/math/vsgl_math.hpp), on a batch of
// generated cases including the edge cases (invalid texels, empty moments, a receiver on the
// VSGL, tiny radii, every branch of A(lambda) and of the SG integral). DESIGN.md §11: "VSGL evaluation
// matches its CPU twin".
//
// Tolerance: |gpu - cpu| <= 1e-4 * max(|gpu|, |cpu|) + floor. Vulkan lets exp/log/inversesqrt
// err by a few ulp and lets the compiler fuse multiply-adds, so float results differ in the last
// bits; the floor covers what that does to ill-conditioned outputs, each stated where it is used:
// sums with cancellation (moments, mu, sigma^2) get a floor relative to the size of the terms,
// lambda one that allows a 2e-6 relative change of r (Banerjee's lambda(r) is steep near r = 1),
// and every output 1e-30 absolute (a GPU may flush denormals to zero).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "gpu_test.hpp"
#include "harness/vk/buffer.hpp"
#include "harness/vk/command_stream.hpp"
#include "harness/vk/compute_pipeline.hpp"
#include "harness/math/vsgl_math.hpp"
#include "kernels/include/interface/testing.h"

namespace vsgl {
namespace {

using test::GpuTest;

// std430 twins of TwinCase / TwinResult in kernels/test_vsgl_math.comp.
struct TwinCase {
  glm::vec4 position_valid{0.0f};
  glm::vec4 normal_camera{0.0f};
  glm::vec4 diffuse_pdf{0.0f};
  glm::vec4 specular_roughness{0.0f};
  glm::vec4 source{0.0f};
  glm::vec4 moment0{0.0f};
  glm::vec4 moment1{0.0f};
  glm::vec4 moment2{0.0f};
  glm::vec4 moment3{0.0f};
  glm::vec4 moment4{0.0f};
  glm::vec4 scale_level{0.0f};
  glm::vec4 center_extra{0.0f};
  glm::vec4 receiver_position{0.0f};
  glm::vec4 receiver_normal{0.0f};
  glm::vec4 receiver_wo{0.0f};
  glm::vec4 rho_d{0.0f};
  glm::vec4 rho_s{0.0f};
  glm::vec4 texel_light{0.0f};
  glm::vec4 scalars{0.0f};
};
static_assert(sizeof(TwinCase) == 19 * 16);

struct TwinResult {
  glm::vec4 m0, m1, m2, m3, m4;
  VsglRecord vsgl;
  glm::vec4 radiance_importance;
  glm::vec4 scalars;
};
static_assert(sizeof(TwinResult) == 13 * 16);

constexpr float kAbsoluteFloor = 1e-30f;
constexpr float kRelative = 1e-4f;

// A deterministic stream of floats in [0, 1).
class Stream {
 public:
  explicit Stream(uint32_t seed) : state_(seed) {}
  float next() {
    state_ = state_ * 747796405u + 2891336453u;
    uint32_t w = ((state_ >> ((state_ >> 28u) + 4u)) ^ state_) * 277803737u;
    w = (w >> 22u) ^ w;
    return static_cast<float>(w >> 8) * 0x1p-24f;
  }
  float range(float lo, float hi) { return lo + (hi - lo) * next(); }
  float log_range(float lo, float hi) { return lo * std::pow(hi / lo, next()); }
  glm::vec3 vec(float lo, float hi) { return {range(lo, hi), range(lo, hi), range(lo, hi)}; }
  glm::vec3 unit() {
    const float z = range(-1.0f, 1.0f), phi = range(0.0f, 2.0f * kPi);
    const float rho = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return {rho * std::cos(phi), rho * std::sin(phi), z};
  }

 private:
  uint32_t state_;
};

std::vector<TwinCase> make_cases(uint32_t count) {
  Stream rng(12345u);
  std::vector<TwinCase> cases(count);
  for (uint32_t i = 0; i < count; ++i) {
    TwinCase& c = cases[i];
    // One texel for texel_moments.
    const glm::vec3 P = rng.vec(-5.0f, 5.0f);
    const glm::vec3 N = rng.unit();
    const bool valid = i % 10 != 3;
    const bool camera = i % 2 == 0;
    const glm::vec3 kd = i % 7 == 1 ? glm::vec3(0.0f) : rng.vec(0.0f, 1.0f);
    const glm::vec3 ks = i % 5 == 2 ? glm::vec3(0.0f) : rng.vec(0.0f, 0.5f);
    const float roughness = i % 11 == 4 ? 0.0f : rng.range(0.01f, 1.0f);
    c.position_valid = glm::vec4(P, valid ? 1.0f : 0.0f);
    c.normal_camera = glm::vec4(N, camera ? 1.0f : 0.0f);
    c.diffuse_pdf = glm::vec4(kd, rng.range(0.0f, 2.0f));
    c.specular_roughness = glm::vec4(ks, roughness);
    c.source = glm::vec4(P + N * rng.range(0.5f, 10.0f) + rng.vec(-3.0f, 3.0f), 0.0f);

    // Moments of a small cluster (2 to 9 texels around a centre, normals near a common one), as
    // the C++ twin computes them: vsgl_from_moments sees realistic sums. Every 13th is empty.
    const glm::vec3 centre = rng.vec(-5.0f, 5.0f);
    const glm::vec3 base_normal = rng.unit();
    const glm::vec3 src = centre + base_normal * 4.0f;
    const float spread = rng.log_range(1e-3f, 1.0f);
    TexelMoments sum;
    if (i % 13 != 6) {
      const auto texels = 2 + static_cast<uint32_t>(rng.range(0.0f, 8.0f));
      for (uint32_t t = 0; t < texels; ++t) {
        const TexelMoments m =
            texel_moments(true, centre + spread * rng.vec(-1.0f, 1.0f), glm::normalize(base_normal + 0.3f * rng.unit()),
                          rng.vec(0.0f, 1.0f), rng.vec(0.0f, 0.3f), rng.range(0.05f, 1.0f), 1.0f, src, camera);
        sum += m;
      }
    }
    c.moment0 = sum.m0;
    c.moment1 = sum.m1;
    c.moment2 = sum.m2;
    c.moment3 = sum.m3;
    c.moment4 = sum.m4;
    c.scale_level = glm::vec4(rng.log_range(1e-2f, 1e3f), 0.0f, 0.0f, rng.range(0.0f, 11.0f));
    c.center_extra = glm::vec4(rng.next(), rng.next(), rng.range(0.0f, 4.0f), static_cast<float>(i % 4));

    // A receiver at distance d from the cluster's mean: d = 0 (on the VSGL) for every 17th, else
    // log-uniform in [1e-5, 100] (clear of the 1e-6 switch to the fallback direction).
    const glm::vec3 mu = sum.m0.w > 0.0f ? glm::vec3(sum.m1) / sum.m0.w : glm::vec3(0.0f);
    const float d = i % 17 == 5 ? 0.0f : rng.log_range(1e-5f, 100.0f);
    // Mostly a receiver in front of the cluster's surface (the exact cosine at the light is then
    // positive); every 19th may lie behind it.
    glm::vec3 dir = rng.unit();
    if (i % 19 != 7 && glm::dot(-dir, base_normal) < 0.0f) dir = -dir;
    const glm::vec3 n = glm::normalize(dir + 0.8f * rng.unit() + glm::vec3(0.0f, 0.0f, 1e-3f));
    glm::vec3 wo = rng.unit();
    if (glm::dot(wo, n) < 0.0f) wo = -wo;
    c.receiver_position = glm::vec4(mu - d * dir, 0.0f);
    c.receiver_normal = glm::vec4(n, i % 9 == 0 ? 0.0f : rng.log_range(0.01f, 1.0f));
    c.receiver_wo = glm::vec4(wo, 0.0f);
    c.rho_d = glm::vec4(rng.vec(0.0f, 1.0f), 0.0f);
    c.rho_s = glm::vec4(rng.vec(0.0f, 1.0f), 0.0f);
    const glm::vec3 to_light = glm::normalize(n + 0.9f * rng.unit() + glm::vec3(1e-3f, 0.0f, 0.0f));
    c.texel_light = glm::vec4(to_light, rng.log_range(1e-3f, 1.0f));
    // Scalars across every branch: A(lambda) (1e-3, 0.5, 20), Banerjee's clamps, sg_integral (0.01).
    c.scalars = glm::vec4(rng.log_range(1e-6f, 1e5f), rng.range(-0.1f, 1.1f), rng.log_range(1e-7f, 1e9f), 0.0f);
  }
  return cases;
}

// |a - b| <= rel * max(|a|, |b|) + floor, as a gtest assertion naming the quantity.
::testing::AssertionResult close(const char* what, float gpu, float cpu, float floor, float rel = kRelative) {
  const float tol = rel * std::max(std::abs(gpu), std::abs(cpu)) + floor + kAbsoluteFloor;
  if (std::isfinite(gpu) && std::isfinite(cpu) && std::abs(gpu - cpu) <= tol) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << what << ": gpu " << gpu << " cpu " << cpu << " (tolerance " << tol << ")";
}

float max_abs(glm::vec4 v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z), std::abs(v.w)}); }

class VsglMathGpuTest : public GpuTest {};

TEST_F(VsglMathGpuTest, GlslMatchesTheCppTwins) {
  Device& dev = device();
  const uint32_t count = 1024;
  const std::vector<TwinCase> cases = make_cases(count);
  Buffer in(dev, sizeof(TwinCase) * count, MemoryUsage::kDeviceLocal, "test.vsgl_math.cases");
  Buffer out(dev, sizeof(TwinResult) * count, MemoryUsage::kDeviceLocal, "test.vsgl_math.results");
  upload(dev, in, cases.data(), sizeof(TwinCase) * count);
  const uint32_t local = gpu::kTestGroupSize;
  ComputePipeline pipeline(dev, {"test_vsgl_math.comp", 2, sizeof(gpu::TestCountPush), work_group_size_1d(local)});
  BindingSet set(dev, pipeline, {in, out}, "test.vsgl_math.set");
  dev.submit_and_wait([&](VkCommandBuffer cmd) {
    CommandStream stream(cmd);
    stream.dispatch(pipeline, set, gpu::TestCountPush{count}, div_up(count, local));
  });
  const auto results = download_vector<TwinResult>(dev, out, count);

  int checked_radiance = 0;
  for (uint32_t i = 0; i < count; ++i) {
    SCOPED_TRACE("case " + std::to_string(i));
    const TwinCase& c = cases[i];
    const TwinResult& g = results[i];

    // texel_moments: sums of products, floor 1e-6 of the layer's largest term.
    const TexelMoments m = texel_moments(c.position_valid.w != 0.0f, glm::vec3(c.position_valid),
                                         glm::vec3(c.normal_camera), glm::vec3(c.diffuse_pdf),
                                         glm::vec3(c.specular_roughness), c.specular_roughness.w, c.diffuse_pdf.w,
                                         glm::vec3(c.source), c.normal_camera.w != 0.0f);
    const glm::vec4 cpu_layers[5] = {m.m0, m.m1, m.m2, m.m3, m.m4};
    const glm::vec4 gpu_layers[5] = {g.m0, g.m1, g.m2, g.m3, g.m4};
    for (int layer = 0; layer < 5; ++layer)
      for (int k = 0; k < 4; ++k)
        ASSERT_TRUE(close(("m" + std::to_string(layer)).c_str(), gpu_layers[layer][k], cpu_layers[layer][k],
                          1e-6f * max_abs(cpu_layers[layer])));

    // vsgl_from_moments.
    const VsglRecord v =
        vsgl_from_moments({c.moment0, c.moment1, c.moment2, c.moment3, c.moment4}, c.scale_level.x, c.scale_level.w,
                          glm::vec2(c.center_extra), c.center_extra.z, c.center_extra.w);
    const float W = c.moment0.w;
    // mu = (sum w P) / W: floor 1e-6 of |P|; sigma^2 = E|P|^2 - |mu|^2 cancels: floor 1e-6 E|P|^2.
    const float mean_sq = W > 0.0f ? c.moment1.w / W : 0.0f;
    for (int k = 0; k < 3; ++k)
      ASSERT_TRUE(close("mu", g.vsgl.position_variance[k], v.position_variance[k], 1e-6f * std::sqrt(mean_sq)));
    ASSERT_TRUE(close("sigma2", g.vsgl.sigma2(), v.sigma2(), 1e-6f * mean_sq));
    const float s = c.moment3.r + c.moment3.g + c.moment3.b;
    const float r = W > 0.0f && s > 0.0f ? std::min(glm::length(glm::vec3(c.moment4) / s), kMaxMeanLength) : 0.0f;
    const float lambda_floor = std::abs(banerjee_sharpness(r * (1.0f + 2e-6f)) - banerjee_sharpness(r));
    ASSERT_TRUE(close("lambda", g.vsgl.sharpness(), v.sharpness(), lambda_floor));
    for (int k = 0; k < 3; ++k) {
      ASSERT_EQ(g.vsgl.power_sharpness[k], v.power_sharpness[k]) << "power = scale * m0.rgb, one product";
      ASSERT_EQ(g.vsgl.specular_power[k], v.specular_power[k]) << "specular power = scale * m3.rgb, one product";
      ASSERT_TRUE(close("axis", g.vsgl.axis_level[k], v.axis_level[k], 1e-5f));
      ASSERT_TRUE(close("normal", g.vsgl.normal_length[k], v.normal_length[k], 1e-5f));
    }
    ASSERT_TRUE(close("normal length", g.vsgl.normal_length.w, v.normal_length.w, 1e-6f));
    ASSERT_EQ(g.vsgl.level(), v.level());
    ASSERT_EQ(g.vsgl.center_pdf, v.center_pdf);

    // SG evaluation, on the GPU's own VSGL on both sides (so that the twins' radiance is compared
    // for identical inputs, apart from the conditioning of sigma^2 checked above).
    const glm::vec3 L = vsgl_radiance_surface(g.vsgl, glm::vec3(c.receiver_position), glm::vec3(c.receiver_normal),
                                              glm::vec3(c.receiver_wo), glm::vec3(c.rho_d), glm::vec3(c.rho_s),
                                              c.receiver_normal.w);
    for (int k = 0; k < 3; ++k) ASSERT_TRUE(close("radiance", g.radiance_importance[k], L[k], 0.0f));
    const float I =
        vsgl_importance_to_texel(g.vsgl, glm::vec3(c.receiver_position), glm::vec3(c.receiver_normal),
                                 glm::vec3(c.texel_light), glm::vec3(c.rho_s), glm::vec3(c.rho_d), c.texel_light.w);
    ASSERT_TRUE(close("importance", g.radiance_importance.w, I, 0.0f));
    if (L.x > 0.0f || I > 0.0f) ++checked_radiance;

    ASSERT_TRUE(close("A(lambda)", g.scalars.x, mean_resultant_length(c.scalars.x), 0.0f));
    const float rb = std::clamp(c.scalars.y, 0.0f, kMaxMeanLength);
    ASSERT_TRUE(close("banerjee", g.scalars.y, banerjee_sharpness(c.scalars.y),
                      std::abs(banerjee_sharpness(rb * (1.0f + 2e-6f)) - banerjee_sharpness(rb))));
    ASSERT_TRUE(close("sg_integral", g.scalars.z, sg_integral(c.scalars.z), 0.0f));
  }
  // The batch exercised the evaluation, not just zeros.
  EXPECT_GT(checked_radiance, static_cast<int>(count) / 2);
}

}  // namespace
}  // namespace vsgl
