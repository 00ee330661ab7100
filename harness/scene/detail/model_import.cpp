#include "harness/scene/detail/model_import.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include "harness/scene/scene_geometry.hpp"

namespace vsgl::gltf {

SceneBounds triangle_bounds(const SceneMesh& mesh, const Reporter& r) {
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (uint32_t i : mesh.indices) {
    lo = glm::min(lo, mesh.vertices[i].position);
    hi = glm::max(hi, mesh.vertices[i].position);
  }
  SceneBounds b;
  b.lo = lo;
  b.hi = hi;
  b.centre = 0.5f * (lo + hi);
  b.radius = std::max(0.5f * glm::length(hi - lo), 1e-3f);
  if (!std::isfinite(b.radius)) r.fail("its bounds are not finite");
  b.far_lo = lo;
  b.far_hi = hi;
  return b;
}

void add_ground(SceneMesh& mesh, SceneBounds& b, std::vector<std::string>& notes) {
  const float y = b.lo.y - 1e-3f * b.radius;
  const glm::vec3 g_lo(b.centre.x - 3.0f * b.radius, y, b.centre.z - 3.0f * b.radius);
  const glm::vec3 g_hi(b.centre.x + 3.0f * b.radius, y, b.centre.z + 3.0f * b.radius);
  const SurfaceMaterial grey{glm::vec3(0.5f), glm::vec3(0.04f), 0.5f, kNoMaterial};
  const std::size_t before = mesh.indices.size();
  add_axis_rect(mesh, g_lo, g_hi, {0.0f, 1.0f, 0.0f}, grey, b.radius);
  char where[64];
  std::snprintf(where, sizeof where, "%.4g", static_cast<double>(y));
  notes.push_back("--ground: a grey floor of " + std::to_string((mesh.indices.size() - before) / 3) +
                  " triangles added at y = " + where);
  b.far_lo = glm::min(b.far_lo, g_lo);
  b.far_hi = glm::max(b.far_hi, g_hi);
}

void conversion_notes(const Conversion& conv, std::vector<std::string>& notes) {
  if (conv.skipped_non_triangle > 0)
    notes.push_back(std::to_string(conv.skipped_non_triangle) + " point/line primitives skipped (no surface)");
  if (conv.normals_normalized > 0)
    notes.push_back(std::to_string(conv.normals_normalized) + " normals were not unit length and were normalized");
  if (conv.normals_replaced > 0)
    notes.push_back(std::to_string(conv.normals_replaced) +
                    " normals were zero or not finite and were replaced by the surface's normal");
  if (conv.tangents_computed > 0)
    notes.push_back("tangents computed for " + std::to_string(conv.tangents_computed) + " normal-mapped vertices");
  for (const std::string& u : conv.unmapped) notes.push_back("not mapped: " + u);
}

TextureImage rgba8_texture(const tinygltf::Image& img, bool srgb, const std::string& what,
                           const std::string& image_name, const Reporter& r) {
  if (img.image.empty() || img.width <= 0 || img.height <= 0)
    r.fail(what + ": " + image_name +
           " is missing or could not be decoded");
  const int comps = img.component;
  const int bytes_per = img.bits == 16 ? 2 : 1;
  const std::size_t texels = static_cast<std::size_t>(img.width) * static_cast<std::size_t>(img.height);
  if (comps < 1 || comps > 4 || (img.bits != 8 && img.bits != 16) ||
      img.image.size() != texels * static_cast<std::size_t>(comps * bytes_per))
    r.fail(what + ": " + image_name + " has an unsupported pixel layout (" + std::to_string(comps) + " channels of " +
           std::to_string(img.bits) + " bits)");
  TextureImage out;
  out.name = escape_name(img.name.empty() ? img.uri.rfind("data:", 0) == 0 ? "embedded" : img.uri : img.name);
  out.width = static_cast<uint32_t>(img.width);
  out.height = static_cast<uint32_t>(img.height);
  out.srgb = srgb;
  out.rgba8.resize(texels * 4);
  for (std::size_t i = 0; i < texels; ++i) {
    uint8_t v[4] = {0, 0, 0, 255};
    for (int c = 0; c < comps; ++c) {
      const std::size_t at = (i * static_cast<std::size_t>(comps) + static_cast<std::size_t>(c)) * static_cast<std::size_t>(bytes_per);
      v[c] = bytes_per == 2 ? img.image[at + 1] : img.image[at];  // 16-bit: little-endian, keep the high byte
    }
    if (comps == 1 || comps == 2) {  // grey (+ alpha)
      v[3] = comps == 2 ? v[1] : 255;
      v[1] = v[2] = v[0];
    }
    std::memcpy(&out.rgba8[i * 4], v, 4);
  }
  return out;
}

}  // namespace vsgl::gltf
