#include "harness/vk/shader_registry.hpp"

#include <algorithm>
#include <mutex>
#include <stdexcept>

namespace vsgl {
namespace {

struct Tables {
  std::mutex mutex;
  std::vector<std::span<const detail::EmbeddedShader>> added;
};

Tables& tables() {
  static Tables t;
  return t;
}

// kEmbeddedShaders, then the added tables in the order they were added.
std::vector<std::span<const detail::EmbeddedShader>> all_tables() {
  std::vector<std::span<const detail::EmbeddedShader>> out{{detail::kEmbeddedShaders, detail::kEmbeddedShadersCount}};
  Tables& t = tables();
  const std::lock_guard lock(t.mutex);
  out.insert(out.end(), t.added.begin(), t.added.end());
  return out;
}

}  // namespace

void add_embedded_shaders(std::span<const detail::EmbeddedShader> shaders) {
  const std::vector<std::string> known = shader_names();
  for (const auto& s : shaders)
    if (std::find(known.begin(), known.end(), s.name) != known.end())
      throw std::logic_error(std::string("embedded shader '") + s.name + "' added twice");
  Tables& t = tables();
  const std::lock_guard lock(t.mutex);
  t.added.push_back(shaders);
}

std::span<const uint32_t> find_shader(std::string_view name) {
  for (const auto& table : all_tables())
    for (const auto& s : table)
      if (name == s.name) return {s.words, s.word_count};
  throw std::out_of_range("no embedded shader named '" + std::string(name) + "'");
}

std::vector<std::string> shader_names() {
  std::vector<std::string> out;
  for (const auto& table : all_tables())
    for (const auto& s : table) out.emplace_back(s.name);
  return out;
}

}  // namespace vsgl
