#version 450
#extension GL_GOOGLE_include_directive : require
// k-means helper: words[offset .. offset + count) = value (clears the grid's counters and the
// feature bounds before they are accumulated with atomics).
#include "kmeans_common.glsl"
#include "interface/kmeans.h"
layout(local_size_x_id = 0) in;  // kKmeansWideGroupSize (interface/kmeans.h)
layout(std430, binding = 0) writeonly buffer Words { uint words[]; };
layout(push_constant) uniform PushBlock { KmeansFillPush pc; };

void main() {
  uint i = kmeans_flat_invocation();
  if (i < pc.count) words[pc.offset + i] = pc.value;
}
