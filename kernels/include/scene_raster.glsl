#ifndef SCENE_RASTER_GLSL
#define SCENE_RASTER_GLSL
// Push constants shared by scene.vert and capture.frag (interface/raster.h).
#include "interface/raster.h"
layout(push_constant) uniform PushBlock { RasterPush raster; };
#endif
