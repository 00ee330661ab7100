#include "harness/core/atomic_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>

#include "harness/core/error.hpp"
#include "harness/core/test_pause.hpp"

namespace vsgl {
namespace {

std::string errno_text(int error) { return std::strerror(error); }

// A name no other writer (thread or process) uses at the same time: pid + a process-wide counter.
std::string temporary_prefix_for(const std::filesystem::path& path) {
  return "." + path.filename().string() + ".tmp-";
}

std::filesystem::path temporary_path_for(const std::filesystem::path& path) {
  static std::atomic<unsigned long long> counter{0};
  std::string name = temporary_prefix_for(path) + std::to_string(::getpid()) + "-" +
                     std::to_string(counter.fetch_add(1));
  return path.parent_path() / name;
}

// A run killed while writing (SIGKILL, power loss) leaves its temporary behind; readers never
// look at temporaries, and the next write of the same file removes those whose writer is gone
// (".NAME.tmp-PID-N" with no process PID). Best effort: errors are ignored.
void remove_stale_temporaries(const std::filesystem::path& path) {
  const std::string prefix = temporary_prefix_for(path);
  const std::filesystem::path dir = path.parent_path().empty() ? "." : path.parent_path();
  std::error_code ec;
  for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    const std::string rest = name.substr(prefix.size());  // "PID-N"
    const std::size_t dash = rest.find('-');
    if (dash == 0 || dash == std::string::npos) continue;
    if (rest.find_first_not_of("0123456789-") != std::string::npos) continue;
    const long pid = std::strtol(rest.substr(0, dash).c_str(), nullptr, 10);
    if (pid <= 0 || pid == ::getpid()) continue;
    if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;  // its writer may still run
    std::error_code ignored;
    std::filesystem::remove(it->path(), ignored);
  }
}

// Owns an open file descriptor; closes it when dropped.
class FileDescriptor {
 public:
  explicit FileDescriptor(int fd) : fd_(fd) {}
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;
  ~FileDescriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  int get() const { return fd_; }
  // Closes now so that a failing close (delayed write errors) is reported.
  int close_now() {
    int result = ::close(fd_);
    fd_ = -1;
    return result;
  }

 private:
  int fd_;
};

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what, int error) {
  throw InputError(path.string() + ": cannot write file: " + what + ": " + errno_text(error));
}

// Writes and flushes the temporary file; on any failure the caller removes it.
void write_temporary(const std::filesystem::path& target, const std::filesystem::path& temporary,
                     std::span<const char> bytes) {
  FileDescriptor fd(::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644));
  if (fd.get() < 0) fail(target, "creating temporary " + temporary.string(), errno);
  // TEST-ONLY (harness/core/test_pause.hpp): stop with half of the bytes written.
  const std::size_t first = test_pause_wanted("partial", target) ? bytes.size() / 2 : bytes.size();
  std::size_t written = 0;
  while (written < bytes.size()) {
    if (written >= first) test_pause_point("partial", target);
    const std::size_t limit = written < first ? first : bytes.size();
    ssize_t n = ::write(fd.get(), bytes.data() + written, limit - written);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail(target, "writing temporary " + temporary.string(), errno);
    }
    written += static_cast<std::size_t>(n);
  }
  if (::fsync(fd.get()) != 0) fail(target, "flushing temporary " + temporary.string(), errno);
  if (fd.close_now() != 0) fail(target, "closing temporary " + temporary.string(), errno);
}

// Makes the rename itself durable. Best effort: some file systems refuse fsync on directories.
void sync_directory(const std::filesystem::path& dir) {
  int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

void write_file_atomic(const std::filesystem::path& path, std::span<const char> bytes) {
  test_pause_count_write(path);  // TEST-ONLY (harness/core/test_pause.hpp)
  remove_stale_temporaries(path);
  const std::filesystem::path temporary = temporary_path_for(path);
  try {
    write_temporary(path, temporary, bytes);
    test_pause_point("complete", path);  // TEST-ONLY (harness/core/test_pause.hpp)
    if (::rename(temporary.c_str(), path.c_str()) != 0) {
      fail(path, "renaming temporary " + temporary.string() + " onto it", errno);
    }
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw;
  }
  test_pause_point("renamed", path);  // TEST-ONLY (harness/core/test_pause.hpp)
  sync_directory(path.parent_path());
}

void write_text_atomic(const std::filesystem::path& path, std::string_view text) {
  write_file_atomic(path, std::span<const char>(text.data(), text.size()));
}

}  // namespace vsgl
