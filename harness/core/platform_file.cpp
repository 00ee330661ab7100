#include "harness/core/platform_file.hpp"

#ifdef _WIN32
#include <windows.h>

#include <chrono>
#include <thread>
#else
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#endif

#include <algorithm>

namespace vsgl {

#ifdef _WIN32
namespace {

std::error_code last_error() { return {static_cast<int>(GetLastError()), std::system_category()}; }
HANDLE as_handle(std::intptr_t h) { return reinterpret_cast<HANDLE>(h); }

}  // namespace

NewFile::~NewFile() {
  if (handle_ != -1) CloseHandle(as_handle(handle_));
}

std::error_code NewFile::create(const std::filesystem::path& path) {
  HANDLE h = CreateFileW(path.c_str(), GENERIC_WRITE, 0, nullptr, CREATE_NEW, FILE_ATTRIBUTE_NORMAL, nullptr);
  if (h == INVALID_HANDLE_VALUE) return last_error();
  handle_ = reinterpret_cast<std::intptr_t>(h);
  return {};
}

std::error_code NewFile::write(std::span<const char> bytes) {
  while (!bytes.empty()) {
    const auto chunk = static_cast<DWORD>(std::min<std::size_t>(bytes.size(), std::size_t{1} << 30));
    DWORD n = 0;
    if (!WriteFile(as_handle(handle_), bytes.data(), chunk, &n, nullptr)) return last_error();
    bytes = bytes.subspan(n);
  }
  return {};
}

std::error_code NewFile::flush_to_disk() {
  if (!FlushFileBuffers(as_handle(handle_))) return last_error();
  return {};
}

std::error_code NewFile::close() {
  HANDLE h = as_handle(handle_);
  handle_ = -1;
  if (!CloseHandle(h)) return last_error();
  return {};
}

std::error_code replace_file(const std::filesystem::path& from, const std::filesystem::path& to) {
  // A reader (or a virus scanner) holding `to` open without FILE_SHARE_DELETE makes the replace
  // fail with a sharing error until it closes the file: retried for up to a second.
  for (int attempt = 0;; ++attempt) {
    if (MoveFileExW(from.c_str(), to.c_str(), MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH)) return {};
    const DWORD error = GetLastError();
    if ((error != ERROR_ACCESS_DENIED && error != ERROR_SHARING_VIOLATION) || attempt == 20) {
      return {static_cast<int>(error), std::system_category()};
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
}

void sync_directory(const std::filesystem::path&) {}

#else

NewFile::~NewFile() {
  if (handle_ >= 0) ::close(static_cast<int>(handle_));
}

std::error_code NewFile::create(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) return {errno, std::generic_category()};
  handle_ = fd;
  return {};
}

std::error_code NewFile::write(std::span<const char> bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::write(static_cast<int>(handle_), bytes.data(), bytes.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      return {errno, std::generic_category()};
    }
    bytes = bytes.subspan(static_cast<std::size_t>(n));
  }
  return {};
}

std::error_code NewFile::flush_to_disk() {
  if (::fsync(static_cast<int>(handle_)) != 0) return {errno, std::generic_category()};
  return {};
}

std::error_code NewFile::close() {
  const int fd = static_cast<int>(handle_);
  handle_ = -1;
  if (::close(fd) != 0) return {errno, std::generic_category()};
  return {};
}

std::error_code replace_file(const std::filesystem::path& from, const std::filesystem::path& to) {
  if (::rename(from.c_str(), to.c_str()) != 0) return {errno, std::generic_category()};
  return {};
}

void sync_directory(const std::filesystem::path& dir) {
  const int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

#endif

}  // namespace vsgl
