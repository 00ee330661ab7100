#pragma once
// Procedural surface detail for the built-in scenes (DESIGN.md §3): tiles and grout, masonry and
// brick, wall panels, carpet, wood grain, smudged gloss. Like a real asset's texture set, each
// pattern is an albedo map, a roughness map and, where the surface has relief, a normal map,
// mipmapped by the recorder. Deterministic: integer hashes and polynomial value noise, no random
// engine; libm enters only through sqrt and the sRGB encode before rounding to 8 bits.
//
// Every pattern covers 1 m x 1 m of surface at kDetailTexelsPerMetre and repeats seamlessly
// (the builders' texture coordinates are metres), so every feature size below is in metres and
// divides 1 m.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "harness/scene/scene.hpp"
#include "harness/scene/scene_geometry.hpp"

namespace vsgl {

inline constexpr uint32_t kDetailTexelsPerMetre = 256;  // 3.9 mm texels

// One pattern before it becomes textures: per texel (rows top to bottom, v down the rows).
struct DetailPlanes {
  std::string name;
  uint32_t size = kDetailTexelsPerMetre;  // texels per side
  std::vector<glm::vec3> albedo;          // linear factor on the surface's diffuse albedo, in [0,1]
  std::vector<float> alpha;               // GGX alpha, in (0,1]
  std::vector<float> height;              // relief in metres; empty: a flat surface (no normal map)
};

// The atrium's polished floor: 50 cm stone tiles, 8 mm recessed grout; per-tile tint and
// clouding; polish (alpha 0.08-0.2) against rough grout (0.85).
DetailPlanes stone_floor_tiles();
// Dressed stone blocks, 50 x 25 cm in running bond, bevelled 10 mm joints, chisel texture.
DetailPlanes ashlar_wall();
// Honed, speckled stone for columns and plinths: clouding, dark grains, fine relief.
DetailPlanes speckled_stone();
// 50 cm carpet tiles laid quarter-turned (alternate pile shade), fibre noise, seams.
DetailPlanes carpet_tiles();
// Painted brick, 25 x 6.25 cm in running bond, recessed 8 mm mortar, eggshell paint.
DetailPlanes painted_brick();
// Painted wall boards 25 cm wide with V-grooves (vertical on walls), orange-peel relief.
DetailPlanes wall_panels();
// Planks 12.5 cm wide along u with growth rings and per-plank tint; lacquer_alpha is the GGX
// alpha of the finish (0.07 polished table top, 0.4 satin), rougher in the open pores.
DetailPlanes wood_grain(float lacquer_alpha);
// A glossy board (alpha 0.06) with wiped smudges up to alpha 0.3.
DetailPlanes smudged_gloss();

// A pattern added to a scene: its material, and the largest alpha of its roughness map.
struct DetailMaterial {
  uint32_t material = kNoMaterial;
  float max_alpha = 1.0f;
};

// The pattern as a material of `scene`: an sRGB albedo map, a roughness map and (with relief) a
// tangent-space normal map, 8 bits per channel, appended to scene.textures; one
// MaterialModel::kVertexAlbedo material appended to scene.materials, which surfaces of
// different colours share. Throws std::logic_error for planes of the wrong size.
DetailMaterial add_surface_detail(Scene& scene, const DetailPlanes& detail);

// The surface to build geometry with: the vertex albedos (the albedo map multiplies `diffuse`),
// and as its roughness the pattern's largest alpha, which the map's G channel scales down
// (kVertexAlbedo: alpha = vertex roughness * G^2).
SurfaceMaterial detailed_surface(const DetailMaterial& detail, glm::vec3 diffuse, glm::vec3 specular);

// The tangent-space normal of a height field (metres, periodic, texel pitch 1/size m) at texel
// (x, y): normalize(-dh/du, -dh/dv, 1), central differences. +u is +x (columns), +v is +y (rows),
// the frame of the builders' tangents (bitangent = +v).
glm::vec3 height_normal(const std::vector<float>& height, uint32_t size, uint32_t x, uint32_t y);

}  // namespace vsgl
