#ifndef SCENE_RASTER_GLSL
#define SCENE_RASTER_GLSL
// Push constants shared by scene.vert and capture.frag (112 bytes, within the 128 every device has).
layout(push_constant) uniform RasterPush {
  mat4 view_projection;        // Vulkan clip space: y down, z in [0,1]
  vec4 source_position_mode;   // xyz: camera (G-buffer) or spot light (RSM) position; w: 0 camera, 1 light
  vec4 spot_axis_cos_cone;     // xyz: unit spot axis; w: cos of the cone half angle
  vec4 intensity_texel_area;   // rgb: spot intensity (W/sr); a: texel area on the unit image plane
} raster;
#endif
