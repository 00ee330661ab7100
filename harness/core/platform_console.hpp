#pragma once
// The console the programs print to (DESIGN.md §13): whether an output is a terminal, and UTF-8
// text (µs, γ, Φ) shown as such on a Windows console.
#include <cstdio>

namespace vsgl {

// Whether `stream` (stdout, stderr) is an interactive terminal: progress lines are for people
// watching one, not for files and pipes.
bool is_terminal(std::FILE* stream);

// The programs print UTF-8. A Windows console shows text in its output code page, so this
// switches that to UTF-8 (SetConsoleOutputCP) for the life of the process; elsewhere it does
// nothing. Files and pipes get the same bytes either way.
void use_utf8_console();

}  // namespace vsgl
