#pragma once
// C++ twins of kernels/include/vsgl_math.glsl and kernels/include/sg_eval.glsl: the maths of a
// VSGL (DESIGN.md §4, §7, §8) in float32, with the GLSL's formulas, branches and operation order, so
// the CPU reference and the GPU kernels agree to float rounding (tests/test_vsgl_math_glsl.cpp).
// Formulas and constants: kernels/CONVENTIONS.md (DESIGN.md §4-§8).
#include <string>
#include <string_view>
#include <type_traits>

#include <glm/glm.hpp>

namespace vsgl {

inline constexpr float kPi = 3.14159265358979f;
inline constexpr float kMaxSharpness = 1e4f;
inline constexpr float kMaxMeanLength = 0.9999f;
inline constexpr float kMinVariance = 1e-8f;   // epsilon of sigma^2
inline constexpr float kMinRoughness = 1e-3f;  // GGX alpha floor
inline constexpr float kMinCosine = 1e-4f;     // cosine floor of the reflection-lobe warp
inline constexpr float kMinDistance = 1e-6f;
// The evaluation of DESIGN.md §8, named in every output that shades: Tok15 Eq. 3 with K = 2 lobes and
// the exact cosines, with §3.3's bias reduction at alpha = gpu::kBiasReductionAlpha.
inline constexpr std::string_view kShadingModel = "tok15-eq3-k2";
// "Tok15 Eq. 3 (K = 2 lobes, exact cosines), §3.3 bias reduction at alpha = 1", for reports.
std::string shading_model_text();

// ---- vsgl_math.glsl ------------------------------------------------------------------------

// A(lambda) = coth(lambda) - 1/lambda, the mean resultant length of an SG/vMF lobe.
float mean_resultant_length(float lambda);
// Banerjee's inverse of A: lambda = r (3 - r^2) / (1 - r^2), r in [0, 0.9999], lambda in [0, 1e4].
float banerjee_sharpness(float r);
// The NDF sharpness 2/alpha^2 warped to the reflection lobe at cosine cos_n (Wang et al. 2009).
float reflection_lobe_sharpness(float roughness, float cos_n);
// A texel's specular lobe as an averaged direction A(lambda_s) reflect(-omega_in, N) (DESIGN.md §7).
glm::vec3 texel_specular_direction(glm::vec3 P, glm::vec3 N, float roughness, glm::vec3 source_pos);
float luminance(glm::vec3 c);  // Rec. 709

// The five moment layers of one texel (DESIGN.md §4): m0 = (Phi, w), m1 = (w P, w |P|^2),
// m2 = (w N, q), m3 = (Phi_s, 0), m4 = (s d_s, 0).
struct TexelMoments {
  glm::vec4 m0{0.0f};
  glm::vec4 m1{0.0f};
  glm::vec4 m2{0.0f};
  glm::vec4 m3{0.0f};
  glm::vec4 m4{0.0f};

  TexelMoments& operator+=(const TexelMoments& o) {
    m0 += o.m0;
    m1 += o.m1;
    m2 += o.m2;
    m3 += o.m3;
    m4 += o.m4;
    return *this;
  }
};
TexelMoments texel_moments(bool valid, glm::vec3 P, glm::vec3 N, glm::vec3 diffuse, glm::vec3 specular,
                           float roughness, float pdf, glm::vec3 source_pos, bool camera_view);

// The GPU's `struct Vsgl` (std430, 96 bytes): the output of every generator (DESIGN.md §7).
struct VsglRecord {
  glm::vec4 position_variance{0.0f};  // mu.xyz, sigma^2 = E|x|^2 - |E x|^2 (r^2 = 2 sigma^2)
  glm::vec4 power_sharpness{0.0f};    // Phi.rgb (diffuse + specular), lambda of the specular lobe
  glm::vec4 axis_level{0.0f};         // specular lobe axis.xyz, level l_i (FIS) or -1 (k-means)
  glm::vec4 center_pdf{0.0f};         // kernel centre x_i.xy, density used in the power, texel count (k-means) else 0
  glm::vec4 normal_length{0.0f};      // filtered normal (unit).xyz, |E N|
  glm::vec4 specular_power{0.0f};     // Phi_s.rgb (part of Phi), 0

