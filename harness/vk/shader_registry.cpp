#include "harness/vk/shader_registry.hpp"

#include <stdexcept>

namespace vsgl {

std::span<const uint32_t> find_shader(std::string_view name) {
  for (std::size_t i = 0; i < detail::kEmbeddedShaderCount; ++i) {
    const auto& s = detail::kEmbeddedShaders[i];
    if (name == s.name) return {s.words, s.word_count};
  }
  throw std::out_of_range("no embedded shader named '" + std::string(name) + "'");
}

std::vector<std::string> shader_names() {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < detail::kEmbeddedShaderCount; ++i) out.emplace_back(detail::kEmbeddedShaders[i].name);
  return out;
}

}  // namespace vsgl
