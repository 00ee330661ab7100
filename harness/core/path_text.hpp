#pragma once
// A path as a message shows it (DESIGN.md §13.1): UTF-8, with '/' between its names on every host.
// On Windows a path joins the user's '/' and the system's '\' ("results\tiny.json" after
// "…/results"), and printable_text shows each '\' as \x5c; the generic form is one spelling that
// Windows itself accepts too. On POSIX it is the path as given.
#include <filesystem>
#include <string>

namespace vsgl {

std::string path_text(const std::filesystem::path& path);

}  // namespace vsgl
