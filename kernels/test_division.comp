#version 450
// Probe for the tests: quotients of given pairs, to learn whether this device's float division is
// correctly rounded (SPIR-V allows 2.5 ULP). Exact CPU/GPU agreement of the sampler needs it.
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Pairs { vec2 pairs[]; };
layout(std430, binding = 1) writeonly buffer Quotients { float quotients[]; };
layout(push_constant) uniform Push { uint count; } pc;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= pc.count) return;
  precise float q = pairs[i].x / pairs[i].y;
  quotients[i] = q;
}
