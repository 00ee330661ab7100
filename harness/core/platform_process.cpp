#include "harness/core/platform_process.hpp"

#ifdef _WIN32
#include <windows.h>
#else
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#endif

namespace vsgl {

#ifdef _WIN32

std::uint64_t current_process_id() { return GetCurrentProcessId(); }

bool process_is_gone(std::uint64_t id) {
  if (id > MAXDWORD) return true;  // no Windows process id is this large
  HANDLE process = OpenProcess(SYNCHRONIZE, FALSE, static_cast<DWORD>(id));
  if (process == nullptr) return GetLastError() == ERROR_INVALID_PARAMETER;  // no such process
  // A process that has ended but whose handle someone still holds is signalled; the exit code
  // alone cannot tell (a process may exit with STILL_ACTIVE's value).
  const bool ended = WaitForSingleObject(process, 0) == WAIT_OBJECT_0;
  CloseHandle(process);
  return ended;
}

#else

std::uint64_t current_process_id() { return static_cast<std::uint64_t>(::getpid()); }

bool process_is_gone(std::uint64_t id) {
  const auto pid = static_cast<pid_t>(id);
  if (pid <= 0 || static_cast<std::uint64_t>(pid) != id) return true;  // no process has this id
  return ::kill(pid, 0) != 0 && errno == ESRCH;                        // EPERM: it exists, owned by someone else
}

#endif

}  // namespace vsgl
