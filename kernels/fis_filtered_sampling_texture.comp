#version 450
#extension GL_GOOGLE_include_directive : require
// FIS filtered sampling on the sampled-image pyramid (`--pyramid texture`, DESIGN.md §6.1a): texelFetch
// for the hierarchical warp, one hardware-filtered textureLod per trilinear lookup, as the paper's
// GPU ran it. The pass: include/fis_filtered_sampling.glsl.
#include "vsgl_math.glsl"
layout(std430, binding = 0) writeonly buffer Vsgls { Vsgl vsgls[]; };
layout(binding = 1) uniform sampler2DArray pyramid_image;
#include "pyramid_texture.glsl"
#include "fis_filtered_sampling.glsl"
