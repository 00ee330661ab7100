#ifndef PARABOLOID_GLSL
#define PARABOLOID_GLSL
// The paraboloid (hemisphere) parameterization of an imperfect shadow map (DESIGN.md §8a.2; Brabec
// et al. 2002): a unit direction d in the hemisphere about a map's axis n, written in the frame
// (t, b, n) as l = (l.x, l.y, l.z), l.z >= 0, maps to p = l.xy / (1 + l.z) in the unit disk, and
// back by l = (2 p, 1 - |p|^2) / (1 + |p|^2). Texel (i, j) of a side x side map covers
// p in [-1 + 2i/side, -1 + 2(i+1)/side] x [-1 + 2j/side, ...]. Shared by the splat (ism_splat.comp)
// and the lookup (ism_lookup.glsl); C++ twin: harness/visibility/paraboloid.hpp.

// An orthonormal frame (t, b, n) about the unit axis n, continuous except where n.z changes sign
// (Duff et al. 2017, "Building an orthonormal basis, revisited").
void paraboloid_frame(vec3 n, out vec3 t, out vec3 b) {
  float s = n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (s + n.z);
  float c = n.x * n.y * a;
  t = vec3(1.0 + s * n.x * n.x * a, s * c, -s * n.x);
  b = vec3(c, s + n.y * n.y * a, -n.y);
}

// The disk point of a direction given in the frame (l.z >= 0: the hemisphere).
vec2 paraboloid_project(vec3 l) { return l.xy / (1.0 + l.z); }

// The unit direction, in the frame, of a disk point (|p| <= 1).
vec3 paraboloid_unproject(vec2 p) {
  float r2 = dot(p, p);
  return vec3(2.0 * p, 1.0 - r2) / (1.0 + r2);
}

// The texel of side x side holding disk point p (clamped to the map).
uvec2 paraboloid_texel(vec2 p, uint side) {
  vec2 u = (p * 0.5 + 0.5) * float(side);
  return uvec2(clamp(ivec2(floor(u)), ivec2(0), ivec2(int(side) - 1)));
}

// The angle one texel spans at disk point p: its width 2/side in p times the map's linear scale
// 2 / (1 + |p|^2) (the square root of the solid angle per area of the disk, 4 / (1 + |p|^2)^2):
// 4/side at the axis, half of it at the rim.
float paraboloid_texel_angle(vec2 p, uint side) { return 4.0 / (float(side) * (1.0 + dot(p, p))); }

#endif
