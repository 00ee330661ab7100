#include "harness/core/text_file.hpp"

#include <fstream>
#include <iterator>

#include "harness/core/path_text.hpp"
#include "harness/core/error.hpp"

namespace vsgl {

std::string read_text_file(const std::filesystem::path& path, const std::string& what, const std::string& hint) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path_text(path) + ": cannot read " + what + hint);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw InputError(path_text(path) + ": cannot read " + what + hint);
  return text;
}

}  // namespace vsgl
