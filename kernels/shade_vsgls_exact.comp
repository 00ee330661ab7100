#version 450
#extension GL_GOOGLE_include_directive : require
// The shading pass with exact visibility, the control (DESIGN.md §8.1, §8a.1): each VSGL's
// contribution to a pixel times the visibility of the segment from the pixel's position to the
// VSGL's mean. The segments of a chunk are answered before its dispatch by the BVH's segment
// kernel (visibility_segments.comp, on queries the host makes as the CPU twin does) into a buffer
// of chunk x pixels answers, which this kernel reads: lavapipe miscompiled the BVH walk inlined
// here (ShadeVisibilityTest.ExactWithManyReferenceVplsMatchesTheCpuTwin). CPU twin:
// shade_pixel_reference with segment_occluded. The pass: include/shade_vsgls.glsl.
#include "interface/shading.h"

layout(local_size_x_id = 0, local_size_y_id = 1) in;  // kShadeGroupSize (interface/shading.h)
layout(push_constant) uniform PushBlock {
  ShadePush pc;
  ShadeVisibilityParams vis;
};

#define SHADE_VISIBILITY
#include "shade_vsgls.glsl"  // bindings 0 (the G-buffer), 1 (the VSGLs), 2 (the radiance)
// Answer k * pixels + p: 1 where VSGL k of this chunk is seen from output pixel p, 0 where not.
layout(std430, binding = 3) readonly buffer Visible { uint visible[]; };

float shade_visibility(Vsgl v, uint k, vec3 P, vec3 N) {
  const uvec2 o = gl_GlobalInvocationID.xy;
  return visible[k * (pc.out_width * pc.out_height) + o.y * pc.out_width + o.x] != 0u ? 1.0 : 0.0;
}
