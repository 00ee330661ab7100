// libFuzzer target: the glTF 2.0 importer behind `record --gltf` (harness/scene/gltf_scene.cpp,
// on Debian's tinygltf), and the animated frames it derives. The input is a .glb when it starts
// with the binary magic "glTF", else a .gltf (JSON with embedded data: URIs). Bad input must end
// in InputError; anything else (a crash, a sanitizer report, another exception) is a bug.
#include <cstdint>
#include <string_view>

#include "fuzz_input_files.hpp"
#include "harness/core/error.hpp"
#include "harness/scene/gltf_scene.hpp"

namespace {

const vsgl::fuzz::ScratchDir& scratch() {
  static const vsgl::fuzz::ScratchDir dir;
  return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const bool binary = input.substr(0, 4) == "glTF";
  const auto file = scratch().write(binary ? "scene.glb" : "scene.gltf", input);
  try {
    const vsgl::GltfImport imported = vsgl::import_gltf(file);
    (void)vsgl::gltf_frame(imported, 1, 4);
  } catch (const vsgl::InputError&) {
  }
  return 0;
}
