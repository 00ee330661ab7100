#include "harness/scene/scene_textures.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "harness/core/error.hpp"
#include "harness/core/portable_float.hpp"

namespace vsgl {
namespace {

glm::vec3 any_orthogonal(glm::vec3 n) {
  const glm::vec3 axis = std::abs(n.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
  return glm::normalize(axis - glm::dot(axis, n) * n);
}

// The four parents of texel (x, y) of the next level, clamped to the level's edge.
template <class Read>
std::array<float, 4> box4(uint32_t w, uint32_t h, uint32_t x, uint32_t y, Read read) {
  const uint32_t x0 = std::min(2 * x, w - 1), x1 = std::min(2 * x + 1, w - 1);
  const uint32_t y0 = std::min(2 * y, h - 1), y1 = std::min(2 * y + 1, h - 1);
  std::array<float, 4> sum{};
  for (uint32_t yy : {y0, y1})
    for (uint32_t xx : {x0, x1})
      for (int c = 0; c < 4; ++c) sum[static_cast<std::size_t>(c)] += read(xx, yy, c);
  for (float& s : sum) s *= 0.25f;
  return sum;
}

}  // namespace

float srgb_to_linear(float e) { return e <= 0.04045f ? e / 12.92f : portable::pow((e + 0.055f) / 1.055f, 2.4f); }

float linear_to_srgb(float l) { return l <= 0.0031308f ? 12.92f * l : 1.055f * portable::pow(l, 1.0f / 2.4f) - 0.055f; }

void compute_tangents(std::vector<SceneVertex>& vertices, const std::vector<uint32_t>& indices) {
  std::vector<glm::vec3> along_u(vertices.size(), glm::vec3(0.0f)), along_v(vertices.size(), glm::vec3(0.0f));
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    const SceneVertex& a = vertices[indices[t]];
    const SceneVertex& b = vertices[indices[t + 1]];
    const SceneVertex& c = vertices[indices[t + 2]];
    const glm::vec3 e1 = b.position - a.position, e2 = c.position - a.position;
    const glm::vec2 d1 = b.uv - a.uv, d2 = c.uv - a.uv;
    const float det = d1.x * d2.y - d2.x * d1.y;
    if (!(std::abs(det) > 1e-20f)) continue;  // degenerate mapping: no direction to add
    // Solve e1 = d1.x T + d1.y B, e2 = d2.x T + d2.y B. Unnormalized T and B scale with the
    // triangle's area over its uv area, i.e. an area weighting in uv space.
    const float sign = det > 0.0f ? 1.0f : -1.0f;  // keep |det| as the weight, not 1/det
    const glm::vec3 tu = (e1 * d2.y - e2 * d1.y) * sign;
    const glm::vec3 tv = (e2 * d1.x - e1 * d2.x) * sign;
    for (std::size_t k = 0; k < 3; ++k) {
      along_u[indices[t + k]] += tu;
      along_v[indices[t + k]] += tv;
    }
  }
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    SceneVertex& v = vertices[i];
    const glm::vec3 n = v.normal;
    glm::vec3 t = along_u[i] - glm::dot(along_u[i], n) * n;
    const float len = glm::length(t);
    if (!(len > 1e-12f) || !std::isfinite(len)) {
      v.tangent = glm::vec4(any_orthogonal(n), 1.0f);
      continue;
    }
    t /= len;
    const float w = glm::dot(glm::cross(n, t), along_v[i]) < 0.0f ? -1.0f : 1.0f;
    v.tangent = glm::vec4(t, w);
  }
}

std::vector<MipLevel> build_mip_chain(const TextureImage& tex) {
  const std::size_t n = std::size_t{tex.width} * tex.height * 4;
  const bool bytes = !tex.rgba8.empty();
  if (tex.width == 0 || tex.height == 0 || (bytes ? tex.rgba8.size() : tex.rgba32f.size()) != n ||
      (bytes && !tex.rgba32f.empty())) {
    throw InputError("texture '" + tex.name + "': " + std::to_string(tex.width) + "x" + std::to_string(tex.height) +
                     " needs exactly one array of " + std::to_string(n) + " RGBA values");
  }
  std::vector<MipLevel> levels;
  levels.push_back(MipLevel{tex.width, tex.height, tex.rgba8, tex.rgba32f});
  // sRGB bytes are decoded once; each level is filtered from the linear level above (not from
  // the re-encoded bytes) so rounding does not accumulate down the chain.
  std::vector<float> linear;
  if (bytes) {
    std::array<float, 256> decode{};
    for (int i = 0; i < 256; ++i) {
      const float v = static_cast<float>(i) / 255.0f;
      decode[static_cast<std::size_t>(i)] = tex.srgb ? srgb_to_linear(v) : v;
    }
    linear.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      linear[i] = (i % 4 == 3) ? tex.rgba8[i] / 255.0f : decode[tex.rgba8[i]];
  } else {
    linear = tex.rgba32f;
  }
  uint32_t w = tex.width, h = tex.height;
  while (w > 1 || h > 1) {
    const uint32_t nw = std::max(1u, w / 2), nh = std::max(1u, h / 2);
    std::vector<float> next(std::size_t{nw} * nh * 4);
    const auto read = [&](uint32_t x, uint32_t y, int c) {
      return linear[(std::size_t{y} * w + x) * 4 + static_cast<std::size_t>(c)];
    };
    for (uint32_t y = 0; y < nh; ++y)
      for (uint32_t x = 0; x < nw; ++x) {
        const auto avg = box4(w, h, x, y, read);
        for (int c = 0; c < 4; ++c) next[(std::size_t{y} * nw + x) * 4 + static_cast<std::size_t>(c)] = avg[static_cast<std::size_t>(c)];
      }
    MipLevel level{nw, nh, {}, {}};
    if (bytes) {
      level.rgba8.resize(next.size());
      for (std::size_t i = 0; i < next.size(); ++i) {
        const float v = (i % 4 == 3 || !tex.srgb) ? next[i] : linear_to_srgb(next[i]);
        level.rgba8[i] = static_cast<uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
      }
    } else {
      level.rgba32f = next;
    }
    levels.push_back(std::move(level));
    linear = std::move(next);
    w = nw;
    h = nh;
  }
  return levels;
}

}  // namespace vsgl
