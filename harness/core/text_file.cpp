#include "harness/core/text_file.hpp"

#include <fstream>
#include <iterator>

#include "harness/core/error.hpp"

namespace vsgl {

std::string read_text_file(const std::filesystem::path& path, const std::string& what, const std::string& hint) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string() + ": cannot read " + what + hint);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw InputError(path.string() + ": cannot read " + what + hint);
  return text;
}

}  // namespace vsgl
