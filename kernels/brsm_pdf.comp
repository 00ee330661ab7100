#version 450
#extension GL_GOOGLE_include_directive : require
// The BRSM PDF (DESIGN.md §8): for every RSM texel, its power times the importance it receives from
// the camera-view VSGLs (made by fis_modified on the G-buffer). One thread per texel; the camera
// VSGLs stream through shared memory in tiles so each is read once per workgroup.
#include "vsgl_math.glsl"
#include "brsm_importance.glsl"
#include "interface/brsm.h"

layout(local_size_x_id = 0, local_size_y_id = 1) in;  // kBrsmGroupSize (interface/brsm.h)
const uint TILE = gl_WorkGroupSize.x * gl_WorkGroupSize.y;  // = threads per group: each thread loads one VSGL of a tile

#include "view_layers.glsl"  // the RSM, DeviceView layout
layout(std430, binding = 1) readonly buffer CameraVsgls { Vsgl camera_vsgls[]; };
layout(std430, binding = 2) writeonly buffer Pdf { float pdf[]; };
layout(push_constant) uniform PushBlock { BrsmPush pc; };

shared Vsgl tile[TILE];

void main() {
  uvec2 p = gl_GlobalInvocationID.xy;
  bool inside = p.x < pc.width && p.y < pc.height;
  uint i = inside ? p.y * pc.width + p.x : 0u;
  vec4 t0 = view_position_valid(i);
  vec4 t1 = view_normal_pdf(i);
  vec4 t2 = view_diffuse_roughness(i);
  vec4 t3 = view_specular(i);
  VplLobe lobe = vpl_lobe(t0.xyz, t1.xyz, t2.rgb, t3.rgb, t2.w, pc.light_position.xyz);
  bool lit = inside && t0.w > 0.5 && lobe.power > 0.0;
  float importance = 0.0;
  for (uint base = 0u; base < pc.camera_count; base += TILE) {
    uint c = base + gl_LocalInvocationIndex;
    if (c < pc.camera_count) tile[gl_LocalInvocationIndex] = camera_vsgls[c];
    barrier();
    uint count = min(TILE, pc.camera_count - base);
    if (lit)
      for (uint k = 0u; k < count; ++k) importance += camera_importance(tile[k], t0.xyz, t1.xyz, lobe);
    barrier();
  }
  if (inside) pdf[i] = lit ? lobe.power * importance : 0.0;
}
