#pragma once
// A seam of `vsgl-bench tables` through which a build adds options that change what is timed. The
// test build of vsgl-bench (tests/hooks/, docs/testing.md) adds `--debug-slow` through it; the
// shipped program adds nothing, so it has no such option.
#include <functional>

#include "harness/report/tables_run.hpp"

namespace CLI {
class App;
}  // namespace CLI

namespace vsgl::cli {

struct TablesExtension {
  // Declares its options on the `tables` command (after the command's own).
  std::function<void(CLI::App& tables)> add_options;
  // Once the whole command line is parsed and the options are set, just before the run. A change
  // to what is timed goes through TablesOptions::wrap_generator and altered_generators, so the run
  // records it.
  std::function<void(TablesOptions& options)> apply;
};

}  // namespace vsgl::cli
