#include "harness/quality/quality_pictures.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "harness/core/error.hpp"
#include "harness/core/statistics.hpp"

namespace vsgl {
namespace {

struct Canvas {
  Rgb8Image image;
  void put(int64_t x, int64_t y, glm::u8vec3 c) {
    if (x < 0 || y < 0 || x >= image.width || y >= image.height) return;
    const std::size_t i = (static_cast<std::size_t>(y) * image.width + static_cast<std::size_t>(x)) * 3;
    image.rgb[i] = c.r;
    image.rgb[i + 1] = c.g;
    image.rgb[i + 2] = c.b;
  }
};

uint8_t to_u8(double v) { return static_cast<uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); }

}  // namespace

Rgb8Image coverage_picture(const MipPyramid& pdf_pyramid, const std::vector<VsglRecord>& kernels, uint32_t max_side) {
  const VirtualSquare& sq = pdf_pyramid.square;
  const uint32_t longest = std::max(sq.width, sq.height);
  const double scale = max_side == 0 || longest <= max_side ? 1.0 : static_cast<double>(max_side) / longest;
  Canvas c;
  c.image.width = std::max(1u, static_cast<uint32_t>(std::lround(sq.width * scale)));
  c.image.height = std::max(1u, static_cast<uint32_t>(std::lround(sq.height * scale)));
  c.image.rgb.assign(std::size_t{c.image.width} * c.image.height * 3, 0);

  std::vector<double> positive;
  for (uint32_t y = 0; y < sq.height; ++y)
    for (uint32_t x = 0; x < sq.width; ++x) {
      const double q = static_cast<double>(pdf_pyramid.at(0, static_cast<int32_t>(x), static_cast<int32_t>(y)).w);
      if (q > 0.0) positive.push_back(q);
    }
  std::sort(positive.begin(), positive.end());
  const double white = positive.empty() ? 1.0 : quantile_sorted(positive, 0.99);
  for (uint32_t py = 0; py < c.image.height; ++py)
    for (uint32_t px = 0; px < c.image.width; ++px) {
      // Nearest texel at the centre of the output pixel (a picture, not a measurement).
      const auto tx = static_cast<int32_t>(std::min<double>((px + 0.5) / scale, sq.width - 1));
      const auto ty = static_cast<int32_t>(std::min<double>((py + 0.5) / scale, sq.height - 1));
      const double q = static_cast<double>(pdf_pyramid.at(0, tx, ty).w);
      const uint8_t g = to_u8(std::sqrt(std::max(q, 0.0) / white) * 0.85);
      c.put(px, py, {g, g, g});
    }
  const double S = static_cast<double>(sq.size);
  const glm::u8vec3 orange(255, 150, 0), red(255, 20, 20);
  for (const VsglRecord& k : kernels) {
    const double half = 0.5 * std::exp2(static_cast<double>(std::max(k.level(), 0.0f)));
    const double cx = static_cast<double>(k.center().x) * S, cy = static_cast<double>(k.center().y) * S;
    const auto x0 = static_cast<int64_t>(std::floor((cx - half) * scale));
    const auto x1 = static_cast<int64_t>(std::floor((cx + half) * scale));
    const auto y0 = static_cast<int64_t>(std::floor((cy - half) * scale));
    const auto y1 = static_cast<int64_t>(std::floor((cy + half) * scale));
    const int64_t W = c.image.width, H = c.image.height;
    for (int64_t x = std::max<int64_t>(x0, 0); x <= std::min(x1, W - 1); ++x) {
      c.put(x, y0, orange);
      c.put(x, y1, orange);
    }
    for (int64_t y = std::max<int64_t>(y0, 0); y <= std::min(y1, H - 1); ++y) {
      c.put(x0, y, orange);
      c.put(x1, y, orange);
    }
  }
  for (const VsglRecord& k : kernels) {
    const auto x = static_cast<int64_t>(std::floor(static_cast<double>(k.center().x) * S * scale));
    const auto y = static_cast<int64_t>(std::floor(static_cast<double>(k.center().y) * S * scale));
    c.put(x, y, red);
    c.put(x + 1, y, red);
    c.put(x, y + 1, red);
    c.put(x + 1, y + 1, red);
  }
  return c.image;
}

