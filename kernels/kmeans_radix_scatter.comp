#version 450
#extension GL_GOOGLE_include_directive : require
// Radix sort pass, step 3 of 3: every element of a tile to its stable slot. Per 256-element
// round, each thread sets its bit in a 256-bit mask of its digit; its rank among the round's
// elements of that digit is the population count of the lower bits. A per-digit cursor (started
// at the scanned histogram) carries the count from round to round.
#include "kmeans_radix.glsl"

const uint MASK_WORDS = RADIX / 32u;
shared uint cursor[RADIX];
shared uint masks[RADIX * MASK_WORDS];

void main() {
  uint t = gl_LocalInvocationIndex;
  uint tile = kmeans_flat_group();
  bool active_tile = tile < pc.tiles;
  if (active_tile) cursor[t] = histogram[t * pc.tiles + tile];
  uint word = t >> 5u;
  uint bit = 1u << (t & 31u);
  for (uint r = 0u; r < pc.rounds; ++r) {
    for (uint k = 0u; k < MASK_WORDS; ++k) masks[t * MASK_WORDS + k] = 0u;
    barrier();
    uint e = radix_element(tile, r);
    bool valid = active_tile && e < pc.count;
    uvec2 pair = uvec2(0u);
    uint digit = 0u;
    if (valid) {
      pair = radix_pair(e);
      digit = radix_digit(pair);
      atomicOr(masks[digit * MASK_WORDS + word], bit);
    }
    barrier();
    bool last_of_digit = false;
    uint round_count = 0u;
    if (valid) {
      uint rank = bitCount(masks[digit * MASK_WORDS + word] & (bit - 1u));
      for (uint k = 0u; k < word; ++k) rank += bitCount(masks[digit * MASK_WORDS + k]);
      destination_pairs[cursor[digit] + rank] = pair;
      last_of_digit = (masks[digit * MASK_WORDS + word] & ~(bit | (bit - 1u))) == 0u;
      for (uint k = word + 1u; k < MASK_WORDS; ++k) last_of_digit = last_of_digit && masks[digit * MASK_WORDS + k] == 0u;
      for (uint k = 0u; k < MASK_WORDS; ++k) round_count += bitCount(masks[digit * MASK_WORDS + k]);
    }
    barrier();
    if (last_of_digit) cursor[digit] += round_count;
    barrier();
  }
}
