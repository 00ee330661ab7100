#version 450
#extension GL_GOOGLE_include_directive : require
// FIS "additional" pass writing level 0 of the sampled-image pyramid (`--pyramid texture`): the
// five moment layers are the image's array layers. The pass: include/fis_additional.glsl.
#include "view_layers.glsl"
layout(binding = 1, rgba32f) uniform writeonly image2DArray level0;
#include "fis_additional.glsl"

void store_moments(uvec2 p, uint i, vec4 m0, vec4 m1, vec4 m2, vec4 m3, vec4 m4) {
  imageStore(level0, ivec3(p, 0), m0);
  imageStore(level0, ivec3(p, 1), m1);
  imageStore(level0, ivec3(p, 2), m2);
  imageStore(level0, ivec3(p, 3), m3);
  imageStore(level0, ivec3(p, 4), m4);
}
