// Push constants of the capture raster pipeline (kernels/scene.vert, kernels/capture.frag via
// kernels/include/scene_raster.glsl; host: harness/scene/capture_recorder.cpp), pushed to both
// stages. See interop.h for how C++ and GLSL share them.
#ifndef VSGL_INTERFACE_RASTER_H
#define VSGL_INTERFACE_RASTER_H
#include "interop.h"

VSGL_INTERFACE_BEGIN

// 112 bytes, within the 128 every device has.
struct RasterPush {
  mat4 view_projection;        // Vulkan clip space: y down, z in [0,1]
  vec4 source_position_mode;   // xyz: camera (G-buffer) or spot light (RSM) position; w: 0 camera, 1 light
  vec4 spot_axis_cos_cone;     // xyz: unit spot axis; w: cos of the cone half angle
  vec4 intensity_texel_area;   // rgb: spot intensity (W/sr); a: texel area on the unit image plane
};
VSGL_LAYOUT(RasterPush, 112);
VSGL_VEC4_AT(RasterPush, view_projection, 0);
VSGL_VEC4_AT(RasterPush, source_position_mode, 64);
VSGL_VEC4_AT(RasterPush, spot_axis_cos_cone, 80);
VSGL_VEC4_AT(RasterPush, intensity_texel_area, 96);

VSGL_INTERFACE_END

#endif  // VSGL_INTERFACE_RASTER_H
