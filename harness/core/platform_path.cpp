#include "harness/core/platform_path.hpp"

#include <string>

namespace vsgl {

std::filesystem::path path_from_utf8(std::string_view text) {
  return std::filesystem::path(std::u8string(text.begin(), text.end()));
}

}  // namespace vsgl
