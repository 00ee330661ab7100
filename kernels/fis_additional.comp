#version 450
#extension GL_GOOGLE_include_directive : require
// FIS "additional" pass writing level 0 of the storage-buffer pyramid (`--pyramid buffer`).
// The pass: include/fis_additional.glsl.
// The uploaded view: 4 layers of W*H texels: (P, valid), (N, pdf), (diffuse, roughness), (specular, 0).
#include "view_layers.glsl"
layout(std430, binding = 1) writeonly buffer Pyramid { vec4 pyramid_texels[]; };
#include "fis_additional.glsl"

void store_moments(uvec2 p, uint i, vec4 m0, vec4 m1, vec4 m2, vec4 m3, vec4 m4) {
  pyramid_texels[i] = m0;
  pyramid_texels[pc.pyramid_total + i] = m1;
  pyramid_texels[2u * pc.pyramid_total + i] = m2;
  pyramid_texels[3u * pc.pyramid_total + i] = m3;
  pyramid_texels[4u * pc.pyramid_total + i] = m4;
}
