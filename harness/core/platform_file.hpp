#pragma once
// The operating system calls behind atomic_file (DESIGN.md §12, §13): create a new file, write
// it, flush it to disk, and rename it over an existing file in one step. POSIX: open/write/
// fsync/rename; Windows: CreateFileW/WriteFile/FlushFileBuffers/MoveFileExW, with wide
// (UTF-16) file names so that any path works.
#include <cstdint>
#include <filesystem>
#include <span>
#include <system_error>

namespace vsgl {

// A file this process created for writing; closed when dropped.
class NewFile {
 public:
  NewFile() = default;
  NewFile(const NewFile&) = delete;
  NewFile& operator=(const NewFile&) = delete;
  ~NewFile();
  // Creates `path`, which must not exist yet (O_EXCL, CREATE_NEW).
  std::error_code create(const std::filesystem::path& path);
  // Writes all of `bytes` (retrying short and interrupted writes).
  std::error_code write(std::span<const char> bytes);
  // The written bytes reach the disk (fsync, FlushFileBuffers).
  std::error_code flush_to_disk();
  // Closes now, so that a failing close (delayed write errors) is reported.
  std::error_code close();

 private:
  std::intptr_t handle_ = -1;  // file descriptor (POSIX) or HANDLE (Windows); -1: none
};

// Renames `from` onto `to`, replacing `to` if it exists, atomically: a reader of `to` sees the
// old file or the new one. Both lie in the same directory.
std::error_code replace_file(const std::filesystem::path& from, const std::filesystem::path& to);

// Makes a rename in `dir` durable where the system needs that (fsync of the directory on POSIX;
// best effort, errors are ignored). Windows has no such call: MoveFileExW's write-through does it.
void sync_directory(const std::filesystem::path& dir);

}  // namespace vsgl
