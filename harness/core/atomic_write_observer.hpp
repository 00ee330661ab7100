#pragma once
// A seam of the atomic writer (atomic_file.hpp): an observer told of the stages of every write.
// The kill tests install one in the test build of vsgl-bench (tests/hooks/, docs/testing.md) to
// stop a real run at a known point of writing a known file; the shipped programs install none,
// and then each write costs one pointer load more.
#include <filesystem>

namespace vsgl {

enum class AtomicWriteStage {
  kPartial,   // half of the bytes are in the temporary file (not flushed, not renamed)
  kComplete,  // the temporary file is complete and flushed, not yet renamed over the target
  kRenamed,   // the target has been replaced, the directory is not yet synced
};

class AtomicWriteObserver {
 public:
  virtual ~AtomicWriteObserver() = default;
  // Once as each write of `target` begins.
  virtual void write_begins(const std::filesystem::path& target) = 0;
  // Whether this write should stop at kPartial: only then are the bytes written in two halves.
  virtual bool wants_partial(const std::filesystem::path& target) = 0;
  // At each stage of the write (kPartial only when wanted); may block.
  virtual void reached(AtomicWriteStage stage, const std::filesystem::path& target) = 0;
};

// Installs `observer` for every later write of this process (nullptr: none). It must outlive them.
void set_atomic_write_observer(AtomicWriteObserver* observer);

// The installed observer, or nullptr.
AtomicWriteObserver* atomic_write_observer();

}  // namespace vsgl
