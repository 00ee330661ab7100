#include "harness/core/path_text.hpp"

namespace vsgl {

std::string path_text(const std::filesystem::path& path) {
  const std::u8string text = path.generic_u8string();  // UTF-8 whatever the C locale (platform_path.hpp)
  return std::string(text.begin(), text.end());
}

}  // namespace vsgl
