#pragma once
// File names given as text (command-line arguments, which are UTF-8 on every system:
// platform_arguments.hpp) become paths here (DESIGN.md §13). std::filesystem::path's constructor
// from std::string takes the native narrow encoding: UTF-8 on Linux, but on Windows (libstdc++)
// the C locale's byte-per-character one, which turns "données" into "donnÃ©es". UTF-8 text
// (char8_t) converts correctly everywhere. The other way, path::string() is UTF-8 on both.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace vsgl {

std::filesystem::path path_from_utf8(std::string_view text);
std::vector<std::filesystem::path> paths_from_utf8(const std::vector<std::string>& texts);

// What separates the directories of a list in one variable (VSGL_ASSETS), as in PATH: ';' on
// Windows, where ':' follows a drive letter, ':' elsewhere.
#ifdef _WIN32
inline constexpr char kPathListSeparator = ';';
#else
inline constexpr char kPathListSeparator = ':';
#endif

}  // namespace vsgl
