#version 450
#extension GL_GOOGLE_include_directive : require
// Probe for the tests: quotients of given pairs, to learn whether this device's float division is
// correctly rounded (SPIR-V allows 2.5 ULP). Exact CPU/GPU agreement of the sampler needs it.
#include "interface/testing.h"
layout(local_size_x_id = 0) in;  // kTestGroupSize (interface/testing.h)
layout(std430, binding = 0) readonly buffer Pairs { vec2 pairs[]; };
layout(std430, binding = 1) writeonly buffer Quotients { float quotients[]; };
layout(push_constant) uniform PushBlock { TestCountPush pc; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= pc.count) return;
  precise float q = pairs[i].x / pairs[i].y;
  quotients[i] = q;
}
