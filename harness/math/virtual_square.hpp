#pragma once
// The virtual square of DESIGN.md §4 and the flat layout of a pyramid over it, shared by the GPU host
// code (buffer sizes, per-level offsets in push constants) and the CPU reference.
//
// An image W x H sits at the origin of an S x S square, S = the next power of two >= max(W, H),
// L = log2 S. Level l stores only its in-bounds extent ceil(W / 2^l) x ceil(H / 2^l) (level L is
// 1 x 1); levels are stored one after another, row-major: offset(0) = 0,
// offset(l + 1) = offset(l) + W_l * H_l.
#include <cstdint>
#include <string>

#include "harness/core/error.hpp"

namespace vsgl {

struct VirtualSquare {
  // The largest image side accepted: keeps M = S^2 and every pyramid offset within uint32 and
  // M exactly representable as a float (a power of two below 2^31).
  static constexpr uint32_t kMaxSide = 16384;

  uint32_t width = 0;   // W
  uint32_t height = 0;  // H
  uint32_t size = 0;    // S
  uint32_t levels = 0;  // L (so there are L + 1 stored levels)

  // Throws InputError naming `what` (a file or a view) for an empty or oversized image.
  static VirtualSquare make(uint32_t w, uint32_t h, const std::string& what = "image") {
    if (w == 0 || h == 0)
      throw InputError(what + ": image is empty (" + std::to_string(w) + "x" + std::to_string(h) + ")");
    if (w > kMaxSide || h > kMaxSide)
      throw InputError(what + ": image " + std::to_string(w) + "x" + std::to_string(h) +
                       " exceeds the largest supported side " + std::to_string(kMaxSide));
    VirtualSquare sq;
    sq.width = w;
    sq.height = h;
    const uint32_t side = w > h ? w : h;
    sq.size = 1;
    sq.levels = 0;
    while (sq.size < side) {
      sq.size <<= 1;
      ++sq.levels;
    }
    return sq;
  }

  // Extent of level l (in-bounds texels only): ceil(W / 2^l), ceil(H / 2^l).
  uint32_t level_width(uint32_t l) const { return ((width - 1) >> l) + 1; }
  uint32_t level_height(uint32_t l) const { return ((height - 1) >> l) + 1; }
  uint32_t level_texels(uint32_t l) const { return level_width(l) * level_height(l); }
  // Flat index of level l's first texel.
  uint32_t level_offset(uint32_t l) const {
    uint32_t offset = 0;
    for (uint32_t k = 0; k < l; ++k) offset += level_texels(k);
    return offset;
  }
  // Texels of all L + 1 levels together (the element count of a pyramid buffer).
  uint32_t total_texels() const { return level_offset(levels + 1); }
  // M of the paper: texels of the virtual square, S^2.
  uint32_t square_texels() const { return size * size; }
};

}  // namespace vsgl
