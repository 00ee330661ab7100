#version 450
#extension GL_GOOGLE_include_directive : require
// FIS phase 1, "additional G-buffer / RSM" (paper Table 1): the per-texel moment layers of
// SPEC §4/§7 written into level 0 of the pyramid. One thread per texel.
#include "vsgl_math.glsl"

layout(local_size_x = 16, local_size_y = 16) in;
// The uploaded view: 4 layers of W*H texels: (P, valid), (N, pdf), (diffuse, roughness), (specular, 0).
layout(std430, binding = 0) readonly buffer View { vec4 view_texels[]; };
layout(std430, binding = 1) writeonly buffer Pyramid { vec4 pyramid_texels[]; };
layout(push_constant) uniform Push {
  uint width;
  uint height;
  uint pyramid_total;  // texels per pyramid layer
  uint camera_view;    // 1: G-buffer (power = reflectance), 0: RSM (power = flux)
  vec4 source_position;
} pc;

void main() {
  uvec2 p = gl_GlobalInvocationID.xy;
  if (p.x >= pc.width || p.y >= pc.height) return;
  uint n = pc.width * pc.height;
  uint i = p.y * pc.width + p.x;
  vec4 t0 = view_texels[i];
  vec4 t1 = view_texels[n + i];
  vec4 t2 = view_texels[2u * n + i];
  vec4 t3 = view_texels[3u * n + i];
  vec4 m0, m1, m2;
  texel_moments(t0.w > 0.5, t0.xyz, t1.xyz, t2.xyz, t3.xyz, t2.w, t1.w, pc.source_position.xyz, pc.camera_view != 0u,
                m0, m1, m2);
  pyramid_texels[i] = m0;
  pyramid_texels[pc.pyramid_total + i] = m1;
  pyramid_texels[2u * pc.pyramid_total + i] = m2;
}
