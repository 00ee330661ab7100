#pragma once
// What the recorder needs from a scene's materials beyond the vertices: tangents for normal maps
// (computed when a file has none) and the full mip chain of every texture, built on the CPU so
// that the same texture gives the same levels on every device.
#include <cstdint>
#include <vector>

#include "harness/scene/scene.hpp"

namespace vsgl {

// Per-vertex tangents from the texture coordinates (accumulated over the triangles a vertex
// belongs to, as MikkTSpace does, without its vertex splitting): for each triangle the
// direction of +u and of +v on its plane, area-weighted; then made orthogonal to the vertex
// normal, with w = +1 or -1 for the handedness of (tangent, normal x tangent) against +v. A
// vertex whose triangles have degenerate texture coordinates gets any unit vector orthogonal to
// its normal. indices: a triangle list into `vertices`.
void compute_tangents(std::vector<SceneVertex>& vertices, const std::vector<uint32_t>& indices);

// One level of a mip chain: width * height * 4 values, in the texture's own encoding (sRGB bytes
// stay sRGB bytes, averaged in linear space).
struct MipLevel {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<uint8_t> rgba8;
  std::vector<float> rgba32f;
};

// Level 0 (the texture itself) down to 1x1; each level is the 2x2 box filter of the one above
// (edge texels repeated on odd sizes). Throws InputError for a texture whose pixel array does not
// match its size.
std::vector<MipLevel> build_mip_chain(const TextureImage& texture);

// The IEC 61966-2-1 sRGB transfer functions (what a *_SRGB Vulkan format decodes).
float srgb_to_linear(float encoded);
float linear_to_srgb(float linear);

}  // namespace vsgl
