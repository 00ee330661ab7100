#include "harness/capture/exr_io.hpp"

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfCompression.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfThreading.h>

#include <algorithm>
#include <climits>
#include <cstring>
#include <exception>
#include <mutex>
#include <thread>
#include <set>

#include "harness/core/atomic_file.hpp"
#include "harness/core/error.hpp"
#include "harness/core/path_text.hpp"
#include "harness/core/printable_text.hpp"

namespace vsgl {
namespace {

Imf::PixelType to_imf(ExrSampleType type) {
  switch (type) {
    case ExrSampleType::kUint:
      return Imf::UINT;
    case ExrSampleType::kHalf:
      return Imf::HALF;
    case ExrSampleType::kFloat:
      return Imf::FLOAT;
  }
  return Imf::FLOAT;
}

ExrSampleType from_imf(Imf::PixelType type) {
  switch (type) {
    case Imf::UINT:
      return ExrSampleType::kUint;
    case Imf::HALF:
      return ExrSampleType::kHalf;
    default:
      return ExrSampleType::kFloat;
  }
}

// An OpenEXR output stream into a byte vector, so the encoded file can be written atomically.
// OpenEXR seeks back to fill in the line offset table, hence writes at a position.
class VectorOStream final : public Imf::OStream {
 public:
  explicit VectorOStream(const std::string& name) : Imf::OStream(name.c_str()) {}

  void write(const char c[], int n) override {
    const std::size_t count = static_cast<std::size_t>(n);
    if (position_ + count > bytes_.size()) bytes_.resize(position_ + count);
    std::memcpy(bytes_.data() + position_, c, count);
    position_ += count;
  }
  uint64_t tellp() override { return position_; }
  void seekp(uint64_t pos) override { position_ = static_cast<std::size_t>(pos); }

  std::vector<char> take() { return std::move(bytes_); }

