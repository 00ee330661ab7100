#version 450
#extension GL_GOOGLE_include_directive : require
// k-means, `cluster_assignment`: the exact nearest centre of every texel's feature (DESIGN.md §6.2),
// ties to the lower cluster id, "no cluster" for texels outside every cluster.
// Search: the cells of the grid in rings (Chebyshev shells) around the texel's cell, until the
// best squared distance found is below the squared distance to the nearest face of the searched
// box that has cells beyond it (less a float margin, since a centre's cell index is rounded), or
// the box covers the whole grid. Every centre not yet visited lies beyond such a face, so the
// result equals brute force over all centres, with the same float distance (kmeans_distance2).
#include "interface/kmeans.h"
layout(local_size_x_id = 0) in;  // kKmeansWideGroupSize (interface/kmeans.h)
layout(std430, binding = 0) readonly buffer Grid { uint grid_words[]; };
#include "kmeans_grid.glsl"
layout(std430, binding = 1) readonly buffer Centres { vec4 centres[]; };
layout(std430, binding = 2) readonly buffer CellItems { uint cell_items[]; };
layout(std430, binding = 3) readonly buffer Features { vec4 features[]; };
layout(std430, binding = 4) writeonly buffer Assignment { uint assignment[]; };
layout(push_constant) uniform PushBlock { KmeansAssignPush pc; };

KmeansGrid grid;
vec3 feature;
float best_d2;
uint best_id;

void visit_cell(ivec3 c) {
  uint cell = kmeans_cell_index(grid, c);
  uint begin = grid_words[KMEANS_GRID_COUNTS + cell];
  uint end = grid_words[KMEANS_GRID_COUNTS + cell + 1u];
  for (uint s = begin; s < end; ++s) {
    uint id = cell_items[s];
    float d2 = kmeans_distance2(feature, centres[id].xyz);
    if (d2 < best_d2 || (d2 == best_d2 && id < best_id)) {
      best_d2 = d2;
      best_id = id;
    }
  }
}

// The cells at Chebyshev distance exactly r from `home` that lie inside the grid.
void visit_shell(ivec3 home, int r) {
  ivec3 lo = max(home - r, ivec3(0));
  ivec3 hi = min(home + r, grid.dims - 1);
  for (int z = lo.z; z <= hi.z; ++z) {
    bool z_face = abs(z - home.z) == r;
    for (int y = lo.y; y <= hi.y; ++y) {
      if (z_face || abs(y - home.y) == r) {
        for (int x = lo.x; x <= hi.x; ++x) visit_cell(ivec3(x, y, z));
      } else {
        if (home.x - r >= 0) visit_cell(ivec3(home.x - r, y, z));
        if (home.x + r < grid.dims.x) visit_cell(ivec3(home.x + r, y, z));
      }
    }
  }
}

void main() {
  uint i = kmeans_flat_invocation();
  if (i >= pc.texels) return;
  vec4 f = features[i];
  if (f.w < 0.0) {
    assignment[i] = KMEANS_NO_CLUSTER;
    return;
  }
  grid = kmeans_grid(pc.count, pc.max_cells);
  feature = f.xyz;
  best_d2 = uintBitsToFloat(0x7F800000u);  // +inf
  best_id = KMEANS_NO_CLUSTER;
  ivec3 home = kmeans_cell_of(grid, feature);
  for (int r = 0;; ++r) {
    visit_shell(home, r);
    // Distance from the feature to the nearest face of the searched box beyond which cells remain.
    float bound = uintBitsToFloat(0x7F800000u);
    bool more = false;
    for (int a = 0; a < 3; ++a) {
      if (home[a] - r > 0) {
        bound = min(bound, feature[a] - (grid.origin[a] + float(home[a] - r) * grid.cell));
        more = true;
      }
      if (home[a] + r < grid.dims[a] - 1) {
        bound = min(bound, grid.origin[a] + float(home[a] + r + 1) * grid.cell - feature[a]);
        more = true;
      }
    }
    if (!more) break;
    float safe = bound - grid.margin;
    if (safe > 0.0 && best_d2 < safe * safe * (1.0 - 1e-5)) break;
  }
  assignment[i] = best_id;
}
