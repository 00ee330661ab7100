#ifndef BRSM_IMPORTANCE_GLSL
#define BRSM_IMPORTANCE_GLSL
// The BRSM PDF weight of one RSM texel (DESIGN.md §8): q_j = w_j * sum_c E(c -> j) over the camera
// VSGLs c, E evaluated through the VPL's own emission lobe, without visibility. A VPL emits into
// the hemisphere of its normal only, so a camera VSGL behind it contributes nothing: a VPL that no
// camera cluster sees gets q = 0. C++ twin: brsm_texel_weight() in harness/scene/brsm_pdf.cpp.
#include "sg_eval.glsl"

struct VplLobe {
  vec3 axis;
  float sharpness;
  float power;  // w_j = Phi_r + Phi_g + Phi_b
};

VplLobe vpl_lobe(vec3 P, vec3 N, vec3 flux_diffuse, vec3 flux_specular, float roughness, vec3 light_position) {
  VplLobe l;
  vec3 phi = flux_diffuse + flux_specular;
  l.power = phi.r + phi.g + phi.b;
  vec3 rbar = texel_emission_lobe(P, N, flux_diffuse, flux_specular, roughness, light_position);
  float r = length(rbar);
  l.axis = r > 0.0 ? rbar / r : N;
  l.sharpness = banerjee_sharpness(r);
  return l;
}

float camera_importance(Vsgl cam, vec3 P, vec3 N, VplLobe lobe) {
  if (dot(N, cam.position_variance.xyz - P) <= 0.0) return 0.0;
  return vsgl_importance_to_vpl(cam, P, lobe.axis, lobe.sharpness);
}

#endif
