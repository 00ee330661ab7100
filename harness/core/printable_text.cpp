#include "harness/core/printable_text.hpp"

namespace vsgl {

std::string printable_text(std::string_view bytes, std::size_t max_bytes) {
  static constexpr char kHex[] = "0123456789abcdef";
  const bool cut = bytes.size() > max_bytes;
  if (cut) bytes = bytes.substr(0, max_bytes);
  std::string out;
  out.reserve(bytes.size() + 8);
  for (const char ch : bytes) {
    const auto byte = static_cast<unsigned char>(ch);
    if (byte >= 0x20 && byte <= 0x7e && byte != '\\') {
      out += ch;
    } else {  // also the backslash, so that "\x97" in a message always means the byte 0x97
      out += "\\x";
      out += kHex[byte >> 4];
      out += kHex[byte & 0xf];
    }
  }
  if (cut) out += "...";
  return out;
}

std::string quoted_text(std::string_view bytes, std::size_t max_bytes) {
  return "\"" + printable_text(bytes, max_bytes) + "\"";
}

}  // namespace vsgl
