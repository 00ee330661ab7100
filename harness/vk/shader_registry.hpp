#pragma once
// The SPIR-V of every kernel, compiled by CMake at build time and embedded in the binary.
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
extern const std::size_t kEmbeddedShaderCount;
}  // namespace detail

// Throws std::out_of_range naming the shader when it was not embedded.
std::span<const uint32_t> find_shader(std::string_view name);
std::vector<std::string> shader_names();

}  // namespace vsgl
