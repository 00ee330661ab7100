#pragma once
// A program a test starts, waits for or kills, with its output in a file (DESIGN.md §13.1): fork/
// execv/waitpid/SIGKILL on POSIX, CreateProcessW/WaitForSingleObject/TerminateProcess on Windows,
// so that the tests that stop vsgl-bench mid-write or need an ended process run in both builds.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#ifdef _WIN32
#include <windows.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <map>
#include <stdexcept>

#include "harness/core/platform_path.hpp"
#else
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#endif

namespace vsgl::test {

// NAME=VALUE set in the child's environment; an empty VALUE removes NAME there.
using EnvironmentChanges = std::vector<std::pair<std::string, std::string>>;

class ChildProcess;
#ifdef _WIN32
namespace detail {
ChildProcess start_process(const std::string& executable, const std::vector<std::string>& arguments,
                           const std::filesystem::path& log, const EnvironmentChanges& environment, bool suspended);
}  // namespace detail
#endif

class ChildProcess {
 public:
  // Starts `executable` with `arguments`, stdout and stderr both to `log` (created or truncated).
  static ChildProcess start(const std::string& executable, const std::vector<std::string>& arguments,
                            const std::filesystem::path& log, const EnvironmentChanges& environment = {});
  // A process that does nothing and lives until it is killed (at the latest by the destructor).
  static ChildProcess start_idle();
  ChildProcess(ChildProcess&& other) noexcept { *this = std::move(other); }
  ChildProcess& operator=(ChildProcess&& other) noexcept;
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;
  ~ChildProcess();

  std::uint64_t id() const { return id_; }
  // The exit code once it has ended (-1 when it was killed), or nothing while it runs.
  std::optional<int> exit_code_if_ended();
  // Waits for the end; the exit code (-1 when it was killed).
  int wait();
  // Kills it (SIGKILL; TerminateProcess) and waits; true when it ended by that kill.
  bool kill_and_wait();

