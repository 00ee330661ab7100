// The patterns are written as a scene artist would paint them: feature sizes in metres, tints
// and roughness chosen to look like the material, nothing fitted to any measured result.
#include "harness/scene/surface_detail.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "harness/scene/scene_textures.hpp"

namespace vsgl {
namespace {

// A 32-bit integer mix (Wellons' lowbias32): well spread, the same on every platform.
uint32_t mix32(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

uint32_t hash3(uint32_t a, uint32_t b, uint32_t seed) { return mix32(a ^ mix32(b ^ mix32(seed))); }

float unit_float(uint32_t h) { return static_cast<float>(h >> 8) * (1.0f / 16777216.0f); }  // [0, 1)

float smooth01(float t) {
  t = std::clamp(t, 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

float smoothstep(float e0, float e1, float x) { return smooth01((x - e0) / (e1 - e0)); }

uint32_t wrap(int64_t i, uint32_t period) {
  const int64_t p = period;
  return static_cast<uint32_t>(((i % p) + p) % p);
}

// Value noise in [0,1] on a lattice of `cells` per metre, periodic over 1 m; (u, v) in metres.
float value_noise(float u, float v, uint32_t cells, uint32_t seed) {
  const float x = u * static_cast<float>(cells), y = v * static_cast<float>(cells);
  const float fx = std::floor(x), fy = std::floor(y);
  const auto ix = static_cast<int64_t>(fx), iy = static_cast<int64_t>(fy);
  const float tx = smooth01(x - fx), ty = smooth01(y - fy);
  auto at = [&](int64_t i, int64_t j) { return unit_float(hash3(wrap(i, cells), wrap(j, cells), seed)); };
  const float bottom = at(ix, iy) + (at(ix + 1, iy) - at(ix, iy)) * tx;
  const float top = at(ix, iy + 1) + (at(ix + 1, iy + 1) - at(ix, iy + 1)) * tx;
  return bottom + (top - bottom) * ty;
}

// Fractal sum of `octaves` value noises from `cells` per metre up (each twice as fine, half as
// strong), normalised to [0,1].
float fbm(float u, float v, uint32_t cells, int octaves, uint32_t seed) {
  float sum = 0.0f, amplitude = 1.0f, norm = 0.0f;
  for (int o = 0; o < octaves; ++o) {
    sum += amplitude * value_noise(u, v, cells << o, seed + static_cast<uint32_t>(o) * 7919u);
    norm += amplitude;
    amplitude *= 0.5f;
  }
  return sum / norm;
}

// Where (u, v) falls in a wall of units (tiles, blocks, bricks) unit_w x unit_h metres, each
// course shifted by half a unit in running bond: the unit's id (periodic over 1 m) and the
// distance in metres to the nearest joint's centre line.
struct MasonryCell {
  uint32_t id;
  uint32_t column, course;
  float joint_distance;
};

MasonryCell masonry(float u, float v, float unit_w, float unit_h, bool running_bond) {
  const auto columns = static_cast<uint32_t>(std::lround(1.0f / unit_w));
  const auto courses = static_cast<uint32_t>(std::lround(1.0f / unit_h));
  const float course = std::floor(v / unit_h);
  const bool shifted = running_bond && (static_cast<int64_t>(course) & 1) != 0;
  const float us = u + (shifted ? 0.5f * unit_w : 0.0f);
  const float column = std::floor(us / unit_w);
  const float lu = us - column * unit_w, lv = v - course * unit_h;
  MasonryCell cell;
  cell.column = wrap(static_cast<int64_t>(column), columns);
  cell.course = wrap(static_cast<int64_t>(course), courses);
  cell.id = cell.course * columns + cell.column;
  cell.joint_distance = std::min(std::min(lu, unit_w - lu), std::min(lv, unit_h - lv));
  return cell;
}

// 1 inside a joint of half-width `half_joint`, falling smoothly to 0 over `bevel` metres.
float joint_weight(float distance, float half_joint, float bevel) {
  if (distance <= half_joint) return 1.0f;
  return 1.0f - smooth01((distance - half_joint) / bevel);
}

struct DetailSample {
  glm::vec3 albedo{1.0f};
  float alpha = 0.5f;
  float height = 0.0f;
};

// Evaluates the pattern at 2x2 points in every texel and averages them (the texel's footprint,
// so that sub-texel grout and seams show as partial coverage rather than aliasing).
template <typename Pattern>
DetailPlanes rasterize(std::string name, bool relief, Pattern pattern) {
  DetailPlanes planes;
  planes.name = std::move(name);
  const uint32_t n = planes.size;
  const std::size_t texels = std::size_t{n} * n;
  planes.albedo.resize(texels);
  planes.alpha.resize(texels);
  if (relief) planes.height.resize(texels);
  const float pitch = 1.0f / static_cast<float>(n);
  for (uint32_t y = 0; y < n; ++y) {
    for (uint32_t x = 0; x < n; ++x) {
      DetailSample sum{glm::vec3(0.0f), 0.0f, 0.0f};
      for (uint32_t sy = 0; sy < 2; ++sy) {
        for (uint32_t sx = 0; sx < 2; ++sx) {
          const float u = (static_cast<float>(x) + 0.25f + 0.5f * static_cast<float>(sx)) * pitch;
          const float v = (static_cast<float>(y) + 0.25f + 0.5f * static_cast<float>(sy)) * pitch;
          const DetailSample s = pattern(u, v);
          sum.albedo += s.albedo;
          sum.alpha += s.alpha;
          sum.height += s.height;
        }
      }
      const std::size_t i = std::size_t{y} * n + x;
      planes.albedo[i] = glm::clamp(0.25f * sum.albedo, glm::vec3(0.0f), glm::vec3(1.0f));
      planes.alpha[i] = std::clamp(0.25f * sum.alpha, 1e-3f, 1.0f);
      if (relief) planes.height[i] = 0.25f * sum.height;
    }
  }
  return planes;
}

// A per-unit tint in [lo, 1] with a small shift between the channels (stone and fired clay vary
// in hue as well as in brightness).
glm::vec3 unit_tint(uint32_t id, uint32_t seed, float lo) {
  const float t = lo + (1.0f - lo) * unit_float(hash3(id, 0u, seed));
  const float warm = 0.04f * (unit_float(hash3(id, 1u, seed)) - 0.5f);
  return glm::clamp(glm::vec3(t * (1.0f + warm), t, t * (1.0f - warm)), glm::vec3(0.0f), glm::vec3(1.0f));
}

uint8_t to_byte(float unit_value) {
  return static_cast<uint8_t>(std::lround(std::clamp(unit_value, 0.0f, 1.0f) * 255.0f));
}

TextureImage rgba8_texture(const std::string& name, uint32_t size, bool srgb) {
  TextureImage t;
  t.name = name;
  t.width = t.height = size;
  t.srgb = srgb;
  t.rgba8.reserve(std::size_t{size} * size * 4);
  return t;  // kRepeat both ways: the patterns are periodic
}

}  // namespace

DetailPlanes stone_floor_tiles() {
  return rasterize("stone_floor_tiles", true, [](float u, float v) {
    const MasonryCell tile = masonry(u, v, 0.5f, 0.5f, false);
    const float grout = joint_weight(tile.joint_distance, 0.004f, 0.002f);
    const float clouds = fbm(u, v, 8, 4, 11u);
    const float vein = 1.0f - 0.3f * (1.0f - smoothstep(0.0f, 0.025f, std::abs(fbm(u, v, 4, 4, 12u + tile.id) - 0.5f)));
    const glm::vec3 stone = unit_tint(tile.id, 13u, 0.8f) * (0.85f + 0.15f * clouds) * vein;
    const float polish = 0.08f + 0.12f * fbm(u, v, 4, 3, 14u);  // worn where people walk
    DetailSample s;
    s.albedo = stone + (glm::vec3(0.35f) - stone) * grout;
    s.alpha = polish + (0.85f - polish) * grout;
    s.height = -0.002f * grout;
    return s;
  });
}

DetailPlanes ashlar_wall() {
  return rasterize("ashlar_wall", true, [](float u, float v) {
    const MasonryCell block = masonry(u, v, 0.5f, 0.25f, true);
    const float joint = joint_weight(block.joint_distance, 0.005f, 0.008f);
    const glm::vec3 stone = unit_tint(block.id, 21u, 0.82f) * (0.9f + 0.1f * fbm(u, v, 16, 3, 22u));
    const float tooled = 0.5f + 0.2f * fbm(u, v, 8, 2, 23u);
    DetailSample s;
    s.albedo = stone + (glm::vec3(0.75f) - stone) * joint;
    s.alpha = tooled + (0.9f - tooled) * joint;
    s.height = -0.006f * joint + 0.0008f * (fbm(u, v, 32, 3, 24u + block.id) - 0.5f);  // chisel marks
    return s;
  });
}

DetailPlanes speckled_stone() {
  return rasterize("speckled_stone", true, [](float u, float v) {
    const auto gx = static_cast<int64_t>(std::floor(u * 128.0f)), gy = static_cast<int64_t>(std::floor(v * 128.0f));
    const bool grain = unit_float(hash3(wrap(gx, 128), wrap(gy, 128), 31u)) > 0.96f;
    DetailSample s;
    s.albedo = glm::vec3((0.85f + 0.15f * fbm(u, v, 8, 4, 32u)) * (grain ? 0.55f : 1.0f));
    s.alpha = 0.25f + 0.15f * fbm(u, v, 4, 3, 33u);
    s.height = 0.0003f * (fbm(u, v, 64, 2, 34u) - 0.5f);
    return s;
  });
}

DetailPlanes carpet_tiles() {
  return rasterize("carpet_tiles", true, [](float u, float v) {
    const MasonryCell tile = masonry(u, v, 0.5f, 0.5f, false);
    const float seam = joint_weight(tile.joint_distance, 0.001f, 0.002f);
    const float pile = ((tile.column + tile.course) & 1u) != 0 ? 0.9f : 1.0f;  // laid quarter-turned
    const float fibre = fbm(u, v, 64, 2, 41u);
    DetailSample s;
    s.albedo = glm::vec3(pile * (0.88f + 0.12f * fibre) * (1.0f - 0.25f * seam));
    s.alpha = 0.9f;
    s.height = 0.0004f * (fbm(u, v, 128, 1, 42u) - 0.5f) - 0.0015f * seam;
    return s;
  });
}

DetailPlanes painted_brick() {
  return rasterize("painted_brick", true, [](float u, float v) {
    const MasonryCell brick = masonry(u, v, 0.25f, 0.0625f, true);
    const float mortar = joint_weight(brick.joint_distance, 0.004f, 0.003f);
    const glm::vec3 paint = unit_tint(brick.id, 51u, 0.92f);
    const float sheen = 0.55f + 0.1f * fbm(u, v, 16, 2, 52u);
    DetailSample s;
    s.albedo = paint + (glm::vec3(0.85f) - paint) * mortar;
    s.alpha = sheen + (0.8f - sheen) * mortar;
    s.height = -0.004f * mortar + 0.0006f * (fbm(u, v, 64, 2, 53u + brick.id) - 0.5f);
    return s;
  });
}

DetailPlanes wall_panels() {
  return rasterize("wall_panels", true, [](float u, float v) {
    constexpr float kBoard = 0.25f, kHalfGroove = 0.003f;
    const float lu = u - kBoard * std::floor(u / kBoard);
    const float from_groove = std::min(lu, kBoard - lu);
    const float groove = std::max(0.0f, 1.0f - from_groove / kHalfGroove);  // a V: 0 at its rim
    DetailSample s;
    s.albedo = glm::vec3((0.97f + 0.03f * fbm(u, v, 8, 2, 61u)) * (1.0f - 0.15f * groove));
    s.alpha = 0.35f + 0.1f * fbm(u, v, 4, 2, 62u);
    s.height = -0.003f * groove + 0.0002f * (fbm(u, v, 64, 2, 63u) - 0.5f);  // orange peel
    return s;
  });
}

DetailPlanes wood_grain(float lacquer_alpha) {
  // Named by the finish (two finishes of one scene are two texture sets).
  const std::string name = "wood_grain_alpha" + std::to_string(std::lround(lacquer_alpha * 100.0f)) + "pct";
  return rasterize(name, true, [lacquer_alpha](float u, float v) {
    constexpr float kPlank = 0.125f;
    const float plank_f = std::floor(v / kPlank);
    const uint32_t plank = wrap(static_cast<int64_t>(plank_f), 8);
    const float lv = v - plank_f * kPlank;
    const float seam = joint_weight(std::min(lv, kPlank - lv), 0.0005f, 0.0005f);
    // Growth rings about 12 mm apart, across the plank, wandering with the grain.
    const float rings = v * 80.0f + 4.0f * fbm(u, v, 4, 3, 71u + plank) + 8.0f * unit_float(hash3(plank, 0u, 72u));
    const float late = smoothstep(0.6f, 0.9f, rings - std::floor(rings));  // dense, dark late wood
    const float tint = 0.8f + 0.2f * unit_float(hash3(plank, 1u, 73u));
    const float figure = 0.95f + 0.05f * fbm(u, v, 32, 2, 74u);
    DetailSample s;
    s.albedo = tint * figure * glm::vec3(1.0f - 0.3f * late, 1.0f - 0.4f * late, 1.0f - 0.5f * late) * (1.0f - 0.4f * seam);
    s.alpha = lacquer_alpha * (1.0f + 0.6f * late) * (0.85f + 0.3f * fbm(u, v, 2, 2, 75u));  // open pores, wear
    s.height = -0.0005f * seam;
    return s;
  });
}

DetailPlanes smudged_gloss() {
  return rasterize("smudged_gloss", false, [](float u, float v) {
    DetailSample s;
    s.albedo = glm::vec3(1.0f);
    s.alpha = 0.06f + 0.24f * smoothstep(0.55f, 0.8f, fbm(u, v, 3, 4, 81u));
    return s;
  });
}

glm::vec3 height_normal(const std::vector<float>& height, uint32_t size, uint32_t x, uint32_t y) {
  auto h = [&](uint32_t i, uint32_t j) { return height[std::size_t{j % size} * size + i % size]; };
  const float two_pitch = 2.0f / static_cast<float>(size);
  const float dhdu = (h(x + 1, y) - h(x + size - 1, y)) / two_pitch;
  const float dhdv = (h(x, y + 1) - h(x, y + size - 1)) / two_pitch;
  return glm::normalize(glm::vec3(-dhdu, -dhdv, 1.0f));
}

DetailMaterial add_surface_detail(Scene& scene, const DetailPlanes& detail) {
  const uint32_t n = detail.size;
  const std::size_t texels = std::size_t{n} * n;
  if (n == 0 || detail.albedo.size() != texels || detail.alpha.size() != texels ||
      (!detail.height.empty() && detail.height.size() != texels)) {
    throw std::logic_error("add_surface_detail: planes of '" + detail.name + "' do not match its size");
  }
  DetailMaterial out;
  out.max_alpha = *std::max_element(detail.alpha.begin(), detail.alpha.end());

  TextureImage albedo = rgba8_texture(detail.name + ".albedo", n, true);
  TextureImage roughness = rgba8_texture(detail.name + ".roughness", n, false);
  for (std::size_t i = 0; i < texels; ++i) {
    const glm::vec3 a = detail.albedo[i];
    albedo.rgba8.insert(albedo.rgba8.end(), {to_byte(linear_to_srgb(a.r)), to_byte(linear_to_srgb(a.g)),
                                             to_byte(linear_to_srgb(a.b)), 255});
    // G = sqrt(alpha / max alpha): kVertexAlbedo squares it and scales by the vertex roughness.
    roughness.rgba8.insert(roughness.rgba8.end(), {255, to_byte(std::sqrt(detail.alpha[i] / out.max_alpha)), 0, 255});
  }

  Material material;
  material.name = detail.name;
  material.model = MaterialModel::kVertexAlbedo;
  material.base_color_texture = static_cast<int32_t>(scene.textures.size());
  scene.textures.push_back(std::move(albedo));
  material.metallic_roughness_texture = static_cast<int32_t>(scene.textures.size());
  scene.textures.push_back(std::move(roughness));
  if (!detail.height.empty()) {
    TextureImage normal = rgba8_texture(detail.name + ".normal", n, false);
    for (uint32_t y = 0; y < n; ++y) {
      for (uint32_t x = 0; x < n; ++x) {
        const glm::vec3 e = 0.5f * height_normal(detail.height, n, x, y) + 0.5f;
        normal.rgba8.insert(normal.rgba8.end(), {to_byte(e.x), to_byte(e.y), to_byte(e.z), 255});
      }
    }
    material.normal_texture = static_cast<int32_t>(scene.textures.size());
    scene.textures.push_back(std::move(normal));
  }
  out.material = static_cast<uint32_t>(scene.materials.size());
  scene.materials.push_back(std::move(material));
  return out;
}

SurfaceMaterial detailed_surface(const DetailMaterial& detail, glm::vec3 diffuse, glm::vec3 specular) {
  return SurfaceMaterial{diffuse, specular, detail.max_alpha, detail.material};
}

}  // namespace vsgl
