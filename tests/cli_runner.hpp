#pragma once
// Runs the vsgl-bench executable as a user would and captures its exit code and output.
#include <array>
#include <cstdio>
#include <string>

#ifdef _WIN32
#include <sstream>
#include <vector>

#include "child_process.hpp"
#include "test_support.hpp"
#else
#include <sys/wait.h>
#endif

namespace vsgl::test {

struct CliResult {
  int exit_code;
  std::string output;  // stdout and stderr together
};

#ifdef _WIN32

// No POSIX shell here: the words of `arguments` (the tests put no quotes or redirections in them)
// become the arguments, and `environment` the changes to this process's environment.
inline CliResult run_program(const std::string& executable, const std::string& arguments,
                             const std::string& environment = "") {
  std::istringstream words(arguments), assignments(environment);
  std::vector<std::string> args;
  for (std::string word; words >> word;) args.push_back(word);
  EnvironmentChanges changes;
  for (std::string assignment; assignments >> assignment;) {
    const std::size_t eq = assignment.find('=');
    changes.emplace_back(assignment.substr(0, eq), eq == std::string::npos ? "" : assignment.substr(eq + 1));
  }
  const TempDir dir("cli");
  ChildProcess child = ChildProcess::start(executable, args, dir / "output.txt", changes);
  const int code = child.wait();
  std::string output;  // text as a POSIX pipe gives it: "\r\n" (the C runtime's text mode) is "\n"
  for (const char c : read_text(dir / "output.txt"))
    if (c != '\r') output += c;
  return CliResult{code, output};
}

#else

// `environment`: "NAME=VALUE ..." put before the command (a shell assignment).
inline CliResult run_program(const std::string& executable, const std::string& arguments,
                             const std::string& environment = "") {
  const std::string command = (environment.empty() ? "" : environment + " ") + executable + " " + arguments + " 2>&1";
  CliResult result{-1, {}};
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer{};
  while (fgets(buffer.data(), static_cast<int>(buffer.size()), pipe) != nullptr) result.output += buffer.data();
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

#endif

inline CliResult run_cli(const std::string& arguments) { return run_program(VSGL_BENCH_EXE, arguments); }

// Vulkan's loader finds no driver at all: any command that reaches the device exits 4, so one
// that exits 2 here was refused before Vulkan was touched.
inline constexpr const char* kNoVulkanDriver = "VK_ICD_FILENAMES=/nonexistent/vsgl_icd.json VK_DRIVER_FILES=/nonexistent/vsgl_icd.json";

inline CliResult run_cli_without_vulkan(const std::string& arguments) {
  return run_program(VSGL_BENCH_EXE, arguments, kNoVulkanDriver);
}

}  // namespace vsgl::test
