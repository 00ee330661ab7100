#ifndef SCENE_RASTER_GLSL
#define SCENE_RASTER_GLSL
// Push constants shared by scene.vert and capture.frag (interface/raster.h).
#include "interface/raster.h"
layout(push_constant) uniform PushBlock { RasterPush raster; };

// The material of one draw (set 0; mirrored by MaterialBlock in harness/scene/capture_recorder.cpp).
const uint kModelConstants = 0u;          // the vertex's albedos and roughness as they are
const uint kModelMetallicRoughness = 1u;  // glTF 2.0 (DESIGN.md §3)
const uint kModelVertexAlbedo = 2u;       // vertex albedos modulated by the maps
layout(set = 0, binding = 0, std140) uniform MaterialBlock {
  vec4 base_color_factor;  // linear rgb, alpha
  vec4 factors;            // x: metallic, y: perceptual roughness, z: normal scale, w: alpha cutoff
  uvec4 mode;              // x: model, y: 1 = alpha mask, z: 1 = double-sided
  uvec4 maps;              // x: base colour, y: metallic-roughness, z: normal map (1 = bound)
} material;
layout(set = 0, binding = 1) uniform sampler2D base_color_map;          // sRGB view: decoded to linear
layout(set = 0, binding = 2) uniform sampler2D metallic_roughness_map;  // G roughness, B metallic
layout(set = 0, binding = 3) uniform sampler2D normal_map;              // tangent space, [0,1] encoded
#endif
