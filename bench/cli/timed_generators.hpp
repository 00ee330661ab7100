#pragma once
// Which generators a timing command (`tables`, `sweep`) runs, and with what config: the
// --generators, --camera-vsgls, --light-vsgls and generator options as given, and on a CPU device
// (lavapipe) the paper's four by default: there a k-means replay of both views takes seconds, so
// the full protocol (2 warm-ups + 10 rounds) of all six would take ~20 minutes; the segmented-sum
// extras are one --generators away.
#include <cstdio>
#include <string>
#include <vector>

#include "bench/cli/generator_options.hpp"
#include "harness/generators/generator_registry.hpp"
#include "harness/report/tables_run.hpp"
#include "harness/vk/device_info.hpp"

namespace vsgl::cli {

// The generators and config as given; every registered generator when none is named.
inline void apply_generator_options(const GeneratorOptions& gen, TablesOptions& t) {
  if (!gen.generators.empty()) t.generators = gen.generators;
  t.camera_vsgls = gen.camera_vsgls;
  t.light_vsgls = gen.light_vsgls;
  t.generator = gen.config;
}

// The same, narrowed to the paper's four on a CPU device when none is named (`tables`, `sweep`;
// `vsgl-gbench` times what it is given: a dashboard asks for its cases by name).
inline void apply_timed_generators(const GeneratorOptions& gen, const DeviceInfo& info, TablesOptions& t) {
  apply_generator_options(gen, t);
  if (gen.generators.empty() && info.type == VK_PHYSICAL_DEVICE_TYPE_CPU) {
    std::vector<std::string> paper;
    for (const auto& g : t.generators)
      if (generator_in_paper(g)) paper.push_back(g);
    t.generators = paper;
    std::fprintf(stderr, "CPU device: timing the paper's four generators (add the extras with --generators)\n");
  }
}

}  // namespace vsgl::cli
