#pragma once
// The scene geometry a capture carries for visibility (DESIGN.md §3, §8a): its triangles, which the
// exact-visibility BVH is built on, and an area-weighted point sampling of them, which the
// imperfect shadow maps splat. Drawn once at record time so that every later run shades the same
// recorded inputs; stored in one little-endian binary file beside the EXR files, named with its
// counts and hash in the sidecar, and read only by the commands that shade with visibility.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "harness/math/surface_point.hpp"

namespace vsgl {

struct CaptureMeta;

inline constexpr const char* kVisibilityGeometryFile = "visibility_geometry.bin";

struct VisibilityGeometry {
  std::vector<glm::vec3> triangle_vertices;  // world space, three per triangle
  std::vector<SurfacePoint> points;          // the area-weighted point sampling
  uint64_t point_seed = 0;                   // the seed it was drawn with
  uint64_t triangle_count() const { return triangle_vertices.size() / 3; }
};

// What the sidecar says about the file (key "visibility_geometry").
struct VisibilityGeometryRecord {
  std::string file = kVisibilityGeometryFile;
  uint64_t triangles = 0;
  uint64_t points = 0;
  uint64_t point_seed = 0;
  std::string hash;  // "fnv1a64:<16 hex>" over the whole file
};

// The file's bytes: the magic "VSGLVIS1", a uint32 version (1) and a zero uint32, the uint64
// triangle count, point count and seed, then 9 floats per triangle, and per point 6 floats
// (position, normal) and the uint32 index of its triangle.
std::string encode_visibility_geometry(const VisibilityGeometry& geometry);
// Throws InputError naming `where` for a short or long file, a wrong magic or version, or a
// position or normal that is not finite, a normal that is not of unit length, or a point whose
// triangle is not in the file.
VisibilityGeometry decode_visibility_geometry(std::span<const char> bytes, const std::string& where);

// The sidecar's record of `geometry` written as `encoded` (its encode_visibility_geometry bytes):
// counts, seed and the file's hash.
VisibilityGeometryRecord visibility_geometry_record(const VisibilityGeometry& geometry, std::string_view encoded);

// Loads DIR's geometry and checks it against the sidecar's record (counts, seed, hash). A capture
// recorded without it is refused with a message naming the record option that stores it.
VisibilityGeometry load_visibility_geometry(const std::filesystem::path& dir, const CaptureMeta& meta);

}  // namespace vsgl
