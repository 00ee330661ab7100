#version 450
#extension GL_GOOGLE_include_directive : require
// The splat of the imperfect shadow maps (DESIGN.md §8a.2; Ritschel et al. 2008): thread (j, m)
// projects point (m mod point_stride) + j point_stride of the shared array into map m's
// paraboloid (paraboloid.glsl) and keeps the nearest distance in its texel of level 0 with
// atomicMin on the distance's float bits (a positive float's bits order like the float). Each map
// takes its own interleaved subset, a stratified sample of the whole surface (the point array is
// stratified by cumulative area, harness/visibility/point_sampling.hpp). Points behind the map's
// plane (l.z <= 0) are left out: the VSGL sends no light there. The points' normals are not used:
// a one-sided wall must shadow from both sides. The host cleared the maps to kIsmEmpty.
#include "paraboloid.glsl"
#include "interface/ism.h"

layout(local_size_x_id = 0) in;  // kIsmGroupSize (interface/ism.h); y: the map

layout(std430, binding = 0) readonly buffer Points { vec4 points[]; };
layout(std430, binding = 1) readonly buffer Origins { IsmOrigin origins[]; };
layout(std430, binding = 2) buffer Maps { uint depths[]; };
layout(push_constant) uniform PushBlock { IsmParams pc; };

void main() {
  uint j = gl_GlobalInvocationID.x;
  uint m = gl_GlobalInvocationID.y;
  if (j >= pc.points_per_map || m >= pc.map_count) return;
  uint i = m % pc.point_stride + j * pc.point_stride;
  if (i >= pc.point_count) return;
  vec3 origin = origins[m].position.xyz;
  vec3 n = origins[m].normal.xyz;
  vec3 v = points[i].xyz - origin;
  float dist = length(v);
  if (!(dist > 0.0)) return;  // a point at the origin has no direction
  vec3 d = v / dist;
  vec3 t, b;
  paraboloid_frame(n, t, b);
  vec3 l = vec3(dot(d, t), dot(d, b), dot(d, n));
  if (l.z <= 0.0) return;
  uvec2 texel = paraboloid_texel(paraboloid_project(l), pc.side);
  atomicMin(depths[m * pc.map_stride + texel.y * pc.side + texel.x], floatBitsToUint(dist));
}
