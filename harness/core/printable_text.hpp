#pragma once
// Text from a file (channel names, JSON keys and values, scene names) shown in a message: printable
// ASCII (0x20-0x7e) as is, every other byte as \xNN, the backslash too
// (\x5c), so that \x97 in a message always means the byte 0x97. A message therefore never carries raw bytes of a
// hostile or corrupt file to a terminal or a log (no invalid UTF-8, no control characters) and
// stays one line. Long texts are cut at `max_bytes` input bytes with "..." appended.
#include <cstddef>
#include <string>
#include <string_view>

namespace vsgl {

inline constexpr std::size_t kPrintableTextMaxBytes = 200;

std::string printable_text(std::string_view bytes, std::size_t max_bytes = kPrintableTextMaxBytes);

// printable_text in double quotes: the form messages use for a name, e.g. channel "val\x97d".
std::string quoted_text(std::string_view bytes, std::size_t max_bytes = kPrintableTextMaxBytes);

}  // namespace vsgl
