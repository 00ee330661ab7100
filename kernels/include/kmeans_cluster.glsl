#ifndef KMEANS_CLUSTER_GLSL
#define KMEANS_CLUSTER_GLSL
// k-means `sum` (DESIGN.md §6.2, §7): the moments of a cluster's texels and the VSGL built from them.
// The includer includes vsgl_math.glsl and, to read texels, defines KMEANS_READS_VIEW and declares
// view_layers.glsl (the uploaded view: 4 layers of W*H vec4). Shared by the sequential sum (kmeans_sum.comp) and the segmented one.
#include "kmeans_common.glsl"

struct ClusterMoments {
  vec4 m0, m1, m2, m3, m4;  // sums of the texel moment layers (texel_moments())
  vec2 pixels;      // sum of the texel centres in pixels (kmeans_3d's image-space centre)
};

ClusterMoments cluster_moments_zero() {
  ClusterMoments s;
  s.m0 = vec4(0.0);
  s.m1 = vec4(0.0);
  s.m2 = vec4(0.0);
  s.m3 = vec4(0.0);
  s.m4 = vec4(0.0);
  s.pixels = vec2(0.0);
  return s;
}

#ifdef KMEANS_READS_VIEW
ClusterMoments texel_cluster_moments(uint texel, uint width, uint height, bool camera_view, vec3 source) {
  vec4 t0 = view_position_valid(texel);
  vec4 t1 = view_normal_pdf(texel);
  vec4 t2 = view_diffuse_roughness(texel);
  vec4 t3 = view_specular(texel);
  ClusterMoments s;
  texel_moments(t0.w > 0.5, t0.xyz, t1.xyz, t2.xyz, t3.xyz, t2.w, t1.w, source, camera_view, s.m0, s.m1, s.m2, s.m3,
                s.m4);
  s.pixels = vec2(float(texel % width), float(texel / width)) + 0.5;
  return s;
}
#endif

ClusterMoments cluster_moments_add(ClusterMoments a, ClusterMoments b) {
  ClusterMoments s;
  s.m0 = a.m0 + b.m0;
  s.m1 = a.m1 + b.m1;
  s.m2 = a.m2 + b.m2;
  s.m3 = a.m3 + b.m3;
  s.m4 = a.m4 + b.m4;
  s.pixels = a.pixels + b.pixels;
  return s;
}

// The cluster's VSGL (DESIGN.md §7): power = the exact sum of its flux (M0.rgb, scale 1), level -1, texel count
// in .w of center_pdf, density 0. Kernel centre: kmeans_2d, the cluster centre / S (in [0,1]^2
// of the virtual square, like FIS); kmeans_3d, the mean texel centre of the cluster in the image
// / S (its world-space centre is mu).
Vsgl cluster_vsgl(ClusterMoments s, uint texel_count, vec4 centre, bool space3d, uint square_size) {
  float S = float(square_size);
  vec2 center = space3d ? (texel_count > 0u ? s.pixels / float(texel_count) / S : vec2(0.0)) : centre.xy / S;
  return vsgl_from_moments(s.m0, s.m1, s.m2, s.m3, s.m4, 1.0, -1.0, center, 0.0, float(texel_count));
}

#endif  // KMEANS_CLUSTER_GLSL
