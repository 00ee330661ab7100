// The single-pass mip chain's hand-over buffer between its two dispatches (DESIGN.md §6.1a):
// per moment layer, the in-bounds texels of levels 6..L, level after level, row-major.
// Needs pyramid_layout.glsl (pyramid_init called) and interface/fis.h.
#ifndef FIS_SPD_MID_GLSL
#define FIS_SPD_MID_GLSL

// Offset of level k (>= 6) in one layer's part of `mid`.
uint mid_offset(uint k) {
  uint offset = 0u;
  for (uint j = kFisSpdTileLevels; j < k; ++j) offset += pyramid_level_width(j) * pyramid_level_height(j);
  return offset;
}

// One layer's part of `mid`.
uint spd_mid_layer_texels() { return mid_offset(pyramid_levels + 1u); }

#endif