 private:
  ChildProcess() = default;
  std::uint64_t id_ = 0;
  std::optional<int> exit_code_;
#ifdef _WIN32
  ChildProcess(HANDLE process, std::uint64_t id) : id_(id), process_(process) {}
  friend ChildProcess detail::start_process(const std::string&, const std::vector<std::string>&,
                                            const std::filesystem::path&, const EnvironmentChanges&, bool);
  HANDLE process_ = nullptr;
  bool killed_ = false;
#endif
};

#ifdef _WIN32

namespace detail {

inline std::wstring wide(const std::string& utf8) { return path_from_utf8(utf8).wstring(); }

// One argument as CommandLineToArgvW reads it back: quoted, with backslashes before a quote doubled.
inline std::wstring quoted_argument(const std::wstring& argument) {
  if (!argument.empty() && argument.find_first_of(L" \t\"") == std::wstring::npos) return argument;
  std::wstring out = L"\"";
  std::size_t backslashes = 0;
  for (const wchar_t c : argument) {
    if (c == L'\\') {
      ++backslashes;
      continue;
    }
    out.append(c == L'"' ? 2 * backslashes + 1 : backslashes, L'\\');
    backslashes = 0;
    out += c;
  }
  out.append(2 * backslashes, L'\\');
  return out + L"\"";
}

// This process's environment with `changes` applied, as the block CreateProcessW takes.
inline std::wstring environment_block(const EnvironmentChanges& changes) {
  std::map<std::wstring, std::wstring> variables;  // Windows sorts the block by name
  const LPWCH strings = GetEnvironmentStringsW();
  for (const wchar_t* p = strings; *p != L'\0'; p += wcslen(p) + 1) {
    const std::wstring entry = p;
    const std::size_t eq = entry.find(L'=', 1);  // "=C:=C:\..." entries start with '='
    if (eq != std::wstring::npos) variables[entry.substr(0, eq)] = entry.substr(eq + 1);
  }
  FreeEnvironmentStringsW(strings);
  for (const auto& [name, value] : changes) {
    if (value.empty()) variables.erase(wide(name));
    else variables[wide(name)] = wide(value);
  }
  std::wstring block;
  for (const auto& [name, value] : variables) block += name + L"=" + value + L'\0';
  return block + L'\0';
}

inline std::filesystem::path this_executable() {
  std::wstring self(MAX_PATH, L'\0');
  self.resize(GetModuleFileNameW(nullptr, self.data(), static_cast<DWORD>(self.size())));
  return self;
}

// Under Wine, now and then a child's start-up ends before its program runs a line, and
// CreateProcessW fails with ERROR_INTERNAL_ERROR (1359): Wine's NtCreateUserProcess reports
// STATUS_INTERNAL_ERROR for a new process that died before its initialisation was done, without an
// exit code. Nothing of the program ran, so it is started again, a few times with a pause; what
// Wine wrote to its output is shown. Any other failure fails at once.
inline constexpr int kStartTries = 3;

inline ChildProcess start_process(const std::string& executable, const std::vector<std::string>& arguments,
                                  const std::filesystem::path& log, const EnvironmentChanges& environment,
                                  bool suspended) {
  // A path such as /work/x names \work\x on the current drive; the program's name keeps its form.
  std::wstring command_line = detail::quoted_argument(path_from_utf8(executable).make_preferred().wstring());
  for (const auto& a : arguments) command_line += L" " + detail::quoted_argument(detail::wide(a));
  std::wstring env = detail::environment_block(environment);
  for (int attempt = 1;; ++attempt) {
    SECURITY_ATTRIBUTES inherit{sizeof(SECURITY_ATTRIBUTES), nullptr, TRUE};
    HANDLE out =
        CreateFileW(log.wstring().c_str(), GENERIC_WRITE, FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE,
                    &inherit, CREATE_ALWAYS, FILE_ATTRIBUTE_NORMAL, nullptr);
    if (out == INVALID_HANDLE_VALUE) throw std::runtime_error("cannot create " + log.string());
    STARTUPINFOW startup{};
    startup.cb = sizeof startup;
    startup.dwFlags = STARTF_USESTDHANDLES;
    startup.hStdInput = GetStdHandle(STD_INPUT_HANDLE);
    startup.hStdOutput = out;
    startup.hStdError = out;
    PROCESS_INFORMATION info{};
    const BOOL started = CreateProcessW(nullptr, command_line.data(), nullptr, nullptr, TRUE,
                                        CREATE_UNICODE_ENVIRONMENT | (suspended ? CREATE_SUSPENDED : 0), env.data(),
                                        nullptr, &startup, &info);
    const DWORD error = GetLastError();
    CloseHandle(out);
    if (started) {
      CloseHandle(info.hThread);
      return ChildProcess(info.hProcess, info.dwProcessId);
    }
    const std::string failure = "cannot start " + executable + " (error " + std::to_string(error) + ")";
    if (error != ERROR_INTERNAL_ERROR) throw std::runtime_error(failure);
    std::ifstream written(log, std::ios::binary);  // what Wine's start-up wrote before it ended
    const std::string said{std::istreambuf_iterator<char>(written), std::istreambuf_iterator<char>()};
    std::fprintf(stderr, "%s, try %d of %d; its output: '%s'\n", failure.c_str(), attempt, kStartTries, said.c_str());
    if (attempt == kStartTries) throw std::runtime_error(failure + " " + std::to_string(kStartTries) + " times");
    Sleep(200 * attempt);
  }
}

}  // namespace detail

inline ChildProcess ChildProcess::start(const std::string& executable, const std::vector<std::string>& arguments,
                                        const std::filesystem::path& log, const EnvironmentChanges& environment) {
  return detail::start_process(executable, arguments, log, environment, false);
}

// This executable, started suspended: it never runs a line.
inline ChildProcess ChildProcess::start_idle() {
  return detail::start_process(detail::this_executable().string(), {}, "NUL", {}, true);
}

inline ChildProcess& ChildProcess::operator=(ChildProcess&& other) noexcept {
  std::swap(id_, other.id_);
  std::swap(exit_code_, other.exit_code_);
  std::swap(process_, other.process_);
  std::swap(killed_, other.killed_);
  return *this;
}

inline ChildProcess::~ChildProcess() {
  if (process_ == nullptr) return;
  if (!exit_code_) kill_and_wait();
  CloseHandle(process_);
}

inline std::optional<int> ChildProcess::exit_code_if_ended() {
  if (!exit_code_ && process_ != nullptr && WaitForSingleObject(process_, 0) == WAIT_OBJECT_0) {
    DWORD code = 0;
    GetExitCodeProcess(process_, &code);
    exit_code_ = killed_ ? -1 : static_cast<int>(code);
  }
  return exit_code_;
}

inline int ChildProcess::wait() {
  if (process_ != nullptr) WaitForSingleObject(process_, INFINITE);
  return exit_code_if_ended().value_or(-1);
}

inline bool ChildProcess::kill_and_wait() {
  if (exit_code_if_ended()) return false;
  killed_ = TerminateProcess(process_, 137) != 0;
  wait();
  return killed_;
}

// The id of a process that this one started and that has ended, with no handle left open to it:
// this test executable listing no test.
inline std::uint64_t ended_process_id() {
  ChildProcess child =
      ChildProcess::start(detail::this_executable().string(), {"--gtest_list_tests", "--gtest_filter=-*"}, "NUL");
  child.wait();
  return child.id();  // its handle is closed when `child` goes
}

#else

inline ChildProcess ChildProcess::start(const std::string& executable, const std::vector<std::string>& arguments,
                                        const std::filesystem::path& log, const EnvironmentChanges& environment) {
  ChildProcess child;
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      ::dup2(fd, 1);
      ::dup2(fd, 2);
    }
    for (const auto& [name, value] : environment) {
      if (value.empty()) ::unsetenv(name.c_str());
      else ::setenv(name.c_str(), value.c_str(), 1);
    }
    std::vector<std::string> copy = arguments;
    copy.insert(copy.begin(), executable);
    std::vector<char*> argv;
    for (auto& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    ::execv(executable.c_str(), argv.data());
    ::_exit(127);
  }
  child.id_ = pid > 0 ? static_cast<std::uint64_t>(pid) : 0;
  if (pid < 0) child.exit_code_ = 127;
  return child;
}