  glm::vec3 mu() const { return glm::vec3(position_variance); }
  float sigma2() const { return position_variance.w; }
  glm::vec3 power() const { return glm::vec3(power_sharpness); }
  glm::vec3 specular() const { return glm::vec3(specular_power); }
  float sharpness() const { return power_sharpness.w; }
  glm::vec3 axis() const { return glm::vec3(axis_level); }
  glm::vec3 normal() const { return glm::vec3(normal_length); }
  float level() const { return axis_level.w; }
  glm::vec2 center() const { return glm::vec2(center_pdf); }
  float density() const { return center_pdf.z; }
};
static_assert(sizeof(VsglRecord) == 96, "VsglRecord must match the std430 layout of struct Vsgl");
static_assert(std::is_trivially_copyable_v<VsglRecord> && std::is_standard_layout_v<VsglRecord>);

// Power = power_scale * m0.rgb (specular part power_scale * m3.rgb): FIS passes Eq. 4 / Eq. 5's
// factor with the filtered means, k-means 1 with the sums.
VsglRecord vsgl_from_moments(const TexelMoments& m, float power_scale, float level, glm::vec2 center, float density,
                             float texel_count);

// ---- sg_eval.glsl --------------------------------------------------------------------------

float sg_integral(float s);                                    // 2 pi (1 - exp(-2 s)) / s
float sg_normalization(float s);                               // 1 / sg_integral(s)
// Integral over S^2 of the product of three SGs (unit axes), without cancellation.
float sg_triple_integral(glm::vec3 a1, float s1, glm::vec3 a2, float s2, glm::vec3 a3, float s3);

// The VSGL as seen from a receiver: direction to its mean, the cone's solid angle, the
// visibility-SG sharpness 4 pi / solid and 1 / (pi r^2).
struct VsglView {
  glm::vec3 wc{0.0f};
  float lambda_v = 0.0f;
  float solid_angle = 0.0f;
  float inv_area = 0.0f;
};
VsglView vsgl_view_from(const VsglRecord& v, glm::vec3 x, glm::vec3 fallback_dir);

// A BRDF or a light's emission as Tok15's K = 2 lobes (sg_eval.glsl).
struct TwoLobes {
  glm::vec3 diffuse{0.0f};
  glm::vec3 specular{0.0f};
  glm::vec3 axis{0.0f, 0.0f, 1.0f};
  float sharpness = 0.0f;
};
TwoLobes surface_lobes(glm::vec3 n, glm::vec3 wo, glm::vec3 rho_d, glm::vec3 rho_s, float roughness);
// Tok15 Eq. 3 with §3.3's bias reduction: a receiver (x, n, response f) lit by v.
glm::vec3 vsgl_two_lobe_radiance(const VsglRecord& v, glm::vec3 x, glm::vec3 n, const TwoLobes& f);

// (a) Radiance toward wo leaving a surface point x (normal n, albedos, GGX roughness) lit by v.
glm::vec3 vsgl_radiance_surface(const VsglRecord& v, glm::vec3 x, glm::vec3 n, glm::vec3 wo, glm::vec3 rho_d,
                                glm::vec3 rho_s, float roughness);
// (b) Importance an RSM texel (P, N, its flux as albedos, seen from the light along to_light)
// receives from a camera VSGL: the channel sum of (a).
float vsgl_importance_to_texel(const VsglRecord& cam, glm::vec3 P, glm::vec3 N, glm::vec3 to_light,
                               glm::vec3 flux_diffuse, glm::vec3 flux_specular, float roughness);

}  // namespace vsgl
