#version 450
#extension GL_GOOGLE_include_directive : require
// Test-only kernel: evaluates the VSGL maths of kernels/include/ for a batch of cases so that
// tests/test_vsgl_math_glsl.cpp can compare the GLSL with its C++ twin (harness/math/vsgl_math.hpp).
#include "sg_eval.glsl"
#include "interface/testing.h"

layout(local_size_x_id = 0) in;  // kTestGroupSize (interface/testing.h)

// One case (std430; C++: TwinCase in the test).
struct TwinCase {
  vec4 position_valid;      // texel P, valid flag (0 | 1)
  vec4 normal_camera;       // texel N, camera view flag (0 | 1)
  vec4 diffuse_pdf;         // diffuse rgb, PDF weight q
  vec4 specular_roughness;  // specular rgb, GGX alpha
  vec4 source;              // source position (light or camera); w unused
  vec4 moment0;             // aggregated moments given to vsgl_from_moments
  vec4 moment1;
  vec4 moment2;
  vec4 moment3;
  vec4 moment4;
  vec4 scale_level;         // power scale, 0, 0, level
  vec4 center_extra;        // kernel centre xy, density, texel count
  vec4 receiver_position;   // x; w unused
  vec4 receiver_normal;     // n, receiver roughness
  vec4 receiver_wo;         // wo: unit direction to the viewer; w unused
  vec4 rho_d;               // receiver diffuse albedo; w unused
  vec4 rho_s;               // receiver specular albedo; w unused
  vec4 texel_light;         // an RSM texel's direction to the light, its roughness (importance)
  vec4 scalars;             // lambda for A(), r for Banerjee, s for sg_integral; w unused
};

struct TwinResult {
  vec4 m0;
  vec4 m1;
  vec4 m2;
  vec4 m3;
  vec4 m4;
  Vsgl vsgl;
  vec4 radiance_importance;  // vsgl_radiance_surface rgb, vsgl_importance_to_vpl
  vec4 scalars;              // A(lambda), banerjee(r), sg_integral(s), 0
};

layout(std430, binding = 0) readonly buffer Cases { TwinCase cases[]; };
layout(std430, binding = 1) writeonly buffer Results { TwinResult results[]; };
layout(push_constant) uniform PushBlock { TestCountPush pc; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= pc.count) return;
  TwinCase c = cases[i];
  TwinResult r;
  texel_moments(c.position_valid.w != 0.0, c.position_valid.xyz, c.normal_camera.xyz, c.diffuse_pdf.rgb,
                c.specular_roughness.rgb, c.specular_roughness.w, c.diffuse_pdf.w, c.source.xyz,
                c.normal_camera.w != 0.0, r.m0, r.m1, r.m2, r.m3, r.m4);
  r.vsgl = vsgl_from_moments(c.moment0, c.moment1, c.moment2, c.moment3, c.moment4, c.scale_level.x, c.scale_level.w,
                             c.center_extra.xy, c.center_extra.z, c.center_extra.w);
  vec3 radiance = vsgl_radiance_surface(r.vsgl, c.receiver_position.xyz, c.receiver_normal.xyz, c.receiver_wo.xyz,
                                        c.rho_d.rgb, c.rho_s.rgb, c.receiver_normal.w);
  float importance = vsgl_importance_to_texel(r.vsgl, c.receiver_position.xyz, c.receiver_normal.xyz, c.texel_light.xyz,
                                              c.rho_s.rgb, c.rho_d.rgb, c.texel_light.w);
  r.radiance_importance = vec4(radiance, importance);
  r.scalars = vec4(mean_resultant_length(c.scalars.x), banerjee_sharpness(c.scalars.y), sg_integral(c.scalars.z), 0.0);
  results[i] = r;
}
