#pragma once
// The visibility options `shade` and `quality` share (DESIGN.md §8.1, §8a): --visibility
// none|ism|exact and the imperfect shadow maps' --ism-* settings, which only --visibility ism
// takes.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "harness/quality/shading_visibility.hpp"

namespace vsgl::cli {

struct VisibilityOptions {
  std::string visibility = "ism";  // the paper's
  IsmSettings ism;
  std::vector<const CLI::Option*> ism_options;  // refused unless --visibility ism
};

// --visibility (described by `what`: what the visibility applies to) and the --ism-* options.
void add_visibility_options(CLI::App& app, VisibilityOptions& options, const std::string& what);

// The settings the options give; UsageError for an --ism-* option given without --visibility ism.
ShadingVisibilitySettings visibility_settings(const VisibilityOptions& options);

}  // namespace vsgl::cli
