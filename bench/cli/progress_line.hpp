#pragma once
// The progress of the timed commands (tables, sweep, frame) on stderr: one line rewritten in place
// while a person watches a terminal, ended before any message line, silent otherwise; and their
// closing output, the markdown on stdout and the files written on stderr.
#include <filesystem>
#include <string>
#include <vector>

#include "harness/timing/timing_runner.hpp"

namespace vsgl::cli {

class ProgressLine {
 public:
  explicit ProgressLine(bool terminal) : terminal_(terminal) {}
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;
  ~ProgressLine() { close(); }

  // "  <where>: warm-up d/t", then "  <where>: repetition r (min m), worst IQR/median x (target y),
  // e s / c s"; nothing unless on a terminal.
  void show(const std::string& where, const TimingProgress& p);
  // A line of its own, after ending the progress line.
  void message(const std::string& text);
  // Ends the progress line, if one is open.
  void close();

 private:
  bool terminal_ = false;
  bool open_ = false;
};

// Each markdown document on stdout, then "wrote PATH" for each file on stderr.
void print_outcome(const std::vector<std::string>& markdown, const std::vector<std::filesystem::path>& written);

}  // namespace vsgl::cli
