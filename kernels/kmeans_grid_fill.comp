#version 450
#extension GL_GOOGLE_include_directive : require
// k-means grid build, step 3 of 3: each centre's id into its cell's slice of the cell list (the
// counts were scanned into cell starts). The order inside a cell depends on the atomics, but the
// search's result does not: it keeps the smallest (distance, id) pair.
#include "interface/kmeans.h"
layout(local_size_x_id = 0) in;  // kKmeansNarrowGroupSize (interface/kmeans.h)
layout(std430, binding = 0) buffer Grid { uint grid_words[]; };
#include "kmeans_grid.glsl"
layout(std430, binding = 1) readonly buffer Centres { vec4 centres[]; };
layout(std430, binding = 2) writeonly buffer CellItems { uint cell_items[]; };
layout(push_constant) uniform PushBlock { KmeansGridPush pc; };

void main() {
  uint k = kmeans_flat_invocation();
  if (k >= pc.count) return;
  KmeansGrid g = kmeans_grid(pc.count, pc.max_cells);
  uint cell = kmeans_cell_index(g, kmeans_cell_of(g, centres[k].xyz));
  uint slot = grid_words[KMEANS_GRID_COUNTS + cell] + atomicAdd(grid_words[kmeans_grid_fill_base(pc.max_cells) + cell], 1u);
  cell_items[slot] = k;
}
