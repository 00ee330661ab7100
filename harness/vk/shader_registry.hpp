#pragma once
// The SPIR-V of every kernel, compiled by CMake at build time and embedded in the binary
// (cmake/Shaders.cmake): the kernels of kernels/ in the table kEmbeddedShaders, and any table a
// program adds (the tests add the test kernels, kernels/test_*.comp, which the shipped programs
// do not hold: docs/testing.md, "Test hooks").
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vsgl {

namespace detail {
struct EmbeddedShader {
  const char* name;  // file name, e.g. "fis_mip_level.comp"
  const uint32_t* words;
  std::size_t word_count;
};
extern const EmbeddedShader kEmbeddedShaders[];
extern const std::size_t kEmbeddedShadersCount;
}  // namespace detail

// Makes a further table of embedded shaders findable, after kEmbeddedShaders. The table must
// outlive every use; a name it shares with an earlier table is refused (std::logic_error).
void add_embedded_shaders(std::span<const detail::EmbeddedShader> shaders);

// Throws std::out_of_range naming the shader when it was not embedded.
std::span<const uint32_t> find_shader(std::string_view name);
std::vector<std::string> shader_names();

}  // namespace vsgl
