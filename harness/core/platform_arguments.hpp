#pragma once
// The command line in UTF-8 (DESIGN.md §13). The programs treat every string, file names
// included, as UTF-8 (std::filesystem::path does so on Windows too). Windows passes main() its
// arguments in the ANSI code page, which cannot hold every file name; there they are taken from
// the wide (UTF-16) command line instead. Elsewhere argv is used as it is.
#include <string>
#include <vector>

namespace vsgl {

class Utf8Arguments {
 public:
  Utf8Arguments(int argc, char** argv);
  int argc() const { return static_cast<int>(pointers_.size()) - 1; }
  char** argv() { return pointers_.data(); }

 private:
  std::vector<std::string> arguments_;
  std::vector<char*> pointers_;  // into arguments_ (or the original argv), then nullptr
};

}  // namespace vsgl
