#pragma once
// Environment variables as UTF-8 text (DESIGN.md §13.1), the encoding of every string the
// programs hold. Windows' getenv gives the ANSI code page, which cannot hold every file name
// (VSGL_ASSETS); there the wide (UTF-16) environment is read instead.
#include <optional>
#include <string>

namespace vsgl {

// The value of `name`, or nothing when it is not set.
std::optional<std::string> environment_variable(const char* name);

}  // namespace vsgl
