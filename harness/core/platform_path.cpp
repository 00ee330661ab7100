#include "harness/core/platform_path.hpp"

#include <string>

namespace vsgl {

std::filesystem::path path_from_utf8(std::string_view text) {
  return std::filesystem::path(std::u8string(text.begin(), text.end()));
}

std::vector<std::filesystem::path> paths_from_utf8(const std::vector<std::string>& texts) {
  std::vector<std::filesystem::path> paths;
  for (const std::string& text : texts) paths.push_back(path_from_utf8(text));
  return paths;
}

}  // namespace vsgl
