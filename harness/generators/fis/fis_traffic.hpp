#pragma once
// The least memory traffic the FIS passes `additional` and `mipmapping` must cause for one view
// (DESIGN.md §9, "physical limit"): bytes that have to cross between memory and the chip whatever the
// kernel, pyramid path (buffer or texture) or mipmapping strategy, so that a pass's time can be
// set beside the device's copy bandwidth. For a view of W x H texels, levels l = 0..L of the
// virtual square (DESIGN.md §4) with in-bounds extents W_l x H_l, T_l = W_l * H_l texels:
//
//   additional:  read  = W * H * C * 4        (C = 15 float32 capture channels, DESIGN.md §3)
//                write = W * H * B            (B = 80: five vec4 float32 moment layers, DESIGN.md §4)
//   mipmapping:  read  = T_0 * B              (level 0, as `additional` left it)
//                write = (T_1 + ... + T_L) * B
//
// Counted once per byte, with no padding (the virtual square's padding and the upload's unused
// fourth float of the specular texel are not data). The PDF is the moment layer M2.w, so it is
// not counted twice even where a path keeps a separate PDF image. The mipmapping minimum reads
// only level 0: a single-pass downsampler keeps the intermediate levels on chip, so reading each
// level back (what a dispatch per level does, sum_{l<L} T_l * B) is the cost of a strategy, not
// of the pass; it is reported beside the minimum as the level-by-level count:
//   mipmapping, level by level: read = (T_0 + ... + T_{L-1}) * B, write = (T_1 + ... + T_L) * B.
// Neither count credits caches, so a fraction of copy bandwidth above 1 means the pass reused
// data on chip, not that the count is wrong.
#include <cstdint>
#include <string>

namespace vsgl {

struct PassBytes {
  uint64_t read = 0;
  uint64_t written = 0;
  uint64_t total() const { return read + written; }
};

struct FisPassBytes {
  PassBytes additional;
  PassBytes mipmapping;                 // the minimum: level 0 read, levels 1..L written
  PassBytes mipmapping_level_by_level;  // every level l < L read once, level l + 1 written
};

// Throws InputError (VirtualSquare::make) for an empty or oversized view.
FisPassBytes fis_minimum_bytes(uint32_t width, uint32_t height);
// The model above in one sentence, with its constants, for the table JSON.
std::string fis_traffic_model();

}  // namespace vsgl
