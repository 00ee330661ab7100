#pragma once
// Reading and writing planar float images as OpenEXR files (DESIGN.md §3 "Storage"), through the
// Debian OpenEXR library. Scanline images, ZIP compression (lossless: a round trip is bit-exact).
// Kept apart from capture.cpp so tests can write deliberately malformed files.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vsgl {

// Sample types an EXR channel can have. Captures use kFloat only; the others exist so that a
// file with a wrong type can be detected (and produced by tests).
enum class ExrSampleType { kUint, kHalf, kFloat };
const char* exr_sample_type_name(ExrSampleType type);  // "uint" | "half" | "float"

// One channel to write: values are row-major, row 0 at the top, width * height of them. They are
// converted to `type` in the file.
struct ExrChannelToWrite {
  std::string name;
  std::span<const float> values;
  ExrSampleType type = ExrSampleType::kFloat;
};

// Encodes the channels as a complete EXR file in memory. Throws InputError (naming `name_for_errors`)
// when a channel has the wrong number of values, or when OpenEXR refuses.
std::vector<char> encode_exr(uint32_t width, uint32_t height,
                             std::span<const ExrChannelToWrite> channels,
                             const std::string& name_for_errors);

// Encodes and writes atomically (see atomic_file.hpp). Throws InputError naming `path`.
void write_exr(const std::filesystem::path& path, uint32_t width, uint32_t height,
               std::span<const ExrChannelToWrite> channels);

struct ExrChannelRead {
  std::string name;
  ExrSampleType type = ExrSampleType::kFloat;  // as stored in the file
  std::vector<float> values;                   // converted to float32, width * height
};

struct ExrImage {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<ExrChannelRead> channels;  // in the file's order (OpenEXR sorts them by name)

  const ExrChannelRead* find(std::string_view name) const;
};

// Called with the image size from the header, before any pixel memory is allocated, so that a
// caller can reject a size (throwing InputError) before a corrupt header asks for gigabytes.
using ExrSizeCheck = std::function<void(uint32_t width, uint32_t height)>;

// Reads the header and every pixel of every channel. Any failure of the library (not an EXR,
// corrupt, truncated) becomes InputError "PATH: cannot read EXR file (corrupt or truncated): ...";
// all pixels are read here, so a damaged file fails now and not later.
ExrImage read_exr(const std::filesystem::path& path, const ExrSizeCheck& check_size = {});

}  // namespace vsgl
