// libFuzzer target: the Wavefront OBJ importer (harness/scene/obj_scene.cpp, on Debian's
// tinyobjloader), and the animated frames it derives. The input is the .obj text; beside it lies
// a fixed material library, fixed.mtl (plain, cut-out, textured and normal-mapped materials),
// which the input may name with `mtllib fixed.mtl` or not, the 2x2 BMP texture it uses, and
// lost.mtl, whose material's texture is missing. Bad input must end in InputError; anything else (a crash, a sanitizer
// report, another exception) is a bug.
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz_input_files.hpp"
#include "harness/core/error.hpp"
#include "harness/scene/obj_scene.hpp"

namespace {

// A 2x2 24-bit BMP (stb_image decodes it like a PNG): header, info header, two padded rows.
std::string tiny_bmp() {
  const unsigned char bytes[70] = {
      'B', 'M', 70, 0, 0, 0, 0, 0, 0, 0, 54, 0, 0, 0,           // file header: size, pixel offset
      40, 0, 0, 0, 2, 0, 0, 0, 2, 0, 0, 0, 1, 0, 24, 0,         // info header: 2 x 2, 1 plane, 24 bit
      0, 0, 0, 0, 16, 0, 0, 0, 0x13, 0x0b, 0, 0, 0x13, 0x0b, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
      0, 0, 255, 255, 255, 255, 0, 0,                          // bottom row (BGR), padded to 8
      0, 255, 0, 128, 128, 128, 0, 0};                         // top row
  return std::string(reinterpret_cast<const char*>(bytes), sizeof bytes);
}

const vsgl::fuzz::ScratchDir& scratch() {
  static const vsgl::fuzz::ScratchDir dir = [] {
    vsgl::fuzz::ScratchDir d;
    d.write("tex.bmp", tiny_bmp());
    d.write("fixed.mtl",
            "newmtl plain\nKd 0.8 0.2 0.2\nKs 0.5 0.5 0.5\nNs 50\n"
            "newmtl cut\nKd 0.2 0.8 0.2\nd 0.4\n"
            "newmtl tex\nKd 1 1 1\nmap_Kd tex.bmp\nmap_d tex.bmp\nmap_bump tex.bmp\nNs 1000\nKs 4 4 4\n");
    // Apart: every material of a library is converted, so this one fails every input naming it.
    d.write("lost.mtl", "newmtl lost\nmap_Kd missing.png\n");
    return d;
  }();
  return dir;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const auto file = scratch().write("scene.obj", input);
  try {
    const vsgl::GltfImport imported = vsgl::import_obj(file);
    (void)vsgl::gltf_frame(imported, 1, 4);
  } catch (const vsgl::InputError&) {
  }
  return 0;
}
