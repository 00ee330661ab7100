#ifndef KMEANS_RADIX_GLSL
#define KMEANS_RADIX_GLSL
// One pass of the stable LSD radix sort of (cluster id, texel index) pairs by sort key (DESIGN.md §6.2
// `sort`): 8-bit digits, a tile of 256 * rounds consecutive elements per group. The first pass
// reads the assignment itself (the pair of element i is (assignment[i], i)), later passes the
// previous pass's output. Histograms are digit-major (hist[digit * tiles + tile]), so their
// exclusive scan is each (digit, tile)'s first output slot: smaller digits first, then tiles in
// order, then (in the scatter) elements in order within the tile — hence stable.
// No subgroup operations: the kernels work for any subgroup size.
#include "kmeans_common.glsl"

#include "interface/kmeans.h"
layout(local_size_x_id = 0) in;  // kKmeansRadixGroupSize: one thread per digit
layout(std430, binding = 0) readonly buffer Assignment { uint assignment[]; };
layout(std430, binding = 1) readonly buffer Source { uvec2 source_pairs[]; };
layout(std430, binding = 2) writeonly buffer Destination { uvec2 destination_pairs[]; };
layout(std430, binding = 3) buffer Histogram { uint histogram[]; };
layout(push_constant) uniform PushBlock { KmeansRadixPush pc; };

const uint RADIX = kKmeansRadix;

uvec2 radix_pair(uint e) { return pc.from_assignment != 0u ? uvec2(assignment[e], e) : source_pairs[e]; }
uint radix_digit(uvec2 pair) { return (kmeans_sort_key(pair.x, pc.clusters) >> pc.shift) & (RADIX - 1u); }
uint radix_element(uint tile, uint round) { return (tile * pc.rounds + round) * RADIX + gl_LocalInvocationIndex; }

#endif  // KMEANS_RADIX_GLSL
