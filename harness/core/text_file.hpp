#pragma once
// A whole file read as bytes, for the readers of JSON, presets and other text inputs.
#include <filesystem>
#include <string>

namespace vsgl {

// The file's bytes; throws InputError "<path>: cannot read <what><hint>" when it cannot be opened
// or read to the end.
std::string read_text_file(const std::filesystem::path& path, const std::string& what, const std::string& hint = "");

}  // namespace vsgl
