#version 450
#extension GL_GOOGLE_include_directive : require
// FIS filtered sampling on the storage-buffer pyramid (`--pyramid buffer`, DESIGN.md §4): software
// trilinear filtering, bit-exact with the CPU reference. The pass: include/fis_filtered_sampling.glsl.
layout(std430, binding = 0) readonly buffer Pyramid { vec4 pyramid_texels[]; };
#include "pyramid.glsl"
#include "vsgl_math.glsl"
layout(std430, binding = 1) writeonly buffer Vsgls { Vsgl vsgls[]; };
#include "fis_filtered_sampling.glsl"
