#version 450
#extension GL_GOOGLE_include_directive : require
// The shading pass with exact visibility, the control (DESIGN.md §8.1, §8a.1): each VSGL's
// contribution to a pixel times the visibility of the segment from the pixel's position to the
// VSGL's mean, traced through the BVH of the capture's triangles, in the kernel (no pixels x VSGLs
// buffer). CPU twin: shade_pixel_reference with segment_occluded. The pass: include/shade_vsgls.glsl.
#include "interface/shading.h"

layout(local_size_x_id = 0, local_size_y_id = 1) in;  // kShadeGroupSize (interface/shading.h)
layout(push_constant) uniform PushBlock {
  ShadePush pc;
  ShadeVisibilityParams vis;
};

#define SHADE_VISIBILITY
#include "shade_vsgls.glsl"  // bindings 0 (the G-buffer), 1 (the VSGLs), 2 (the radiance)
#define BVH_BINDING 3
#include "bvh_traverse.glsl"  // bindings 3 (nodes) and 4 (triangles)

float shade_visibility(Vsgl v, uint k, vec3 P, vec3 N) {
  return bvh_segment_occluded(bvh_segment_query(P, v.position_variance.xyz, vis.epsilon), vis.node_count) ? 0.0 : 1.0;
}
