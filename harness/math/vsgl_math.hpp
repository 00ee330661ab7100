#pragma once
// C++ twins of kernels/include/vsgl_math.glsl and kernels/include/sg_eval.glsl: the maths of a
// VSGL (DESIGN.md §4, §7, §8) in float32, with the GLSL's formulas, branches and operation order, so
// the CPU reference and the GPU kernels agree to float rounding (tests/test_vsgl_math_glsl.cpp).
// Formulas and constants: kernels/CONVENTIONS.md (DESIGN.md §4-§8).
#include <type_traits>

#include <glm/glm.hpp>

namespace vsgl {

inline constexpr float kPi = 3.14159265358979f;
// A_d: mean resultant length of the vMF approximating a clamped cosine (lambda ~= 2.29, DESIGN.md §7).
inline constexpr float kDiffuseMeanLength = 0.575f;
inline constexpr float kMaxSharpness = 1e4f;
inline constexpr float kMaxMeanLength = 0.9999f;
inline constexpr float kMinVariance = 1e-8f;   // epsilon of sigma^2
inline constexpr float kMinRoughness = 1e-3f;  // GGX alpha floor
inline constexpr float kMinCosine = 1e-4f;     // cosine floor of the reflection-lobe warp
inline constexpr float kCosineSgAmplitude = 1.17f;  // max(dot(w, n), 0) ~= 1.17 G(w; n, 2.133)
inline constexpr float kCosineSgSharpness = 2.133f;
inline constexpr float kMinDistance = 1e-6f;

// ---- vsgl_math.glsl ------------------------------------------------------------------------

// A(lambda) = coth(lambda) - 1/lambda, the mean resultant length of an SG/vMF lobe.
float mean_resultant_length(float lambda);
// Banerjee's inverse of A: lambda = r (3 - r^2) / (1 - r^2), r in [0, 0.9999], lambda in [0, 1e4].
float banerjee_sharpness(float r);
// rbar, a texel's emission lobe as a mean direction vector (DESIGN.md §7).
glm::vec3 texel_emission_lobe(glm::vec3 P, glm::vec3 N, glm::vec3 diffuse, glm::vec3 specular, float roughness,
                              glm::vec3 source_pos);
float luminance(glm::vec3 c);  // Rec. 709

// The three moment layers of one texel: m0 = (Phi, w), m1 = (w P, w |P|^2), m2 = (w rbar, q).
struct TexelMoments {
  glm::vec4 m0{0.0f};
  glm::vec4 m1{0.0f};
  glm::vec4 m2{0.0f};
};
TexelMoments texel_moments(bool valid, glm::vec3 P, glm::vec3 N, glm::vec3 diffuse, glm::vec3 specular,
                           float roughness, float pdf, glm::vec3 source_pos, bool camera_view);

// The GPU's `struct Vsgl` (std430, 64 bytes): the output of every generator (DESIGN.md §7).
struct VsglRecord {
  glm::vec4 position_variance{0.0f};  // mu.xyz, sigma^2
  glm::vec4 power_sharpness{0.0f};    // Phi.rgb, lambda
  glm::vec4 axis_level{0.0f};         // lobe axis.xyz, level l_i (FIS) or -1 (k-means)
  glm::vec4 center_pdf{0.0f};         // kernel centre x_i.xy, density used in the power, texel count (k-means) else 0

  glm::vec3 mu() const { return glm::vec3(position_variance); }
  float sigma2() const { return position_variance.w; }
  glm::vec3 power() const { return glm::vec3(power_sharpness); }
  float sharpness() const { return power_sharpness.w; }
  glm::vec3 axis() const { return glm::vec3(axis_level); }
  float level() const { return axis_level.w; }
  glm::vec2 center() const { return glm::vec2(center_pdf); }
  float density() const { return center_pdf.z; }
};
static_assert(sizeof(VsglRecord) == 64, "VsglRecord must match the std430 layout of struct Vsgl");
static_assert(std::is_trivially_copyable_v<VsglRecord> && std::is_standard_layout_v<VsglRecord>);

VsglRecord vsgl_from_moments(glm::vec4 m0, glm::vec4 m1, glm::vec4 m2, glm::vec3 power, float level,
                             glm::vec2 center, float density, float texel_count);

// ---- sg_eval.glsl --------------------------------------------------------------------------

float sg_integral(float s);                                    // 2 pi (1 - exp(-2 s)) / s
float sg_normalization(float s);                               // 1 / sg_integral(s)
// Integral over S^2 of the product of three SGs (unit axes), without cancellation.
float sg_triple_integral(glm::vec3 a1, float s1, glm::vec3 a2, float s2, glm::vec3 a3, float s3);

// The VSGL as seen from a receiver: direction to its mean, visibility-SG sharpness 4 pi / solid,
// and 2 / (pi r^2).
struct VsglView {
  glm::vec3 wc{0.0f};
  float lambda_v = 0.0f;
  float scale = 0.0f;
};
VsglView vsgl_view_from(const VsglRecord& v, glm::vec3 x, glm::vec3 fallback_dir);

// (a) Radiance toward wo leaving a surface point x (normal n, albedos, GGX roughness) lit by v.
glm::vec3 vsgl_radiance_surface(const VsglRecord& v, glm::vec3 x, glm::vec3 n, glm::vec3 wo, glm::vec3 rho_d,
                                glm::vec3 rho_s, float roughness);
// (b) Importance a VPL at x with emission lobe (axis, lambda) receives from a camera VSGL; the
// camera VSGL's rgb power enters as its channel sum (a scalar, no luminance weighting).
float vsgl_importance_to_vpl(const VsglRecord& cam, glm::vec3 x, glm::vec3 vpl_axis, float vpl_lambda);

}  // namespace vsgl
