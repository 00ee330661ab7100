#ifndef ISM_LOOKUP_GLSL
#define ISM_LOOKUP_GLSL
// The visibility of a receiver from an imperfect shadow map's origin (DESIGN.md §8a.2): the
// fraction in [0, 1] of the PCF taps around the receiver's texel of level 0 whose distance is not
// nearer than the receiver. The includer sets ISM_MAPS_BINDING, the binding of the maps buffer
// (interface/ism.h: map after map, level 0 first), and includes interface/ism.h.
//
// Bias: the receiver x is first moved off its surface along its normal n_x (turned to face the
// origin) by normal_offset texel widths at its distance (normal offset, Holbert 2011). On a planar
// receiver at angle theta to the ray this puts it normal_offset * w / cos(theta) (w: a texel's width
// at x) in front of the surface along the ray, while the surface's depth changes by at most about
// sqrt(2) (r + 1) w tan(theta) over the taps of radius r: an offset above sqrt(2) (r + 1) texels
// clears the receiver of its own depths at any angle. depth_bias (relative) covers what is left:
// the error of a depth that pull-push interpolated.
#include "paraboloid.glsl"

layout(std430, binding = ISM_MAPS_BINDING) readonly buffer IsmMaps { uint ism_depths[]; };

// Map `map` (origin and hemisphere axis `origin`, `axis`) seen from receiver x with surface normal
// n_x (0: none, no offset). A receiver behind the map's plane is visible (1): nothing is stored
// there, and the VSGL's clamped cosine already sends it no light (DESIGN.md §8). So is one whose
// taps are all empty (a map without points). Taps whose centre lies outside the hemisphere's disk
// are left out: they stand for no direction.
float ism_visibility(IsmParams prm, uint map, vec3 origin, vec3 axis, vec3 x, vec3 n_x) {
  vec3 t, b;
  paraboloid_frame(axis, t, b);
  vec3 v = x - origin;
  float dist = length(v);
  if (!(dist > 0.0) || dot(v, axis) <= 0.0) return 1.0;
  vec3 d = v / dist;
  vec2 p = paraboloid_project(vec3(dot(d, t), dot(d, b), dot(d, axis)));
  vec3 facing = dot(n_x, d) > 0.0 ? -n_x : n_x;
  vec3 xo = x + facing * (prm.normal_offset * paraboloid_texel_angle(p, prm.side) * dist);
  v = xo - origin;
  dist = length(v);
  if (!(dist > 0.0) || dot(v, axis) <= 0.0) return 1.0;
  d = v / dist;
  p = paraboloid_project(vec3(dot(d, t), dot(d, b), dot(d, axis)));
  float nearest_visible = dist * (1.0 - prm.depth_bias);
  float step = 2.0 / float(prm.side);
  int r = int(prm.pcf_radius);
  uint base = map * prm.map_stride;
  float taps = 0.0;
  float visible = 0.0;
  for (int j = -r; j <= r; ++j)
    for (int i = -r; i <= r; ++i) {
      vec2 q = p + vec2(i, j) * step;
      if ((i != 0 || j != 0) && dot(q, q) > 1.0) continue;
      uvec2 texel = paraboloid_texel(q, prm.side);
      uint bits = ism_depths[base + texel.y * prm.side + texel.x];
      taps += 1.0;
      if (bits == kIsmEmpty || uintBitsToFloat(bits) >= nearest_visible) visible += 1.0;
    }
  return visible / taps;
}

#endif
