#ifndef FIS_ADDITIONAL_GLSL
#define FIS_ADDITIONAL_GLSL
// FIS phase 1, "additional G-buffer / RSM" (paper Table 1), shared by both pyramid paths: the
// per-texel moment layers of DESIGN.md §4/§7 for level 0 of the pyramid. One thread per texel. The
// includer includes view_layers.glsl and defines store_moments(p, i, m0, ..., m4) (i = p.y W + p.x).
#include "interface/fis.h"
#include "vsgl_math.glsl"

layout(local_size_x_id = 0, local_size_y_id = 1) in;
layout(push_constant) uniform PushBlock { FisAdditionalPush pc; };

void store_moments(uvec2 p, uint i, vec4 m0, vec4 m1, vec4 m2, vec4 m3, vec4 m4);

void main() {
  uvec2 p = gl_GlobalInvocationID.xy;
  if (p.x >= pc.width || p.y >= pc.height) return;
  uint i = p.y * pc.width + p.x;
  vec4 t0 = view_position_valid(i);
  vec4 t1 = view_normal_pdf(i);
  vec4 t2 = view_diffuse_roughness(i);
  vec4 t3 = view_specular(i);
  vec4 m0, m1, m2, m3, m4;
  texel_moments(t0.w > 0.5, t0.xyz, t1.xyz, t2.xyz, t3.xyz, t2.w, t1.w, pc.source_position.xyz, pc.camera_view != 0u,
                m0, m1, m2, m3, m4);
  store_moments(p, i, m0, m1, m2, m3, m4);
}

#endif
