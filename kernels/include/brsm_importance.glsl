#ifndef BRSM_IMPORTANCE_GLSL
#define BRSM_IMPORTANCE_GLSL
// The BRSM PDF weight of one RSM texel (DESIGN.md §8): q_j = sum_c E(c -> j) over the camera VSGLs
// c, E the importance camera VSGL c sends to texel j, evaluated as shading is (Tok15 Eq. 3, the
// texel a receiver whose albedos are its flux, seen from the light), without visibility. The exact
// cosines make a camera VSGL behind the texel's surface, or a texel behind the VSGL's, contribute
// nothing: a texel that no camera cluster sees gets q = 0. C++ twin: brsm_texel_weight() in
// harness/scene/brsm_pdf.cpp.
#include "sg_eval.glsl"

float camera_importance(Vsgl cam, vec3 P, vec3 N, vec3 flux_diffuse, vec3 flux_specular, float roughness,
                        vec3 light_position) {
  vec3 to_light = light_position - P;
  float d2 = dot(to_light, to_light);
  vec3 wo = d2 > 0.0 ? to_light * inversesqrt(d2) : N;
  return vsgl_importance_to_texel(cam, P, N, wo, flux_diffuse, flux_specular, roughness);
}

#endif
