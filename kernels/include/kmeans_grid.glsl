#ifndef KMEANS_GRID_GLSL
#define KMEANS_GRID_GLSL
// The uniform grid that accelerates the exact nearest-centre search of k-means (DESIGN.md §6.2).
// The includer declares `grid_words` (uint[]), laid out as
//   [0..2] ~order(min feature), [3..5] order(max feature)   (atomicMax-reduced in kmeans_prepare)
//   [8 .. 8 + cells]          per-cell centre counts, scanned in place into cell starts (+ total)
//   [9 + max_cells ..]        per-cell fill cursors of the scatter
// Every invocation derives the grid (origin, cubic cell size, dims) from the feature bounds with
// the same code, so all agree without another pass. The grid holds about
// KMEANS_CELLS_PER_CENTRE cells per centre over the features' bounding box; the cell size is
// chosen for the box's real dimensionality (a flat box of a 2D feature space or of a wall gets a
// 2D grid, not a 3D one of mostly empty cells).
#include "kmeans_common.glsl"

const float KMEANS_CELLS_PER_CENTRE = 2.0;
const uint KMEANS_GRID_COUNTS = 8u;

struct KmeansGrid {
  vec3 origin;
  float cell;    // edge of a cubic cell
  ivec3 dims;    // cells per axis (>= 1)
  float margin;  // float slack of the search's stopping bound (cell indices of centres are rounded)
};

uint kmeans_grid_fill_base(uint max_cells) { return KMEANS_GRID_COUNTS + max_cells + 1u; }

ivec3 kmeans_grid_dims(vec3 extent, float cell) {
  return clamp(ivec3(ceil(extent / cell)), ivec3(1), ivec3(1 << 20));
}

KmeansGrid kmeans_grid(uint centre_count, uint max_cells) {
  vec3 lo = vec3(kmeans_unorder_float(~grid_words[0]), kmeans_unorder_float(~grid_words[1]),
                 kmeans_unorder_float(~grid_words[2]));
  vec3 hi = vec3(kmeans_unorder_float(grid_words[3]), kmeans_unorder_float(grid_words[4]),
                 kmeans_unorder_float(grid_words[5]));
  vec3 e = max(hi - lo, vec3(0.0));
  float target = float(centre_count) * KMEANS_CELLS_PER_CENTRE;
  float e_max = max(e.x, max(e.y, e.z));
  float e_min = min(e.x, min(e.y, e.z));
  float e_mid = max(min(e.x, e.y), min(max(e.x, e.y), e.z));
  float cell = pow(e.x * e.y * e.z / target, 1.0 / 3.0);  // 3D box
  if (!(cell > 0.0 && cell <= e_min)) cell = sqrt(e_mid * e_max / target);  // flat box: 2D grid
  if (!(cell > 0.0 && cell <= e_mid)) cell = e_max / target;                // thin box: 1D grid
  if (!(cell > 0.0)) cell = 1.0;                              // all features equal: one cell
  ivec3 dims = kmeans_grid_dims(e, cell);
  // ceil() can add up to one cell per axis; grow the cells until the grid fits its buffer.
  while (uint(dims.x) * uint(dims.y) * uint(dims.z) > max_cells) {
    cell *= 1.25;
    dims = kmeans_grid_dims(e, cell);
  }
  KmeansGrid g;
  g.origin = lo;
  g.cell = cell;
  g.dims = dims;
  vec3 a = max(abs(lo), abs(hi));
  g.margin = 1e-3 * cell + 1e-6 * max(a.x, max(a.y, a.z));
  return g;
}

ivec3 kmeans_cell_of(KmeansGrid g, vec3 f) {
  return clamp(ivec3(floor((f - g.origin) / g.cell)), ivec3(0), g.dims - 1);
}
uint kmeans_cell_index(KmeansGrid g, ivec3 c) { return uint((c.z * g.dims.y + c.y) * g.dims.x + c.x); }

#endif  // KMEANS_GRID_GLSL
