#pragma once
// Runs the vsgl-bench executable as a user would and captures its exit code and output.
#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace vsgl::test {

struct CliResult {
  int exit_code;
  std::string output;  // stdout and stderr together
};

inline CliResult run_cli(const std::string& arguments) {
  const std::string command = std::string(VSGL_BENCH_EXE) + " " + arguments + " 2>&1";
  CliResult result{-1, {}};
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer{};
  while (fgets(buffer.data(), static_cast<int>(buffer.size()), pipe) != nullptr) result.output += buffer.data();
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

}  // namespace vsgl::test
