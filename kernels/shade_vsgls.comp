#version 450
#extension GL_GOOGLE_include_directive : require
// The shading pass without visibility (DESIGN.md §8 (a)): every VSGL reaches every receiver. The
// pass: include/shade_vsgls.glsl; the variants with visibility are shade_vsgls_ism.comp and
// shade_vsgls_exact.comp.
#include "interface/shading.h"

layout(local_size_x_id = 0, local_size_y_id = 1) in;  // kShadeGroupSize (interface/shading.h)
layout(push_constant) uniform PushBlock { ShadePush pc; };

#include "shade_vsgls.glsl"
