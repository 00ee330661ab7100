// The FIS kernels' push constants and work-group sizes (DESIGN.md §6.1, §6.1a), shared by GLSL and
// harness/generators/fis/fis_generator.cpp through interop.h. Both pyramid paths (the storage
// buffer of DESIGN.md §4 and the sampled image of §6.1a) use these blocks.
#ifndef VSGL_INTERFACE_FIS_H
#define VSGL_INTERFACE_FIS_H
#include "interop.h"

VSGL_INTERFACE_BEGIN

VSGL_CONST uint kFisTile = 16u;          // 16x16 threads per group in the per-texel passes
VSGL_CONST uint kFisSamplingGroup = 64u; // threads per group in filtered sampling
// Single-pass downsampler: a 16x16 group reduces a 64x64 tile of level 0 to one level-6 texel.
VSGL_CONST uint kFisSpdTileLevels = 6u;
// Its second dispatch writes levels 7..14 (8 storage images, the desktop baseline's per-stage
// limit), so it takes squares of up to 2^14 texels.
VSGL_CONST uint kFisSpdTailLevelSlots = 8u;
// Moment layers per texel (DESIGN.md §4): (Phi, w), (w P, w |P|^2), (w N, q), (Phi_s, 0), (s d_s, 0).
VSGL_CONST uint kMomentLayers = 5u;

// fis_additional*.comp
struct FisAdditionalPush {
  vec4 source_position;  // camera (G-buffer) or spot light (RSM)
  uint width;
  uint height;
  uint pyramid_total;    // texels per buffer-pyramid layer (unused by the texture path)
  uint camera_view;      // 1: G-buffer (power = reflectance), 0: RSM (power = flux)
};
VSGL_LAYOUT(FisAdditionalPush, 32);
VSGL_VEC4_AT(FisAdditionalPush, source_position, 0);

// fis_mip_level*.comp (one dispatch per level) and fis_mip_single_pass*.comp
struct FisMipPush {
  uint width;
  uint height;
  uint source_level;     // per-level kernels: level l, writing l + 1
  uint reserved;         // 0 (keeps the block 16 bytes)
};
VSGL_LAYOUT(FisMipPush, 16);

// fis_filtered_sampling*.comp
struct FisSamplingPush {
  uint width;
  uint height;
  uint count;        // N
  uint offset_bits;  // per-frame lattice offset o in 32-bit fixed point (0 by default)
  float K;           // kernel-size parameter (paper: K = 1)
};
VSGL_LAYOUT(FisSamplingPush, 20);

VSGL_INTERFACE_END

#endif  // VSGL_INTERFACE_FIS_H