 private:
  std::vector<char> bytes_;
  std::size_t position_ = 0;
};

// (De)compressing a full-size capture takes seconds on one core; OpenEXR spreads the scanline
// blocks over its global thread pool, which is empty unless someone sizes it.
void use_all_cores_for_exr() {
  static std::once_flag once;
  std::call_once(once, [] {
    if (Imf::globalThreadCount() == 0) {
      Imf::setGlobalThreadCount(static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
    }
  });
}

// OpenEXR's frame buffers take a mutable base pointer even for writing.
Imf::Slice float_slice(const float* values, uint32_t width) {
  return Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(const_cast<float*>(values)), sizeof(float),
                    sizeof(float) * std::size_t{width});
}

}  // namespace

const char* exr_sample_type_name(ExrSampleType type) {
  switch (type) {
    case ExrSampleType::kUint:
      return "uint";
    case ExrSampleType::kHalf:
      return "half";
    case ExrSampleType::kFloat:
      return "float";
  }
  return "float";
}

const ExrChannelRead* ExrImage::find(std::string_view name) const {
  for (const ExrChannelRead& channel : channels) {
    if (channel.name == name) return &channel;
  }
  return nullptr;
}

std::vector<char> encode_exr(uint32_t width, uint32_t height,
                             std::span<const ExrChannelToWrite> channels,
                             const std::string& name_for_errors) {
  if (width == 0 || height == 0 || width > INT_MAX || height > INT_MAX) {
    throw InputError(name_for_errors + ": cannot write EXR: image size " + std::to_string(width) +
                     "x" + std::to_string(height) + " is not a positive 32-bit size");
  }
  const std::size_t texels = std::size_t{width} * height;
  std::set<std::string> names;
  for (const ExrChannelToWrite& channel : channels) {
    if (channel.values.size() != texels) {
      throw InputError(name_for_errors + ": cannot write EXR: channel \"" + channel.name + "\" has " +
                       std::to_string(channel.values.size()) + " values, expected " +
                       std::to_string(texels) + " (" + std::to_string(width) + "x" +
                       std::to_string(height) + ")");
    }
    if (!names.insert(channel.name).second) {
      throw InputError(name_for_errors + ": cannot write EXR: channel \"" + channel.name +
                       "\" appears twice");
    }
  }
  use_all_cores_for_exr();
  try {
    Imf::Header header(static_cast<int>(width), static_cast<int>(height));
    header.compression() = Imf::ZIP_COMPRESSION;
    // OpenEXR converts types when reading but not when writing: other types get converted copies.
    std::vector<std::vector<Imath::half>> half_copies;
    std::vector<std::vector<unsigned int>> uint_copies;
    half_copies.reserve(channels.size());
    uint_copies.reserve(channels.size());
    Imf::FrameBuffer frame_buffer;
    for (const ExrChannelToWrite& channel : channels) {
      header.channels().insert(channel.name, Imf::Channel(to_imf(channel.type)));
      switch (channel.type) {
        case ExrSampleType::kFloat:
          frame_buffer.insert(channel.name, float_slice(channel.values.data(), width));
          break;
        case ExrSampleType::kHalf: {
          std::vector<Imath::half>& copy = half_copies.emplace_back(channel.values.begin(),
                                                             channel.values.end());
          frame_buffer.insert(channel.name,
                              Imf::Slice(Imf::HALF, reinterpret_cast<char*>(copy.data()),
                                         sizeof(Imath::half), sizeof(Imath::half) * std::size_t{width}));
          break;
        }
        case ExrSampleType::kUint: {
          std::vector<unsigned int>& copy = uint_copies.emplace_back();
          for (float value : channel.values) {
            copy.push_back(value > 0.0f ? static_cast<unsigned int>(value) : 0u);
          }
          frame_buffer.insert(channel.name,
                              Imf::Slice(Imf::UINT, reinterpret_cast<char*>(copy.data()),
                                         sizeof(unsigned int),
                                         sizeof(unsigned int) * std::size_t{width}));
          break;
        }
      }
    }
    VectorOStream stream(name_for_errors);
    {
      // The file is complete (offset table written) only once OutputFile is destroyed.
      Imf::OutputFile file(stream, header);
      file.setFrameBuffer(frame_buffer);
      file.writePixels(static_cast<int>(height));
    }
    return stream.take();
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(name_for_errors + ": cannot write EXR: " + e.what());
  }
}

void write_exr(const std::filesystem::path& path, uint32_t width, uint32_t height,
               std::span<const ExrChannelToWrite> channels) {
  const std::vector<char> bytes = encode_exr(width, height, channels, path_text(path));
  write_file_atomic(path, bytes);
}

// OpenEXR's checkOpenEXRFile (ImfCheckFile.h) is not called first: measured with
// tests/fuzz/measure_check_file (DESIGN.md §3, §12), it added ~70 % to reading a full-size view (2.8 s on
// top of 3.9 s, ASan build) and, over 394 fuzzed EXR inputs, flagged none that this reader
// accepted (this reader refused 2 that it passed).
ExrImage read_exr(const std::filesystem::path& path, const ExrSizeCheck& check_size) {
  const std::string where = path_text(path);
  ExrImage image;
  use_all_cores_for_exr();
  try {
    Imf::InputFile file(where.c_str());
    const Imf::Header& header = file.header();
    const Imath::Box2i window = header.dataWindow();
    if (window.min.x != 0 || window.min.y != 0) {
      throw InputError(where + ": the EXR data window starts at (" + std::to_string(window.min.x) +
                       ", " + std::to_string(window.min.y) + "), expected (0, 0)");
    }
    const long long w = static_cast<long long>(window.max.x) + 1;
    const long long h = static_cast<long long>(window.max.y) + 1;
    if (w <= 0 || h <= 0) throw InputError(where + ": the EXR data window is empty");
    image.width = static_cast<uint32_t>(w);
    image.height = static_cast<uint32_t>(h);
    if (check_size) check_size(image.width, image.height);

    const std::size_t texels = std::size_t{image.width} * image.height;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
      if (it.channel().xSampling != 1 || it.channel().ySampling != 1) {
        throw InputError(where + ": channel " + quoted_text(it.name()) +
                         " is subsampled; every channel must have one sample per texel");
      }
      image.channels.push_back({it.name(), from_imf(it.channel().type), {}});
    }
    Imf::FrameBuffer frame_buffer;
    for (ExrChannelRead& channel : image.channels) {
      channel.values.assign(texels, 0.0f);
      frame_buffer.insert(channel.name, float_slice(channel.values.data(), image.width));
    }
    file.setFrameBuffer(frame_buffer);
    file.readPixels(0, static_cast<int>(image.height) - 1);
    if (!file.isComplete()) {
      throw InputError(where + ": the EXR file is incomplete (truncated): some scanlines are missing");
    }
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(where + ": cannot read EXR file (corrupt or truncated): " + printable_text(e.what()));
  }
  return image;
}

}  // namespace vsgl
