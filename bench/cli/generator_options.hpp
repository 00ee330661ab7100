#pragma once
// The generator options every timing front end reads the same way (`tables`, `vsgl-gbench`):
// --generators, --camera-vsgls, --light-vsgls, --K, --iterations, --kmeans-iterations,
// --pyramid texture|buffer, --mipmapping single-pass|blit|per-level.
#include <cstdint>
#include <string>
#include <vector>

#include "bench/cli/args.hpp"
#include "harness/generators/generator_descriptor.hpp"

namespace vsgl::cli {

struct GeneratorOptions {
  std::vector<std::string> generators;  // empty: the caller's default set
  uint32_t camera_vsgls = 2048;         // N on the G-buffer (the paper's)
  uint32_t light_vsgls = 1024;          // N on the RSM (the paper's)
  GeneratorConfig config;               // K and iterations; vsgl_count is set per view
};

// Throws UsageError for a malformed value (generator names are checked by the caller's run).
GeneratorOptions read_generator_options(Args& args);

// --pyramid texture|buffer (default texture, DESIGN.md §6.1a) and --mipmapping STRATEGY (default: the
// device kind's, left unset here) into `config`; `shade`, `quality` and `verify` read them too.
// Throws UsageError naming the accepted values.
void read_pyramid_options(Args& args, GeneratorConfig& config);
// The same for one value of --pyramid (e.g. one item of verify's list).
PyramidPath parse_pyramid_option(const std::string& value);

}  // namespace vsgl::cli
