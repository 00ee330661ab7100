#include "harness/core/embedded_files.hpp"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "harness/core/error.hpp"
#include "harness/core/json_reader.hpp"

namespace vsgl {
namespace {

std::string_view text_of(const detail::EmbeddedBytes& f) { return {reinterpret_cast<const char*>(f.bytes), f.size}; }

}  // namespace

std::optional<std::string_view> embedded_file(std::string_view name) {
  const detail::EmbeddedBytes* begin = detail::kEmbeddedFiles;
  const detail::EmbeddedBytes* end = begin + detail::kEmbeddedFileCount;
  const auto it = std::lower_bound(begin, end, name, [](const detail::EmbeddedBytes& f, std::string_view n) {
    return std::string_view(f.name) < n;
  });
  if (it == end || std::string_view(it->name) != name) return std::nullopt;
  return text_of(*it);
}

std::vector<std::string> embedded_file_names(std::string_view prefix) {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < detail::kEmbeddedFileCount; ++i) {
    const std::string_view name(detail::kEmbeddedFiles[i].name);
    if (name.substr(0, prefix.size()) == prefix) names.emplace_back(name);
  }
  return names;
}

std::string embedded_file_label(std::string_view name) { return std::string(name) + " (built in)"; }

nlohmann::ordered_json embedded_json(std::string_view name, const std::string& what) {
  const std::optional<std::string_view> text = embedded_file(name);
  if (!text) throw InputError(embedded_file_label(name) + ": this build did not embed " + what);
  return parse_json_text(*text, embedded_file_label(name), what);
}

nlohmann::ordered_json json_file_or_built_in(const std::optional<std::filesystem::path>& file,
                                             std::string_view built_in, const std::string& what,
                                             const std::string& hint) {
  return file ? read_json_file(*file, what, hint) : embedded_json(built_in, what);
}

std::string file_or_built_in_name(const std::optional<std::filesystem::path>& file, std::string_view built_in) {
  return file ? file->string() : embedded_file_label(built_in);
}

}  // namespace vsgl
