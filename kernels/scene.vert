#version 450
#extension GL_GOOGLE_include_directive : require
// Scene geometry for both views: world-space attributes pass through to capture.frag.
#include "scene_raster.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec3 in_diffuse;
layout(location = 3) in vec3 in_specular;
layout(location = 4) in float in_roughness;
layout(location = 5) in vec2 in_uv;
layout(location = 6) in vec4 in_tangent;

layout(location = 0) out vec3 out_position;
layout(location = 1) out vec3 out_normal;
layout(location = 2) flat out vec3 out_diffuse;
layout(location = 3) flat out vec3 out_specular;
layout(location = 4) flat out float out_roughness;
layout(location = 5) out vec2 out_uv;
layout(location = 6) out vec4 out_tangent;

void main() {
  out_position = in_position;
  out_normal = in_normal;
  out_diffuse = in_diffuse;
  out_specular = in_specular;
  out_roughness = in_roughness;
  out_uv = in_uv;
  out_tangent = in_tangent;
  gl_Position = raster.view_projection * vec4(in_position, 1.0);
}
