#pragma once
// Turning a linear radiance image (harness/quality/shading_pass.hpp) into a picture: exposure, clamp to
// [0, 1], the sRGB transfer curve, 8 bits per channel, PNG. Deterministic: the same radiance and
// exposure give the same bytes. PNG coding is Debian's stb (libstb), written atomically (DESIGN.md §10).
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "harness/quality/radiance_image.hpp"

namespace vsgl {

// 8-bit sRGB, 3 channels, row-major, row 0 = top.
struct Rgb8Image {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<uint8_t> rgb;  // width * height * 3
};

// Auto exposure: the scale that maps the `percentile` (in (0, 1]) luminance of the pixels with a
// surface (alpha > 0) to `target`. 1 when no such pixel has a positive luminance (nothing to see).
float auto_exposure(const RadianceImage& image, float percentile = 0.99f, float target = 0.8f);

// One linear value to an 8-bit sRGB code: clamp(exposure * v, 0, 1), then the sRGB OETF
// (12.92 v below 0.0031308, else 1.055 v^(1/2.4) - 0.055), rounded. Monotonic non-decreasing in v.
uint8_t tone_map_value(float linear, float exposure);

// Tone-maps every pixel. Throws std::runtime_error naming the first non-finite pixel (a NaN or an
// infinity in the radiance is a bug of the pass, never shown as a colour).
Rgb8Image tone_map(const RadianceImage& image, float exposure);

// PNG bytes of an image (stb's encoder; deterministic).
std::vector<char> encode_png(const Rgb8Image& image);
// Decodes PNG bytes to 3-channel 8 bits (tests, and reading reference pictures). Throws InputError
// naming `what` when the bytes are not a PNG stb can read.
Rgb8Image decode_png(std::span<const char> bytes, const std::string& what = "PNG data");

// encode_png + write_file_atomic.
void write_png_atomic(const std::filesystem::path& path, const Rgb8Image& image);

}  // namespace vsgl
