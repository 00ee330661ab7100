#include "harness/core/platform_arguments.hpp"

#ifdef _WIN32
#include <windows.h>

#include <shellapi.h>
#endif

namespace vsgl {

#ifdef _WIN32

namespace {

std::string to_utf8(const wchar_t* text) {
  const int size = WideCharToMultiByte(CP_UTF8, 0, text, -1, nullptr, 0, nullptr, nullptr);
  if (size <= 1) return {};
  std::string out(static_cast<std::size_t>(size), '\0');
  WideCharToMultiByte(CP_UTF8, 0, text, -1, out.data(), size, nullptr, nullptr);
  out.pop_back();  // the terminating NUL
  return out;
}

}  // namespace

Utf8Arguments::Utf8Arguments(int argc, char** argv) {
  int count = 0;
  wchar_t** wide = CommandLineToArgvW(GetCommandLineW(), &count);
  if (wide != nullptr && count == argc) {
    for (int i = 0; i < count; ++i) arguments_.push_back(to_utf8(wide[i]));
  } else {  // cannot happen for a program's own command line; keep what main() got
    for (int i = 0; i < argc; ++i) arguments_.emplace_back(argv[i]);
  }
  if (wide != nullptr) LocalFree(wide);
  for (std::string& a : arguments_) pointers_.push_back(a.data());
  pointers_.push_back(nullptr);
}

#else

Utf8Arguments::Utf8Arguments(int argc, char** argv) : pointers_(argv, argv + argc) { pointers_.push_back(nullptr); }

#endif

}  // namespace vsgl
