#version 450
#extension GL_GOOGLE_include_directive : require
// Radix sort pass, step 1 of 3 (histogram -> scan -> scatter): digit counts of one tile.
#include "kmeans_radix.glsl"

shared uint bins[RADIX];

void main() {
  uint t = gl_LocalInvocationIndex;
  uint tile = kmeans_flat_group();
  bins[t] = 0u;
  barrier();
  if (tile < pc.tiles) {
    for (uint r = 0u; r < pc.rounds; ++r) {
      uint e = radix_element(tile, r);
      if (e < pc.count) atomicAdd(bins[radix_digit(radix_pair(e))], 1u);
    }
  }
  barrier();
  if (tile < pc.tiles) histogram[t * pc.tiles + tile] = bins[t];
}
