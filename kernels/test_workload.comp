#version 450
// A known amount of work for the timing tests: each invocation runs `iterations` steps of an
// integer hash and stores the result, so the dispatch cannot be optimized away.
layout(local_size_x_id = 0) in;
layout(std430, binding = 0) writeonly buffer Out { uint values[]; };
layout(push_constant) uniform Push {
  uint count;
  uint iterations;
} pc;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= pc.count) return;
  uint h = i * 2654435761u + 1u;
  for (uint k = 0u; k < pc.iterations; ++k) h = (h ^ (h >> 15)) * 2246822519u + k;
  values[i] = h;
}
