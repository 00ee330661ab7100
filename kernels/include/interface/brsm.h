// Push constants and work-group size of the BRSM PDF pass (kernels/brsm_pdf.comp; host:
// harness/scene/brsm_pdf.cpp). See interop.h for how C++ and GLSL share them.
#ifndef VSGL_INTERFACE_BRSM_H
#define VSGL_INTERFACE_BRSM_H
#include "interop.h"

VSGL_INTERFACE_BEGIN

// kBrsmGroupSize x kBrsmGroupSize threads, one per RSM texel; the camera VSGLs stream through
// shared memory one per thread per tile.
VSGL_CONST uint kBrsmGroupSize = 16u;

struct BrsmPush {
  uint width;  // RSM W x H
  uint height;
  uint camera_count;
  uint pad;
  vec4 light_position;
};
VSGL_LAYOUT(BrsmPush, 32);
VSGL_VEC4_AT(BrsmPush, light_position, 16);

VSGL_INTERFACE_END

#endif  // VSGL_INTERFACE_BRSM_H
