// Push constants and work-group sizes of the k-means kernels (kernels/kmeans_*.comp; host:
// harness/generators/kmeans/kmeans_generator.cpp). See interop.h for how C++ and GLSL share them.
#ifndef VSGL_INTERFACE_KMEANS_H
#define VSGL_INTERFACE_KMEANS_H
#include "interop.h"

VSGL_INTERFACE_BEGIN

// Work-group sizes (specialization constants 0 and 1 of the kernels).
VSGL_CONST uint kKmeansImageGroupSize = 16u;    // 16 x 16: per-texel passes over the image (prepare, pdf_mip)
VSGL_CONST uint kKmeansWideGroupSize = 256u;    // fill, assign, scan
VSGL_CONST uint kKmeansNarrowGroupSize = 64u;   // per-centre / per-cluster / per-chunk passes
VSGL_CONST uint kKmeansRadix = 256u;            // 8-bit digits of the radix sort
VSGL_CONST uint kKmeansRadixGroupSize = kKmeansRadix;  // one thread per digit (histogram and scatter)
VSGL_CONST uint kKmeansScanItems = 4u;          // values per thread of kmeans_scan_blocks / _add
VSGL_CONST uint kKmeansPieceVec4s = 6u;         // a segsum piece: the 5 moment sums and the pixel sum

// kmeans_fill.comp: words[offset .. offset + count) = value.
struct KmeansFillPush {
  uint offset;
  uint count;
  uint value;
};
VSGL_LAYOUT(KmeansFillPush, 12);

// kmeans_prepare.comp
struct KmeansPreparePush {
  uint width;
  uint height;
  uint camera_view;  // 1: G-buffer (w = luminance of reflectance), 0: RSM (w = flux sum)
  uint space3d;      // 0: kmeans_2d (pixels), 1: kmeans_3d (world position)
  vec4 source_position;
};
VSGL_LAYOUT(KmeansPreparePush, 32);
VSGL_VEC4_AT(KmeansPreparePush, source_position, 16);

// kmeans_pdf_mip.comp: level source_level + 1 of the PDF pyramid.
struct KmeansMipPush {
  uint width;
  uint height;
  uint source_level;
};
VSGL_LAYOUT(KmeansMipPush, 12);

// kmeans_seed.comp
struct KmeansSeedPush {
  uint width;
  uint height;
  uint count;        // N
  uint offset_bits;  // lattice offset o (DESIGN.md §5)
  uint space3d;
};
VSGL_LAYOUT(KmeansSeedPush, 20);

// kmeans_grid_count.comp, kmeans_grid_fill.comp
struct KmeansGridPush {
  uint count;  // N
  uint max_cells;
};
VSGL_LAYOUT(KmeansGridPush, 8);

// kmeans_assign.comp
struct KmeansAssignPush {
  uint texels;  // W * H
  uint count;   // N
  uint max_cells;
};
VSGL_LAYOUT(KmeansAssignPush, 12);

// kmeans_scan_blocks.comp (out_offset: where the block totals go) and kmeans_scan_add.comp
// (out_offset: the scanned block totals to add), both in the aux buffer.
struct KmeansScanPush {
  uint in_aux;      // 0: this level is in the target buffer, 1: in the aux buffer
  uint in_offset;   // first element of this level
  uint count;       // elements of this level
  uint out_offset;
};
VSGL_LAYOUT(KmeansScanPush, 16);

// kmeans_radix_histogram.comp, kmeans_radix_scatter.comp (kernels/include/kmeans_radix.glsl)
struct KmeansRadixPush {
  uint count;     // elements (W * H)
  uint clusters;  // N: the key of "no cluster"
  uint shift;     // bit offset of this pass's digit
  uint from_assignment;
  uint tiles;     // groups holding elements
  uint rounds;    // kKmeansRadix-element rounds per tile
};
VSGL_LAYOUT(KmeansRadixPush, 24);

// kmeans_ranges.comp
struct KmeansRangesPush {
  uint count;     // sorted elements (W * H)
  uint clusters;  // N
};
VSGL_LAYOUT(KmeansRangesPush, 8);

// kmeans_update_pieces.comp
struct KmeansPiecesPush {
  uint count;  // sorted elements (W * H)
  uint chunk;  // kKmeansChunk
};
VSGL_LAYOUT(KmeansPiecesPush, 8);

// kmeans_update_centres.comp
struct KmeansUpdatePush {
  uint clusters;  // N
  uint chunk;
};
VSGL_LAYOUT(KmeansUpdatePush, 8);

// kmeans_sum.comp, kmeans_segsum_pieces.comp, kmeans_segsum_clusters.comp
// (kernels/include/kmeans_sum_push.glsl)
struct KmeansSumPush {
  uint width;
  uint height;
  uint texels;       // W * H (sorted elements)
  uint clusters;     // N
  uint chunk;        // elements per piece of the segmented sum
  uint camera_view;  // 1: G-buffer, 0: RSM
  uint space3d;      // 0: kmeans_2d, 1: kmeans_3d
  uint square_size;  // S
  vec4 source_position;
};
VSGL_LAYOUT(KmeansSumPush, 48);
VSGL_VEC4_AT(KmeansSumPush, source_position, 32);

VSGL_INTERFACE_END

#endif  // VSGL_INTERFACE_KMEANS_H
