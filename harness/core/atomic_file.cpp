#include "harness/core/atomic_file.hpp"

#include <atomic>
#include <cstdlib>
#include <string>
#include <system_error>

#include "harness/core/atomic_write_observer.hpp"
#include "harness/core/error.hpp"
#include "harness/core/path_text.hpp"
#include "harness/core/platform_file.hpp"
#include "harness/core/platform_process.hpp"

namespace vsgl {
namespace {

// A name no other writer (thread or process) uses at the same time: pid + a process-wide counter.
std::string temporary_prefix_for(const std::filesystem::path& path) {
  return "." + path.filename().string() + ".tmp-";
}

std::filesystem::path temporary_path_for(const std::filesystem::path& path) {
  static std::atomic<unsigned long long> counter{0};
  std::string name =
      temporary_prefix_for(path) + std::to_string(current_process_id()) + "-" + std::to_string(counter.fetch_add(1));
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
    const unsigned long long pid = std::strtoull(rest.substr(0, dash).c_str(), nullptr, 10);
    if (pid == 0 || pid == current_process_id()) continue;
    if (!process_is_gone(pid)) continue;  // its writer may still run
    std::error_code ignored;
    std::filesystem::remove(it->path(), ignored);
  }
}

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what, std::error_code error) {
  throw InputError(path_text(path) + ": cannot write file: " + what + ": " + error.message());
}

// Writes and flushes the temporary file; on any failure the caller removes it.
void write_temporary(const std::filesystem::path& target, const std::filesystem::path& temporary,
                     std::span<const char> bytes, AtomicWriteObserver* observer) {
  NewFile file;
  if (auto ec = file.create(temporary)) fail(target, "creating temporary " + path_text(temporary), ec);
  // An observer may stop the write with half of the bytes in the temporary (atomic_write_observer.hpp).
  const bool halves = observer != nullptr && observer->wants_partial(target);
  const std::size_t first = halves ? bytes.size() / 2 : bytes.size();
  if (auto ec = file.write(bytes.first(first))) fail(target, "writing temporary " + path_text(temporary), ec);
  if (halves) {
    observer->reached(AtomicWriteStage::kPartial, target);
    if (auto ec = file.write(bytes.subspan(first))) fail(target, "writing temporary " + path_text(temporary), ec);
  }
  if (auto ec = file.flush_to_disk()) fail(target, "flushing temporary " + path_text(temporary), ec);
  if (auto ec = file.close()) fail(target, "closing temporary " + path_text(temporary), ec);
}

}  // namespace

void write_file_atomic(const std::filesystem::path& path, std::span<const char> bytes) {
  AtomicWriteObserver* const observer = atomic_write_observer();  // none in the shipped programs
  if (observer != nullptr) observer->write_begins(path);
  remove_stale_temporaries(path);
  const std::filesystem::path temporary = temporary_path_for(path);
  try {
    write_temporary(path, temporary, bytes, observer);
    if (observer != nullptr) observer->reached(AtomicWriteStage::kComplete, path);
    if (auto ec = replace_file(temporary, path)) {
      fail(path, "renaming temporary " + path_text(temporary) + " onto it", ec);
    }
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw;
  }
  if (observer != nullptr) observer->reached(AtomicWriteStage::kRenamed, path);
  sync_directory(path.parent_path());
}

void write_text_atomic(const std::filesystem::path& path, std::string_view text) {
  write_file_atomic(path, std::span<const char>(text.data(), text.size()));
}

}  // namespace vsgl
