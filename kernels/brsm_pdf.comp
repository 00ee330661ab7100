#version 450
#extension GL_GOOGLE_include_directive : require
// The BRSM PDF (DESIGN.md §8): for every RSM texel, the importance its flux receives from the
// camera-view VSGLs (made by fis_modified on the G-buffer). One thread per texel; the camera
// VSGLs stream through shared memory in tiles so each is read once per workgroup.
#include "vsgl_math.glsl"
#include "brsm_importance.glsl"
#include "interface/brsm.h"

layout(local_size_x_id = 0, local_size_y_id = 1) in;  // kBrsmGroupSize (interface/brsm.h)
// Half the group's threads load one VSGL each per tile: 128 records of 96 bytes keep the tile within
// the 16 KiB of shared memory every Vulkan device has.
const uint TILE = gl_WorkGroupSize.x * gl_WorkGroupSize.y / 2u;

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
  vec3 flux = t2.rgb + t3.rgb;
  bool lit = inside && t0.w > 0.5 && flux.r + flux.g + flux.b > 0.0;
  float importance = 0.0;
  for (uint base = 0u; base < pc.camera_count; base += TILE) {
    uint c = base + gl_LocalInvocationIndex;
    if (gl_LocalInvocationIndex < TILE && c < pc.camera_count) tile[gl_LocalInvocationIndex] = camera_vsgls[c];
    barrier();
    uint count = min(TILE, pc.camera_count - base);
    if (lit)
      for (uint k = 0u; k < count; ++k) importance += camera_importance(tile[k], t0.xyz, t1.xyz, t2.rgb, t3.rgb, t2.w, pc.light_position.xyz);
    barrier();
  }
  if (inside) pdf[i] = lit ? importance : 0.0;
}