RadianceImage downscale(const RadianceImage& image, uint32_t factor) {
  if (factor == 0) throw InputError("downscale: the factor must be at least 1");
  RadianceImage out;
  out.width = (image.width + factor - 1) / factor;
  out.height = (image.height + factor - 1) / factor;
  out.pixels.assign(std::size_t{out.width} * out.height, glm::vec4(0.0f));
  for (uint32_t y = 0; y < out.height; ++y)
    for (uint32_t x = 0; x < out.width; ++x) {
      glm::vec4 sum(0.0f);
      uint32_t n = 0;
      for (uint32_t j = y * factor; j < std::min((y + 1) * factor, image.height); ++j)
        for (uint32_t i = x * factor; i < std::min((x + 1) * factor, image.width); ++i) {
          const glm::vec4 p = image.pixels[std::size_t{j} * image.width + i];
          sum += glm::vec4(glm::vec3(p), p.a > 0.0f ? 1.0f : 0.0f);
          ++n;
        }
      // rgb averaged over the block; alpha 1 when any pixel of the block has a surface.
      out.pixels[std::size_t{y} * out.width + x] =
          glm::vec4(glm::vec3(sum) / static_cast<float>(n), sum.a > 0.0f ? 1.0f : 0.0f);
    }
  return out;
}

Rgb8Image error_map(const RadianceImage& image, const RadianceImage& reference, float full_scale) {
  if (image.width != reference.width || image.height != reference.height)
    throw InputError("error map: the image and the reference differ in size");
  double mean = 0;
  std::size_t n = 0;
  for (const glm::vec4& r : reference.pixels)
    if (r.a > 0.0f) {
      mean += static_cast<double>(luminance(glm::vec3(r)));
      ++n;
    }
  mean = n > 0 ? mean / static_cast<double>(n) : 1.0;
  const double denom = static_cast<double>(full_scale) * (mean > 0.0 ? mean : 1.0);
  Rgb8Image out;
  out.width = image.width;
  out.height = image.height;
  out.rgb.resize(std::size_t{out.width} * out.height * 3);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    uint8_t r = 64, g = 64, b = 64;
    if (reference.pixels[i].a > 0.0f) {
      const double e = std::abs(static_cast<double>(luminance(glm::vec3(image.pixels[i]))) -
                                static_cast<double>(luminance(glm::vec3(reference.pixels[i])))) / denom;
      // Black -> red -> yellow -> white over [0, 1].
      r = to_u8(e * 3.0);
      g = to_u8(e * 3.0 - 1.0);
      b = to_u8(e * 3.0 - 2.0);
    }
    out.rgb[i * 3] = r;
    out.rgb[i * 3 + 1] = g;
    out.rgb[i * 3 + 2] = b;
  }
  return out;
}

Rgb8Image tile_grid(const std::vector<Rgb8Image>& tiles, uint32_t columns) {
  if (tiles.empty() || columns == 0) throw InputError("tile grid: no tiles");
  const uint32_t tw = tiles.front().width, th = tiles.front().height;
  for (const auto& t : tiles)
    if (t.width != tw || t.height != th) throw InputError("tile grid: tiles of different sizes");
  constexpr uint32_t kBorder = 4;
  const uint32_t cols = std::min<uint32_t>(columns, static_cast<uint32_t>(tiles.size()));
  const uint32_t rows = static_cast<uint32_t>((tiles.size() + cols - 1) / cols);
  Rgb8Image out;
  out.width = cols * tw + (cols + 1) * kBorder;
  out.height = rows * th + (rows + 1) * kBorder;
  out.rgb.assign(std::size_t{out.width} * out.height * 3, 24);
  for (std::size_t k = 0; k < tiles.size(); ++k) {
    const uint32_t ox = kBorder + static_cast<uint32_t>(k % cols) * (tw + kBorder);
    const uint32_t oy = kBorder + static_cast<uint32_t>(k / cols) * (th + kBorder);
    for (uint32_t y = 0; y < th; ++y)
      std::copy_n(tiles[k].rgb.begin() + static_cast<std::ptrdiff_t>(std::size_t{y} * tw * 3), tw * 3,
                  out.rgb.begin() + static_cast<std::ptrdiff_t>((std::size_t{oy + y} * out.width + ox) * 3));
  }
  return out;
}

}  // namespace vsgl
