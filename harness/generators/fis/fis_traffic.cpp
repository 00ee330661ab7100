#include "harness/generators/fis/fis_traffic.hpp"

#include "harness/capture/capture.hpp"
#include "harness/math/virtual_square.hpp"
#include "harness/math/vsgl_math.hpp"

namespace vsgl {
namespace {

constexpr uint64_t kCaptureTexelBytes = uint64_t{kChannelCount} * sizeof(float);
// m0..m4: 5 x vec4, the two reserved .w of m3 and m4 included (they are stored and moved).
constexpr uint64_t kMomentTexelBytes = sizeof(TexelMoments);
static_assert(kMomentTexelBytes == 80, "five vec4 float32 moment layers (DESIGN.md §4)");

}  // namespace

std::string fis_traffic_model() {
  const std::string c = std::to_string(kCaptureTexelBytes), m = std::to_string(kMomentTexelBytes);
  return "additional: W*H texels x (" + c + " B read: " + std::to_string(int{kChannelCount}) +
         " float32 capture channels; " + m +
         " B written: 5 vec4 float32 moment layers); mipmapping: level 0 read once (" + m +
         " B per texel) and levels 1..L written once (" + m +
         " B per in-bounds texel); level_by_level: every level l < L read once and level l + 1 written; no padding "
         "counted, no credit for caches";
}

FisPassBytes fis_minimum_bytes(uint32_t width, uint32_t height) {
  const VirtualSquare sq = VirtualSquare::make(width, height, "view");
  FisPassBytes b;
  const uint64_t texels = uint64_t{width} * height;
  b.additional.read = texels * kCaptureTexelBytes;
  b.additional.written = texels * kMomentTexelBytes;
  b.mipmapping.read = uint64_t{sq.level_texels(0)} * kMomentTexelBytes;
  for (uint32_t l = 1; l <= sq.levels; ++l) b.mipmapping.written += uint64_t{sq.level_texels(l)} * kMomentTexelBytes;
  b.mipmapping_level_by_level.written = b.mipmapping.written;
  for (uint32_t l = 0; l < sq.levels; ++l)
    b.mipmapping_level_by_level.read += uint64_t{sq.level_texels(l)} * kMomentTexelBytes;
  return b;
}

}  // namespace vsgl
