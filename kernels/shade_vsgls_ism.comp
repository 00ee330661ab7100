#version 450
#extension GL_GOOGLE_include_directive : require
// The shading pass with imperfect shadow maps (DESIGN.md §8.1, §8a.2): each VSGL's contribution to a
// pixel times the lookup of that VSGL's map (about its mean and filtered normal) at the pixel's
// position and normal. The maps were built for exactly the VSGLs shaded, in their order, so the
// map of the chunk's VSGL k is vis.map_first + pc.first_vsgl + k. The pass: include/shade_vsgls.glsl.
#include "interface/shading.h"

layout(local_size_x_id = 0, local_size_y_id = 1) in;  // kShadeGroupSize (interface/shading.h)
layout(push_constant) uniform PushBlock {
  ShadePush pc;
  ShadeVisibilityParams vis;
};

#define SHADE_VISIBILITY
#include "shade_vsgls.glsl"  // bindings 0 (the G-buffer), 1 (the VSGLs), 2 (the radiance)
#define ISM_MAPS_BINDING 3
#include "ism_lookup.glsl"

float shade_visibility(Vsgl v, uint k, vec3 P, vec3 N) {
  return ism_visibility(vis.ism, vis.map_first + pc.first_vsgl + k, v.position_variance.xyz, v.normal_length.xyz, P,
                        N);
}
