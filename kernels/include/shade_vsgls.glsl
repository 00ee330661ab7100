#ifndef SHADE_VSGLS_GLSL
#define SHADE_VSGLS_GLSL
// The shading pass (DESIGN.md §8 (a)): the camera view lit by N VSGLs. One thread per output pixel;
// output pixel (i, j) shades G-buffer texel (i * stride, j * stride), so a stride k > 1 gives a
// ceil(W / k) x ceil(H / k) preview. Radiance toward the camera is the sum over the VSGLs of
// vsgl_radiance_surface() in index order (the CPU twin, harness/quality/shading_pass.cpp, sums in
// the same order). The VSGLs stream through shared memory in tiles, one VSGL per thread per tile.
// A long sum is split into chunks of VSGLs, one dispatch each (so none runs long enough to trip a
// driver's watchdog); a later chunk starts from the sum the previous one stored and adds in the
// same index order, so the chunked image is bit for bit the one-dispatch image.
// Output: linear radiance (rgb, 1) per valid pixel, (0, 0, 0, 0) where the G-buffer has no surface.
//
// Visibility (DESIGN.md §8.1): a kernel that defines
// SHADE_VISIBILITY (shade_vsgls_ism.comp, shade_vsgls_exact.comp) declares, before including this,
//     float shade_visibility(Vsgl v, uint k, vec3 P, vec3 N)
// (k: the VSGL's index in this dispatch's chunk, P and N the receiver) and the push block
// { ShadePush pc; ShadeVisibilityParams vis; }; each VSGL's contribution is multiplied by it where
// the contribution is not zero (elsewhere the product is 0 anyway, and the lookup or the trace is
// saved). Without it (shade_vsgls.comp) the sum is the one without visibility, as before.
#include "vsgl_math.glsl"
#include "sg_eval.glsl"
#include "interface/shading.h"

// Half the group's threads load one VSGL each per tile: 128 records of 96 bytes keep the tile within
// the 16 KiB of shared memory every Vulkan device has.
const uint TILE = gl_WorkGroupSize.x * gl_WorkGroupSize.y / 2u;

#include "view_layers.glsl"  // the G-buffer, DeviceView layout
layout(std430, binding = 1) readonly buffer Lights { Vsgl vsgls[]; };
layout(std430, binding = 2) buffer Radiance { vec4 radiance[]; };

shared Vsgl tile[TILE];

#ifdef SHADE_VISIBILITY
float shade_visibility(Vsgl v, uint k, vec3 P, vec3 N);
#endif

void main() {
  uvec2 o = gl_GlobalInvocationID.xy;
  bool inside = o.x < pc.out_width && o.y < pc.out_height;
  uint i = inside ? (o.y * pc.stride) * pc.width + o.x * pc.stride : 0u;
  vec4 t0 = view_position_valid(i);
  vec4 t1 = view_normal_pdf(i);
  vec4 t2 = view_diffuse_roughness(i);
  vec4 t3 = view_specular(i);
  bool valid = inside && t0.w > 0.5;
  vec3 wo = normalize(pc.camera_position.xyz - t0.xyz);
  vec3 sum = vec3(0.0);
  if (inside && valid && pc.accumulate != 0u) sum = radiance[o.y * pc.out_width + o.x].xyz;
  // Every thread of the group takes part in the loads and barriers, inside the image or not.
  for (uint base = 0u; base < pc.vsgl_count; base += TILE) {
    uint c = base + gl_LocalInvocationIndex;
    if (gl_LocalInvocationIndex < TILE && c < pc.vsgl_count) tile[gl_LocalInvocationIndex] = vsgls[pc.first_vsgl + c];
    barrier();
    uint count = min(TILE, pc.vsgl_count - base);
    if (valid)
      for (uint k = 0u; k < count; ++k) {
#ifdef SHADE_VISIBILITY
        vec3 L = vsgl_radiance_surface(tile[k], t0.xyz, t1.xyz, wo, t2.rgb, t3.rgb, t2.w);
        if (L.r + L.g + L.b > 0.0) L *= shade_visibility(tile[k], base + k, t0.xyz, t1.xyz);
        sum += L;
#else
        sum += vsgl_radiance_surface(tile[k], t0.xyz, t1.xyz, wo, t2.rgb, t3.rgb, t2.w);
#endif
      }
    barrier();
  }
  if (inside) radiance[o.y * pc.out_width + o.x] = valid ? vec4(sum, 1.0) : vec4(0.0);
}

#endif
