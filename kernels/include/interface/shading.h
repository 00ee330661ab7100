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
  uint vsgl_count;
  uint pad0;
  uint pad1;
  vec4 camera_position;
};
VSGL_LAYOUT(ShadePush, 48);
VSGL_VEC4_AT(ShadePush, camera_position, 32);

VSGL_INTERFACE_END

#endif  // VSGL_INTERFACE_SHADING_H
