#ifndef KMEANS_COMMON_GLSL
#define KMEANS_COMMON_GLSL
// Shared pieces of the k-means kernels (DESIGN.md §6.2; host: harness/generators/kmeans/kmeans_generator.cpp, CPU twin:
// harness/reference/kmeans_reference.cpp): the "no cluster" id, the sort key, the feature distance, and the
// flat invocation index of a 1D workload spread over a 2D grid of groups (so that no dispatch
// exceeds maxComputeWorkGroupCount[0]).

const uint KMEANS_NO_CLUSTER = 0xFFFFFFFFu;  // invalid texels belong to no cluster

// Flat index of this invocation when groups are laid out row by row (gl_NumWorkGroups.x per row).
// A macro, not a function: gl_WorkGroupSize is only known after the kernel's local_size layout,
// which may come after this include.
#define kmeans_flat_invocation() \
  ((gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationIndex)
uint kmeans_flat_group() { return gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x; }

// Sort key of a cluster id: clusters 0..N-1 keep their id, "no cluster" becomes N (sorted last).
uint kmeans_sort_key(uint cluster, uint cluster_count) { return min(cluster, cluster_count); }

// Squared feature distance, in exactly this operation order and without contraction, so that the
// CPU twin (kmeans_distance2 in harness/reference/kmeans_reference.cpp) gives the same float bit for bit:
// this is what makes "grid search == brute force" an exact property.
float kmeans_distance2(vec3 a, vec3 b) {
  precise vec3 d = a - b;
  precise float r = d.x * d.x + d.y * d.y;
  r = r + d.z * d.z;
  return r;
}

// Floats as uints whose unsigned order is the float order (for atomicMax-based min/max).
uint kmeans_order_float(float f) {
  uint u = floatBitsToUint(f);
  return (u & 0x80000000u) != 0u ? ~u : (u | 0x80000000u);
}
float kmeans_unorder_float(uint o) {
  return uintBitsToFloat((o & 0x80000000u) != 0u ? (o & 0x7FFFFFFFu) : ~o);
}

#endif  // KMEANS_COMMON_GLSL
