#version 450
#extension GL_GOOGLE_include_directive : require
// A known amount of work for the timing tests: each invocation runs `iterations` steps of an
// integer hash and stores the result, so the dispatch cannot be optimized away.
#include "interface/testing.h"
layout(local_size_x_id = 0) in;  // kTestGroupSize (interface/testing.h)
layout(std430, binding = 0) writeonly buffer Out { uint values[]; };
layout(push_constant) uniform PushBlock { TestWorkloadPush pc; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= pc.count) return;
  uint h = i * 2654435761u + 1u;
  for (uint k = 0u; k < pc.iterations; ++k) h = (h ^ (h >> 15)) * 2246822519u + k;
  values[i] = h;
}
