#pragma once
// glTF import, part 1 of 4 (gltf_scene.cpp chooses; see also gltf_materials, gltf_nodes): the
// file's bytes (reading, the glTF 2.0 version check, the content hash, the checked image loader)
// and its accessors, decoded to doubles with every byte checked to lie inside its buffer.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <tiny_gltf.h>

#include <glm/glm.hpp>

#include "harness/core/content_hash.hpp"
#include "harness/core/error.hpp"
#include "harness/scene/gltf_scene.hpp"

namespace vsgl::gltf {

// FNV-1a, 64 bit, over several byte ranges in turn (core/content_hash.hpp).
using Fnv1a = Fnv1a64;

inline std::string quote_name(const std::string& name) { return "'" + escape_name(name) + "'"; }

// Builds messages "glTF file F: <where>: <problem>" (or "OBJ file F: ...") and throws them.
class Reporter {
 public:
  explicit Reporter(std::string file, std::string kind = "glTF file") : file_(std::move(file)), kind_(std::move(kind)) {}
  [[noreturn]] void fail(const std::string& problem) const {
    throw InputError(kind_ + " " + file_ + ": " + problem);
  }
  const std::string& file() const { return file_; }

 private:
  std::string file_;
  std::string kind_;
};

std::vector<unsigned char> read_bytes(const std::filesystem::path& path, const Reporter& r);

// tinygltf reads many glTF 1.0 files without complaint and then finds nothing (or garbage) in
// them, so the version is checked first: from the binary header, else from asset.version.
void require_gltf2(const std::vector<unsigned char>& bytes, const Reporter& r);

// tinygltf 2.7 (Debian 12) hands an image's bufferView to the decoder as
// &buffer.data[byteOffset] with byteLength bytes, without checking that the view lies inside its
// buffer: a file whose view runs past the buffer made stb_image read past the heap block (found
// by fuzz_gltf). This loader checks the view against the model being filled (its buffers and
// views are parsed before the images) and only then lets tinygltf's own decoder run.
struct ImageLoadContext {
  const tinygltf::Model* model = nullptr;
};

bool load_image_checked(tinygltf::Image* image, const int image_idx, std::string* err, std::string* warn,
                        int req_width, int req_height, const unsigned char* bytes, int size, void* user_data);

// Components per element of an accessor type (SCALAR 1 ... VEC4 4), 0 for the others.
int type_components(int type);

bool finite3(glm::dvec3 v);

// The model's accessors, each read with every byte checked.
class Importer {
 public:
  Importer(const tinygltf::Model& model, Reporter reporter) : m_(model), r_(std::move(reporter)) {}

  // Accessor `index`, an error naming `what` when there is none.
  const tinygltf::Accessor& accessor(int index, const std::string& what) const {
    if (index < 0 || static_cast<std::size_t>(index) >= m_.accessors.size())
      r_.fail(what + ": accessor " + std::to_string(index) + " does not exist (" +
              std::to_string(m_.accessors.size()) + " accessors)");
    return m_.accessors[static_cast<std::size_t>(index)];
  }

  // The accessor's elements as doubles (count * components), every byte checked to lie inside
  // its buffer view and buffer. `what` names the accessor's use in messages.
  std::vector<double> read_accessor(int index, int want_components, const std::string& what) const;

  const tinygltf::Model& model() const { return m_; }
  const Reporter& reporter() const { return r_; }

 private:
  const tinygltf::Model& m_;
  Reporter r_;
};

}  // namespace vsgl::gltf
