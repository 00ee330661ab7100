#version 450
#extension GL_GOOGLE_include_directive : require
// Writes the capture channels of DESIGN.md §3 into five RGBA32F render targets.
//  camera view (G-buffer): albedos and the camera PDF = luminance of the reflectance;
//  light view (RSM): flux Phi = I * dOmega_j * rho with dOmega_j = texel area * cos^3(theta_j),
//  zero outside the spot cone. The BRSM PDF is computed later from camera VSGLs (DESIGN.md §8).
// The surface comes from the draw's material: constants (procedural scenes, exactly the vertex
// values), glTF metallic-roughness, or vertex albedos modulated by textures; maps are sampled
// trilinearly from their full mip chains.
#include "scene_raster.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) flat in vec3 in_diffuse;
layout(location = 3) flat in vec3 in_specular;
layout(location = 4) flat in float in_roughness;
layout(location = 5) in vec2 in_uv;
layout(location = 6) in vec4 in_tangent;

layout(location = 0) out vec4 out_position_valid;
layout(location = 1) out vec4 out_normal;
layout(location = 2) out vec4 out_diffuse;
layout(location = 3) out vec4 out_specular_roughness;
layout(location = 4) out vec4 out_pdf;

const vec3 kLuminance = vec3(0.2126, 0.7152, 0.0722);
const float kMinGgxAlpha = 1e-3;  // what the generators clamp alpha to (CONVENTIONS.md)

void main() {
  vec3 n = normalize(in_normal);
  vec3 diffuse = in_diffuse;
  vec3 specular = in_specular;
  float roughness = in_roughness;
  if (material.mode.x != kModelConstants) {
    // Every map is read before any discard, in uniform control flow, so that the implicit
    // derivatives that choose the mip level are defined.
    vec4 base = material.base_color_factor;
    if (material.maps.x != 0u) base *= texture(base_color_map, in_uv);
    vec4 mr = material.maps.y != 0u ? texture(metallic_roughness_map, in_uv) : vec4(1.0);
    vec3 tangent_normal = material.maps.z != 0u ? texture(normal_map, in_uv).xyz * 2.0 - 1.0 : vec3(0.0, 0.0, 1.0);
    if (material.mode.y != 0u && base.a < material.factors.w) discard;  // alpha mask cut-out
    if (!gl_FrontFacing) n = -n;  // a double-sided surface seen from behind
    if (material.maps.z != 0u) {
      // Tangent frame of the interpolated vertex frame (glTF: bitangent = w * cross(n, t)).
      vec3 t = in_tangent.xyz - n * dot(n, in_tangent.xyz);
      if (dot(t, t) > 1e-12) {
        t = normalize(t);
        vec3 b = cross(n, t) * (in_tangent.w < 0.0 ? -1.0 : 1.0);
        if (!gl_FrontFacing) b = -b;
        tangent_normal.xy *= material.factors.z;
        vec3 mapped = t * tangent_normal.x + b * tangent_normal.y + n * tangent_normal.z;
        if (dot(mapped, mapped) > 1e-12) n = normalize(mapped);
      }
    }
    float perceptual = material.factors.y * mr.g;
    if (material.mode.x == kModelMetallicRoughness) {
      float metallic = clamp(material.factors.x * mr.b, 0.0, 1.0);
      vec3 colour = clamp(base.rgb * in_diffuse, 0.0, 1.0);  // in_diffuse: the vertex colour
      diffuse = colour * (1.0 - metallic);
      specular = mix(vec3(0.04), colour, metallic);
      roughness = clamp(perceptual * perceptual, kMinGgxAlpha, 1.0);
    } else {
      diffuse = clamp(in_diffuse * base.rgb, 0.0, 1.0);
      roughness = clamp(in_roughness * perceptual * perceptual, kMinGgxAlpha, 1.0);
    }
  }
  out_position_valid = vec4(in_position, 1.0);
  out_normal = vec4(n, 0.0);
  if (raster.source_position_mode.w < 0.5) {
    out_diffuse = vec4(diffuse, 0.0);
    out_specular_roughness = vec4(specular, roughness);
    out_pdf = vec4(dot(kLuminance, diffuse + specular), 0.0, 0.0, 0.0);
  } else {
    vec3 to_texel = normalize(in_position - raster.source_position_mode.xyz);
    float cos_theta = dot(to_texel, raster.spot_axis_cos_cone.xyz);
    float solid_angle = cos_theta >= raster.spot_axis_cos_cone.w
                            ? raster.intensity_texel_area.a * cos_theta * cos_theta * cos_theta
                            : 0.0;
    vec3 incident = raster.intensity_texel_area.rgb * solid_angle;  // W entering the texel's cone
    out_diffuse = vec4(incident * diffuse, 0.0);
    out_specular_roughness = vec4(incident * specular, roughness);
    out_pdf = vec4(0.0);
  }
}
