#version 450
#extension GL_GOOGLE_include_directive : require
// Test-only kernel: ism_visibility() (include/ism_lookup.glsl) for a batch of (map, receiver)
// queries, so that tests/test_ism_box.cpp can hold the ISMs against exact visibility.
#include "interface/ism.h"
#define ISM_MAPS_BINDING 2
#include "ism_lookup.glsl"

layout(local_size_x_id = 0) in;  // kIsmGroupSize (interface/ism.h)

layout(std430, binding = 0) readonly buffer Origins { IsmOrigin origins[]; };
layout(std430, binding = 1) readonly buffer Queries { IsmQuery queries[]; };
layout(std430, binding = 3) writeonly buffer Results { float visibility[]; };
layout(push_constant) uniform PushBlock { IsmQueryPush pc; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= pc.count) return;
  IsmQuery q = queries[i];
  IsmOrigin o = origins[q.map];
  visibility[i] = ism_visibility(pc.params, q.map, o.position.xyz, o.normal.xyz, q.position.xyz, q.normal.xyz);
}
