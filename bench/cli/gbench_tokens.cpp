#include "bench/cli/gbench_tokens.hpp"

#include "harness/core/error.hpp"

namespace vsgl::cli {

std::vector<std::string> gbench_tokens(int argc, char** argv) {
  std::vector<std::string> out;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a.rfind("--vsgl_", 0) != 0) throw UsageError("unknown argument '" + a + "' (this tool's own options start with --vsgl_)");
    std::string name = a.substr(7), value;
    if (const auto eq = name.find('='); eq != std::string::npos) {
      value = name.substr(eq);
      name.resize(eq);
    }
    for (char& c : name)
      if (c == '_') c = '-';
    out.push_back("--" + name + value);
  }
  return out;
}

}  // namespace vsgl::cli
