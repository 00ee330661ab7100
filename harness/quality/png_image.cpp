#include "harness/quality/png_image.hpp"

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <stdexcept>
#include <string>

#include "harness/core/atomic_file.hpp"
#include "harness/core/error.hpp"
#include "harness/math/vsgl_math.hpp"

// The stb implementations come compiled from Debian's libstb (linked through PkgConfig::STB), so
// no translation unit here defines STB_IMAGE_*_IMPLEMENTATION.

namespace vsgl {

float auto_exposure(const RadianceImage& image, float percentile, float target) {
  if (!(percentile > 0.0f && percentile <= 1.0f))
    throw std::invalid_argument("auto_exposure: percentile must lie in (0, 1]");
  std::vector<float> lum;
  lum.reserve(image.pixels.size());
  for (const glm::vec4& p : image.pixels)
    if (p.a > 0.0f) lum.push_back(std::max(luminance(glm::vec3(p)), 0.0f));
  if (lum.empty()) return 1.0f;
  // The k-th smallest, k = ceil(percentile * n) - 1 (the nearest-rank percentile); the slack
  // absorbs the float rounding of `percentile` (0.99f * 100 is 99.000001, rank 99 is meant).
  const auto n = static_cast<double>(lum.size());
  const auto rank = static_cast<std::size_t>(std::ceil(static_cast<double>(percentile) * n * (1.0 - 1e-6)));
  const std::size_t k = std::min(lum.size() - 1, rank > 0 ? rank - 1 : 0);
  std::nth_element(lum.begin(), lum.begin() + static_cast<std::ptrdiff_t>(k), lum.end());
  const float level = lum[k];
  if (!(level > 0.0f) || !std::isfinite(level)) {
    // Fewer than 1% of the pixels are lit: expose for the brightest one instead.
    const float brightest = *std::max_element(lum.begin(), lum.end());
    return brightest > 0.0f && std::isfinite(brightest) ? target / brightest : 1.0f;
  }
  return target / level;
}

uint8_t tone_map_value(float linear, float exposure) {
  const float v = std::clamp(exposure * linear, 0.0f, 1.0f);
  const float encoded = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
  return static_cast<uint8_t>(std::lround(std::clamp(encoded, 0.0f, 1.0f) * 255.0f));
}

Rgb8Image tone_map(const RadianceImage& image, float exposure) {
  if (image.pixels.size() != std::size_t{image.width} * image.height)
    throw std::invalid_argument("tone_map: the image holds " + std::to_string(image.pixels.size()) +
                                " pixels, not " + std::to_string(image.width) + " x " + std::to_string(image.height));
  if (!(exposure >= 0.0f) || !std::isfinite(exposure))
    throw InputError("tone mapping: the exposure must be a finite non-negative number");
  Rgb8Image out;
  out.width = image.width;
  out.height = image.height;
  out.rgb.resize(image.pixels.size() * 3);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    const glm::vec4& p = image.pixels[i];
    for (int c = 0; c < 3; ++c) {
      if (!std::isfinite(p[c]))
        throw std::runtime_error("tone mapping: radiance pixel (" + std::to_string(i % image.width) + ", " +
                                 std::to_string(i / image.width) + ") channel " + std::to_string(c) +
                                 " is not finite (" + std::to_string(p[c]) + ")");
      out.rgb[3 * i + static_cast<std::size_t>(c)] = tone_map_value(p[c], exposure);
    }
  }
  return out;
}

namespace {

void append_bytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<char>*>(context);
  const auto* bytes = static_cast<const char*>(data);
  out->insert(out->end(), bytes, bytes + size);
}

}  // namespace

std::vector<char> encode_png(const Rgb8Image& image) {
  if (image.rgb.size() != std::size_t{image.width} * image.height * 3 || image.width == 0 || image.height == 0)
    throw std::invalid_argument("encode_png: empty image or wrong pixel count");
  if (image.width > INT_MAX / 3 || image.height > INT_MAX)
    throw std::invalid_argument("encode_png: image too large for the PNG encoder");
  std::vector<char> bytes;
  const int w = static_cast<int>(image.width);
  const int h = static_cast<int>(image.height);
  if (stbi_write_png_to_func(&append_bytes, &bytes, w, h, 3, image.rgb.data(), 3 * w) == 0)
    throw std::runtime_error("encode_png: the PNG encoder failed");
  return bytes;
}

Rgb8Image decode_png(std::span<const char> bytes, const std::string& what) {
  if (bytes.size() > static_cast<std::size_t>(INT_MAX)) throw InputError(what + ": too large to decode");
  int w = 0, h = 0, channels = 0;
  stbi_uc* data = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()),
                                        static_cast<int>(bytes.size()), &w, &h, &channels, 3);
  if (data == nullptr) throw InputError(what + ": not a readable image (" + stbi_failure_reason() + ")");
  Rgb8Image out;
  out.width = static_cast<uint32_t>(w);
  out.height = static_cast<uint32_t>(h);
  out.rgb.assign(data, data + std::size_t{out.width} * out.height * 3);
  stbi_image_free(data);
  return out;
}

void write_png_atomic(const std::filesystem::path& path, const Rgb8Image& image) {
  const std::vector<char> bytes = encode_png(image);
  write_file_atomic(path, bytes);
}

}  // namespace vsgl
