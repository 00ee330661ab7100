#include "harness/core/platform_environment.hpp"

#include <cstdlib>

#ifdef _WIN32
#include <windows.h>
#endif

namespace vsgl {

#ifdef _WIN32

std::optional<std::string> environment_variable(const char* name) {
  const auto wide = [](const char* text, UINT code_page) {
    const int size = MultiByteToWideChar(code_page, 0, text, -1, nullptr, 0);
    std::wstring out(static_cast<std::size_t>(size > 0 ? size : 1), L'\0');
    MultiByteToWideChar(code_page, 0, text, -1, out.data(), size);
    out.pop_back();  // the terminating NUL
    return out;
  };
  const wchar_t* value = _wgetenv(wide(name, CP_UTF8).c_str());
  if (value == nullptr) return std::nullopt;
  const int size = WideCharToMultiByte(CP_UTF8, 0, value, -1, nullptr, 0, nullptr, nullptr);
  std::string out(static_cast<std::size_t>(size > 0 ? size : 1), '\0');
  WideCharToMultiByte(CP_UTF8, 0, value, -1, out.data(), size, nullptr, nullptr);
  out.pop_back();
  return out;
}

#else

std::optional<std::string> environment_variable(const char* name) {
  const char* value = std::getenv(name);
  if (value == nullptr) return std::nullopt;
  return std::string(value);
}

#endif

}  // namespace vsgl
