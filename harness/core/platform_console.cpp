#include "harness/core/platform_console.hpp"

#ifdef _WIN32
#include <io.h>
#include <windows.h>
#else
#include <unistd.h>
#endif

#include <cstdlib>

namespace vsgl {

#ifdef _WIN32

bool is_terminal(std::FILE* stream) { return _isatty(_fileno(stream)) != 0; }

void use_utf8_console() {
  static const UINT before = GetConsoleOutputCP();
  if (before == 0 || before == CP_UTF8) return;                                      // no console, or already UTF-8
  if (SetConsoleOutputCP(CP_UTF8)) std::atexit([] { SetConsoleOutputCP(before); });  // the shell's, back
}

#else

bool is_terminal(std::FILE* stream) { return ::isatty(::fileno(stream)) != 0; }

void use_utf8_console() {}

#endif

}  // namespace vsgl
