#include "harness/capture/visibility_geometry.hpp"

#include <bit>
#include <cmath>
#include <cstring>

#include "harness/capture/capture.hpp"
#include "harness/capture/capture_sidecar.hpp"
#include "harness/core/error.hpp"
#include "harness/core/path_text.hpp"
#include "harness/core/text_file.hpp"

namespace vsgl {
namespace {

// The file is defined little-endian, float32 and uint64 as the machine lays them out.
static_assert(std::endian::native == std::endian::little);
constexpr char kMagic[8] = {'V', 'S', 'G', 'L', 'V', 'I', 'S', '1'};
constexpr uint32_t kVersion = 1;
constexpr std::size_t kHeaderBytes = 8 + 4 + 4 + 3 * 8;
constexpr std::size_t kTriangleBytes = 9 * sizeof(float);
constexpr std::size_t kPointBytes = 6 * sizeof(float) + sizeof(uint32_t);
// Normals are written as unit vectors in float32; anything further off was not written by us.
constexpr float kUnitTolerance = 1e-3f;

template <typename T>
void put(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

template <typename T>
T take(std::span<const char> bytes, std::size_t& at) {
  T value;
  std::memcpy(&value, bytes.data() + at, sizeof value);
  at += sizeof value;
  return value;
}

glm::vec3 take_vec3(std::span<const char> bytes, std::size_t& at) {
  const float x = take<float>(bytes, at), y = take<float>(bytes, at), z = take<float>(bytes, at);
  return {x, y, z};
}

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

std::string encode_visibility_geometry(const VisibilityGeometry& g) {
  if (g.triangle_vertices.size() % 3 != 0)
    throw InputError("visibility geometry: " + std::to_string(g.triangle_vertices.size()) +
                     " triangle vertices is not a whole number of triangles");
  std::string out;
  out.reserve(kHeaderBytes + g.triangle_count() * kTriangleBytes + g.points.size() * kPointBytes);
  out.append(kMagic, sizeof kMagic);
  put(out, kVersion);
  put(out, uint32_t{0});
  put(out, uint64_t{g.triangle_count()});
  put(out, uint64_t{g.points.size()});
  put(out, g.point_seed);
  for (const glm::vec3& v : g.triangle_vertices) put(out, v);
  for (const SurfacePoint& p : g.points) {
    put(out, p.position);
    put(out, p.normal);
    put(out, p.triangle);
  }
  return out;
}

VisibilityGeometry decode_visibility_geometry(std::span<const char> bytes, const std::string& where) {
  if (bytes.size() < kHeaderBytes || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
    throw InputError(where + ": not a visibility geometry file (no VSGLVIS1 header)");
  std::size_t at = sizeof kMagic;
  const uint32_t version = take<uint32_t>(bytes, at);
  take<uint32_t>(bytes, at);
  if (version != kVersion)
    throw InputError(where + ": visibility geometry version " + std::to_string(version) + ", this version reads " +
                     std::to_string(kVersion));
  const uint64_t triangles = take<uint64_t>(bytes, at), points = take<uint64_t>(bytes, at);
  VisibilityGeometry g;
  g.point_seed = take<uint64_t>(bytes, at);
  // Counts are checked against the size before anything is allocated by them.
  const uint64_t rest = bytes.size() - kHeaderBytes;
  if (triangles > rest / kTriangleBytes || points > (rest - triangles * kTriangleBytes) / kPointBytes ||
      triangles * kTriangleBytes + points * kPointBytes != rest)
    throw InputError(where + ": " + std::to_string(bytes.size()) + " bytes, but its header announces " +
                     std::to_string(triangles) + " triangles and " + std::to_string(points) + " points (" +
                     std::to_string(kHeaderBytes + triangles * kTriangleBytes + points * kPointBytes) + " bytes)");
  g.triangle_vertices.resize(triangles * 3);
  for (std::size_t i = 0; i < g.triangle_vertices.size(); ++i) {
    g.triangle_vertices[i] = take_vec3(bytes, at);
    if (!finite(g.triangle_vertices[i]))
      throw InputError(where + ": triangle " + std::to_string(i / 3) + " has a vertex that is not finite");
  }
  g.points.resize(points);
  for (std::size_t i = 0; i < g.points.size(); ++i) {
    SurfacePoint& p = g.points[i];
    p.position = take_vec3(bytes, at);
    p.normal = take_vec3(bytes, at);
    p.triangle = take<uint32_t>(bytes, at);
    if (!finite(p.position) || !finite(p.normal) || std::abs(glm::length(p.normal) - 1.0f) > kUnitTolerance)
      throw InputError(where + ": point " + std::to_string(i) +
                       " has a position or normal that is not finite, or a normal not of unit length");
    if (p.triangle >= triangles)
      throw InputError(where + ": point " + std::to_string(i) + " lies on triangle " + std::to_string(p.triangle) +
                       ", but the file holds " + std::to_string(triangles));
  }
  return g;
}

VisibilityGeometryRecord visibility_geometry_record(const VisibilityGeometry& g, std::string_view encoded) {
  VisibilityGeometryRecord r;
  r.triangles = g.triangle_count();
  r.points = g.points.size();
  r.point_seed = g.point_seed;
  r.hash = bytes_hash(encoded);
  return r;
}

VisibilityGeometry load_visibility_geometry(const std::filesystem::path& dir, const CaptureMeta& meta) {
  if (!meta.visibility_geometry)
    throw InputError(path_text(dir / kSidecarName) +
                     ": the capture has no visibility geometry (the scene's triangles and their point sampling), so "
                     "it cannot be shaded with visibility; record it again with vsgl-bench record, which stores it "
                     "unless --visibility-points 0 is given, or shade it with --visibility none");
  const VisibilityGeometryRecord& rec = *meta.visibility_geometry;
  const std::filesystem::path path = dir / rec.file;
  const std::string bytes = read_text_file(path, "the capture's visibility geometry");
  const std::string where = path_text(path);
  if (const std::string actual = bytes_hash(bytes); actual != rec.hash)
    throw InputError(where + ": its hash is " + actual + ", the sidecar says " + rec.hash +
                     " (the file was changed or replaced); record the capture again");
  VisibilityGeometry g = decode_visibility_geometry(bytes, where);
  if (g.triangle_count() != rec.triangles || g.points.size() != rec.points || g.point_seed != rec.point_seed)
    throw InputError(where + ": holds " + std::to_string(g.triangle_count()) + " triangles, " +
                     std::to_string(g.points.size()) + " points, seed " + std::to_string(g.point_seed) +
                     "; the sidecar says " + std::to_string(rec.triangles) + ", " + std::to_string(rec.points) +
                     ", seed " + std::to_string(rec.point_seed));
  return g;
}

}  // namespace vsgl
