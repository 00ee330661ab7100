// Push constants and work-group size of the shading pass (kernels/shade_vsgls.comp; host:
// harness/quality/shading_pass.cpp). See interop.h for how C++ and GLSL share them.
#ifndef VSGL_INTERFACE_SHADING_H
#define VSGL_INTERFACE_SHADING_H
#include "interop.h"
#include "ism.h"

VSGL_INTERFACE_BEGIN

// kShadeGroupSize x kShadeGroupSize threads, one per output pixel; the VSGLs stream through
// shared memory one per thread per tile.
VSGL_CONST uint kShadeGroupSize = 16u;

// Tok15 §3.3's alpha: a VSGL's rho(w) is pulled out of the integral where its sharpest lobe is below
// alpha * lambda_v (sg_eval.glsl). Tok15 leaves it to the user; 1 compares the two sharpnesses as
// they are. Every output that shades records it (DESIGN.md §8).
VSGL_CONST float kBiasReductionAlpha = 1.0;

struct ShadePush {
  uint width;       // G-buffer W x H
  uint height;
  uint out_width;   // ceil(W / stride) x ceil(H / stride)
  uint out_height;
  uint stride;
  uint vsgl_count;  // VSGLs [first_vsgl, first_vsgl + vsgl_count) of the buffer
  uint first_vsgl;
  uint accumulate;  // 1: add to the radiance already in the output (a later chunk), 0: start from 0
  vec4 camera_position;
};
VSGL_LAYOUT(ShadePush, 48);
VSGL_VEC4_AT(ShadePush, camera_position, 32);

// What the variants with visibility read beside ShadePush (shade_vsgls_ism.comp, _exact.comp;
// DESIGN.md §8.1): their push block is { ShadePush pc; ShadeVisibilityParams vis; }.
struct ShadeVisibilityParams {
  IsmParams ism;    // ism: the maps' parameters (interface/ism.h)
  uint map_first;   // ism: the map of the binding's first VSGL (maps follow the VSGLs' order)
  uint node_count;  // exact: the BVH's nodes (0: nothing occludes)
  float epsilon;    // exact: crossings within this distance (world units) of either end do not count
};
VSGL_LAYOUT(ShadeVisibilityParams, 48);

struct ShadeVisibilityPush {
  ShadePush shade;
  ShadeVisibilityParams vis;
};
VSGL_LAYOUT(ShadeVisibilityPush, 96);

VSGL_INTERFACE_END

#endif  // VSGL_INTERFACE_SHADING_H
