#version 450
#extension GL_GOOGLE_include_directive : require
// Writes the capture channels of SPEC §3 into five RGBA32F render targets.
//  camera view (G-buffer): albedos and the camera PDF = luminance of the reflectance;
//  light view (RSM): flux Phi = I * dOmega_j * rho with dOmega_j = texel area * cos^3(theta_j),
//  zero outside the spot cone. The BRSM PDF is computed later from camera VSGLs (SPEC §8).
#include "scene_raster.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) flat in vec3 in_diffuse;
layout(location = 3) flat in vec3 in_specular;
layout(location = 4) flat in float in_roughness;

layout(location = 0) out vec4 out_position_valid;
layout(location = 1) out vec4 out_normal;
layout(location = 2) out vec4 out_diffuse;
layout(location = 3) out vec4 out_specular_roughness;
layout(location = 4) out vec4 out_pdf;

const vec3 kLuminance = vec3(0.2126, 0.7152, 0.0722);

void main() {
  vec3 n = normalize(in_normal);
  out_position_valid = vec4(in_position, 1.0);
  out_normal = vec4(n, 0.0);
  if (raster.source_position_mode.w < 0.5) {
    out_diffuse = vec4(in_diffuse, 0.0);
    out_specular_roughness = vec4(in_specular, in_roughness);
    out_pdf = vec4(dot(kLuminance, in_diffuse + in_specular), 0.0, 0.0, 0.0);
  } else {
    vec3 to_texel = normalize(in_position - raster.source_position_mode.xyz);
    float cos_theta = dot(to_texel, raster.spot_axis_cos_cone.xyz);
    float solid_angle = cos_theta >= raster.spot_axis_cos_cone.w
                            ? raster.intensity_texel_area.a * cos_theta * cos_theta * cos_theta
                            : 0.0;
    vec3 incident = raster.intensity_texel_area.rgb * solid_angle;  // W entering the texel's cone
    out_diffuse = vec4(incident * in_diffuse, 0.0);
    out_specular_roughness = vec4(incident * in_specular, in_roughness);
    out_pdf = vec4(0.0);
  }
}
