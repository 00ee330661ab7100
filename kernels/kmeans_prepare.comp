#version 450
#extension GL_GOOGLE_include_directive : require
// k-means, `cluster_assignment` step 1: per texel, its feature (DESIGN.md §6.2: the texel centre in
// pixels for kmeans_2d, the world position for kmeans_3d) with its PDF weight q, or q = -1 for a
// texel that belongs to no cluster (valid flag 0, or w = 0 and q = 0); level 0 of the PDF pyramid
// (q in .w, as the FIS "additional" pass stores it, so the seeds equal the FIS kernel centres);
// and the features' bounding box for the grid (reduced in shared memory, then one atomic per
// group and component).
#include "kmeans_common.glsl"
#include "vsgl_math.glsl"

#include "interface/kmeans.h"
layout(local_size_x_id = 0, local_size_y_id = 1) in;  // kKmeansImageGroupSize (interface/kmeans.h)
#include "view_layers.glsl"
layout(std430, binding = 1) writeonly buffer Features { vec4 features[]; };
layout(std430, binding = 2) writeonly buffer PdfPyramid { vec4 pdf_level0[]; };
layout(std430, binding = 3) buffer Grid { uint grid_words[]; };
layout(push_constant) uniform PushBlock { KmeansPreparePush pc; };

shared uint group_bounds[6];

void main() {
  if (gl_LocalInvocationIndex < 6u) group_bounds[gl_LocalInvocationIndex] = 0u;
  barrier();
  uvec2 p = gl_GlobalInvocationID.xy;
  if (p.x < pc.width && p.y < pc.height) {
    uint i = p.y * pc.width + p.x;
    vec4 t0 = view_position_valid(i);
    vec4 t1 = view_normal_pdf(i);
    vec4 t2 = view_diffuse_roughness(i);
    vec4 t3 = view_specular(i);
    vec4 m0, m1, m2, m3, m4;
    texel_moments(t0.w > 0.5, t0.xyz, t1.xyz, t2.xyz, t3.xyz, t2.w, t1.w, pc.source_position.xyz,
                  pc.camera_view != 0u, m0, m1, m2, m3, m4);
    bool member = t0.w > 0.5 && !(m0.w == 0.0 && m2.w == 0.0);
    vec3 f = pc.space3d != 0u ? t0.xyz : vec3(vec2(p) + 0.5, 0.0);
    features[i] = vec4(f, member ? m2.w : -1.0);
    pdf_level0[i] = vec4(0.0, 0.0, 0.0, m2.w);
    if (member) {
      for (uint a = 0u; a < 3u; ++a) {
        atomicMax(group_bounds[a], ~kmeans_order_float(f[a]));
        atomicMax(group_bounds[3u + a], kmeans_order_float(f[a]));
      }
    }
  }
  barrier();
  if (gl_LocalInvocationIndex < 6u) atomicMax(grid_words[gl_LocalInvocationIndex], group_bounds[gl_LocalInvocationIndex]);
}
