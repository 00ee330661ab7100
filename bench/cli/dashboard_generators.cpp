#include "bench/cli/dashboard_generators.hpp"

#include "harness/generators/generator_registry.hpp"

namespace vsgl::cli {

std::vector<DashboardGenerator> dashboard_generators() {
  std::vector<DashboardGenerator> out;
  for (const auto& d : generator_descriptors()) out.push_back({d.name, d.short_label, d.in_paper, d.phases});
  return out;
}

}  // namespace vsgl::cli
