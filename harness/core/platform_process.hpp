#pragma once
// Process identity, for names unique to one process (atomic_file's temporaries) and for telling
// whether the process that left such a file behind is gone (DESIGN.md §12, §13: POSIX and Windows).
#include <cstdint>

namespace vsgl {

// This process's id (getpid, GetCurrentProcessId).
std::uint64_t current_process_id();

// True only when no running process has `id`: it has ended. An existing process we may not
// inspect counts as running.
bool process_is_gone(std::uint64_t id);

}  // namespace vsgl