// A fork that waits for its signal.
inline ChildProcess ChildProcess::start_idle() {
  ChildProcess child;
  const pid_t pid = ::fork();
  if (pid == 0) {
    for (;;) ::pause();
  }
  child.id_ = pid > 0 ? static_cast<std::uint64_t>(pid) : 0;
  if (pid < 0) child.exit_code_ = 127;
  return child;
}

inline ChildProcess& ChildProcess::operator=(ChildProcess&& other) noexcept {
  std::swap(id_, other.id_);
  std::swap(exit_code_, other.exit_code_);
  return *this;
}

inline ChildProcess::~ChildProcess() {
  if (id_ != 0 && !exit_code_) kill_and_wait();
}

namespace detail {
inline int exit_code_of(int status) { return WIFEXITED(status) ? WEXITSTATUS(status) : -1; }
}  // namespace detail

inline std::optional<int> ChildProcess::exit_code_if_ended() {
  int status = 0;
  if (!exit_code_ && id_ != 0 && ::waitpid(static_cast<pid_t>(id_), &status, WNOHANG) == static_cast<pid_t>(id_))
    exit_code_ = detail::exit_code_of(status);
  return exit_code_;
}

inline int ChildProcess::wait() {
  int status = 0;
  if (!exit_code_ && id_ != 0 && ::waitpid(static_cast<pid_t>(id_), &status, 0) == static_cast<pid_t>(id_))
    exit_code_ = detail::exit_code_of(status);
  return exit_code_.value_or(-1);
}

inline bool ChildProcess::kill_and_wait() {
  if (exit_code_ || id_ == 0) return false;
  ::kill(static_cast<pid_t>(id_), SIGKILL);
  int status = 0;
  if (::waitpid(static_cast<pid_t>(id_), &status, 0) != static_cast<pid_t>(id_)) return false;
  exit_code_ = detail::exit_code_of(status);
  return WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL;
}

// The id of a process that this one started and that has ended, reaped: a fork that exits at once.
inline std::uint64_t ended_process_id() {
  const pid_t dead = ::fork();
  if (dead == 0) ::_exit(0);
  if (dead > 0) ::waitpid(dead, nullptr, 0);
  return dead > 0 ? static_cast<std::uint64_t>(dead) : 0;
}

#endif

}  // namespace vsgl::test
