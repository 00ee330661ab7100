#include "harness/scene/detail/gltf_accessors.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>

namespace vsgl::gltf {
namespace {

uint32_t le32(const std::vector<unsigned char>& b, std::size_t at) {
  return uint32_t{b[at]} | uint32_t{b[at + 1]} << 8 | uint32_t{b[at + 2]} << 16 | uint32_t{b[at + 3]} << 24;
}

std::size_t component_bytes(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

double read_component(const unsigned char* p, int type, bool normalized) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
      float f;
      std::memcpy(&f, p, 4);
      return f;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? p[0] / 255.0 : p[0];
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const auto v = static_cast<signed char>(p[0]);
      return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      uint16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? v / 65535.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      int16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? std::max(v / 32767.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      uint32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
    case TINYGLTF_COMPONENT_TYPE_INT: {
      int32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
    default: return 0.0;
  }
}

}  // namespace

std::vector<unsigned char> read_bytes(const std::filesystem::path& path, const Reporter& r) {
  std::error_code ec;
  // A directory opens as a stream whose reads throw (std::ios_failure): refused first.
  if (std::filesystem::is_directory(path, ec)) r.fail("is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) r.fail("cannot be opened (missing or unreadable)");
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) r.fail("could not be read");
  return bytes;
}

void require_gltf2(const std::vector<unsigned char>& bytes, const Reporter& r) {
  std::string json_text;
  if (bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0) {
    if (bytes.size() < 20) r.fail("binary glTF header is truncated (" + std::to_string(bytes.size()) + " bytes)");
    const uint32_t version = le32(bytes, 4);
    if (version != 2)
      r.fail("binary glTF container version " + std::to_string(version) +
             (version == 1 ? " is glTF 1.0" : "") + "; only glTF 2.0 is supported");
    const uint32_t json_length = le32(bytes, 12);
    if (json_length > bytes.size() - 20) r.fail("binary glTF JSON chunk runs past the end of the file");
    json_text.assign(reinterpret_cast<const char*>(bytes.data()) + 20, json_length);
  } else {
    json_text.assign(bytes.begin(), bytes.end());
  }
  const nlohmann::ordered_json doc = nlohmann::ordered_json::parse(json_text, nullptr, /*allow_exceptions=*/false);
  if (doc.is_discarded()) r.fail("is not valid JSON (neither a .gltf nor a .glb file)");
  if (!doc.is_object()) r.fail("is not a glTF document (top level is not a JSON object)");
  const auto asset = doc.find("asset");
  if (asset == doc.end() || !asset->is_object() || !asset->contains("version") || !(*asset)["version"].is_string())
    r.fail("has no asset.version (glTF 1.0 files may omit it); only glTF 2.0 is supported");
  const std::string version = (*asset)["version"].get<std::string>();
  if (version.rfind("2.", 0) != 0)
    r.fail("is glTF " + escape_name(version) + "; only glTF 2.0 is supported (convert it, e.g. with gltf-pipeline)");
}

bool load_image_checked(tinygltf::Image* image, const int image_idx, std::string* err, std::string* warn,
                        int req_width, int req_height, const unsigned char* bytes, int size, void* user_data) {
  const auto* ctx = static_cast<const ImageLoadContext*>(user_data);
  if (image->bufferView >= 0) {
    const tinygltf::Model& m = *ctx->model;
    // The loader found both indices valid before calling; the range is what it does not check.
    const tinygltf::BufferView& view = m.bufferViews[static_cast<std::size_t>(image->bufferView)];
    const tinygltf::Buffer& buffer = m.buffers[static_cast<std::size_t>(view.buffer)];
    if (view.byteOffset > buffer.data.size() || view.byteLength > buffer.data.size() - view.byteOffset) {
      if (err != nullptr) {
        *err += "image " + std::to_string(image_idx) + ": bufferView " + std::to_string(image->bufferView) +
                " (offset " + std::to_string(view.byteOffset) + ", " + std::to_string(view.byteLength) +
                " bytes) runs past the end of buffer " + std::to_string(view.buffer) + " (" +
                std::to_string(buffer.data.size()) + " bytes)";
      }
      return false;
    }
  }
  return tinygltf::LoadImageData(image, image_idx, err, warn, req_width, req_height, bytes, size, nullptr);
}

int type_components(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    default: return 0;
  }
}

bool finite3(glm::dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::vector<double> Importer::read_accessor(int index, int want_components, const std::string& what) const {
  const tinygltf::Accessor& a = accessor(index, what);
  const std::string where = what + " (accessor " + std::to_string(index) + ")";
  if (a.sparse.isSparse) r_.fail(where + ": sparse accessors are not supported");
  const int comps = type_components(a.type);
  const std::size_t csize = component_bytes(a.componentType);
  if (comps == 0 || csize == 0) r_.fail(where + ": unsupported accessor type or component type");
  if (comps != want_components)
    r_.fail(where + ": has " + std::to_string(comps) + " components per element, expected " +
            std::to_string(want_components));
  const std::size_t count = a.count;
  std::vector<double> out(count * static_cast<std::size_t>(comps), 0.0);
  if (a.bufferView < 0) return out;  // glTF: an accessor without a buffer view is all zeros
  if (static_cast<std::size_t>(a.bufferView) >= m_.bufferViews.size())
    r_.fail(where + ": buffer view " + std::to_string(a.bufferView) + " does not exist");
  const tinygltf::BufferView& view = m_.bufferViews[static_cast<std::size_t>(a.bufferView)];
  if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= m_.buffers.size())
    r_.fail(where + ": buffer " + std::to_string(view.buffer) + " does not exist");
  const tinygltf::Buffer& buffer = m_.buffers[static_cast<std::size_t>(view.buffer)];
  const std::string buffer_name =
      "buffer " + std::to_string(view.buffer) + (buffer.uri.empty() || buffer.uri.rfind("data:", 0) == 0
                                                     ? std::string()
                                                     : " (" + quote_name(buffer.uri) + ")");
  if (buffer.data.empty()) r_.fail(where + ": " + buffer_name + " is missing or empty");
  if (view.byteOffset > buffer.data.size() || view.byteLength > buffer.data.size() - view.byteOffset)
    r_.fail(where + ": buffer view " + std::to_string(a.bufferView) + " (bytes " + std::to_string(view.byteOffset) +
            " + " + std::to_string(view.byteLength) + ") runs past the end of " + buffer_name + " (" +
            std::to_string(buffer.data.size()) + " bytes): the buffer is short");
  const std::size_t element = csize * static_cast<std::size_t>(comps);
  const std::size_t stride = view.byteStride != 0 ? view.byteStride : element;
  if (count == 0) return out;
  const std::size_t needed = a.byteOffset + stride * (count - 1) + element;
  if (a.byteOffset > view.byteLength || needed > view.byteLength)
    r_.fail(where + ": " + std::to_string(count) + " elements need " + std::to_string(needed) +
            " bytes of buffer view " + std::to_string(a.bufferView) + ", which has " +
            std::to_string(view.byteLength));
  const unsigned char* base = buffer.data.data() + view.byteOffset + a.byteOffset;
  for (std::size_t i = 0; i < count; ++i)
    for (int c = 0; c < comps; ++c)
      out[i * static_cast<std::size_t>(comps) + static_cast<std::size_t>(c)] =
          read_component(base + i * stride + static_cast<std::size_t>(c) * csize, a.componentType, a.normalized);
  return out;
}

}  // namespace vsgl::gltf
