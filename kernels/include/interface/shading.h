// Push constants and work-group size of the shading pass (kernels/shade_vsgls.comp; host:
// harness/quality/shading_pass.cpp). See interop.h for how C++ and GLSL share them.
#ifndef VSGL_INTERFACE_SHADING_H
#define VSGL_INTERFACE_SHADING_H
#include "interop.h"

VSGL_INTERFACE_BEGIN

// kShadeGroupSize x kShadeGroupSize threads, one per output pixel; the VSGLs stream through
// shared memory one per thread per tile.
VSGL_CONST uint kShadeGroupSize = 16u;

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

VSGL_INTERFACE_END

#endif  // VSGL_INTERFACE_SHADING_H
