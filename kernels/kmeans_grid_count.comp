#version 450
#extension GL_GOOGLE_include_directive : require
// k-means grid build, step 1 of 3 (count -> scan -> scatter): centres per cell. One thread per centre.
#include "interface/kmeans.h"
layout(local_size_x_id = 0) in;  // kKmeansNarrowGroupSize (interface/kmeans.h)
layout(std430, binding = 0) buffer Grid { uint grid_words[]; };
#include "kmeans_grid.glsl"
layout(std430, binding = 1) readonly buffer Centres { vec4 centres[]; };
layout(push_constant) uniform PushBlock { KmeansGridPush pc; };

void main() {
  uint k = kmeans_flat_invocation();
  if (k >= pc.count) return;
  KmeansGrid g = kmeans_grid(pc.count, pc.max_cells);
  uint cell = kmeans_cell_index(g, kmeans_cell_of(g, centres[k].xyz));
  atomicAdd(grid_words[KMEANS_GRID_COUNTS + cell], 1u);
}
