// The portability audit (DESIGN.md §9): every kernel a generator dispatches, its resource needs
// from SPIR-V reflection (descriptors by type, push-constant bytes, shared memory, work-group
// size), against the Vulkan 1.2 required limits and the desktop baseline profile
// VP_LUNARG_desktop_baseline_2023 (harness/vk/portability_baselines.hpp). A kernel over the
// desktop baseline fails the audit unless its generator falls back to kernels that fit and that
// fallback is tested (tests/test_device_limits.cpp). The table it prints is docs/portability.md's,
// which must match it line for line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include "harness/generators/device_support.hpp"
#include "harness/generators/generator_registry.hpp"
#include "harness/vk/portability_baselines.hpp"

namespace vsgl {
namespace {

namespace fs = std::filesystem;

// Kernels with a tested fallback: the single pass falls back to blit or per-level, per-level to
// blit or the buffer path (DeviceLimits.TooFewStorageImagesMakeTheSinglePassFallBack...,
// DeviceLimits.NoStrategyFitsSoTheTexturePathFallsBackToTheBuffer, DeviceLimitsTest.*).
const std::set<std::string> kWithTestedFallback = {"fis_mip_single_pass.comp", "fis_mip_single_pass_tail.comp",
                                                   "fis_mip_level_texture.comp"};

std::string fits(const DeviceLimits& l, const PipelineNeeds& n) {
  const auto s = shortfalls(l, n);
  if (s.empty()) return "yes";
  std::string out = "no:";
  for (const auto& x : s) out += " " + x.limit + " " + std::to_string(x.needed) + ">" + std::to_string(x.value);
  return out;
}

TEST(PortabilityAudit, EveryKernelFitsTheDesktopBaselineOrHasATestedFallback) {
  std::map<std::string, std::pair<PipelineNeeds, std::set<std::string>>> kernels;
  for (const auto& g : generator_names())
    for (const auto& n : generator_pipeline_needs(g)) {
      kernels[n.name].first = n;
      kernels[n.name].second.insert(g);
    }
  ASSERT_FALSE(kernels.empty());
  std::ostringstream table;
  table << "| kernel | generators | storage images | sampled images | samplers | storage buffers | uniform buffers "
           "| push constants (B) | shared memory (B) | work group | Vulkan 1.2 minimum | "
        << kDesktopBaselineName << " |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& [name, entry] : kernels) {
    const PipelineNeeds& n = entry.first;
    std::string gens;
    for (const auto& g : entry.second) gens += (gens.empty() ? "" : ", ") + g;
    const std::string desktop = fits(desktop_baseline_2023_limits(), n);
    table << "| `" << name << "` | " << gens << " | " << n.storage_images << " | " << n.sampled_images << " | "
          << n.samplers << " | " << n.storage_buffers << " | " << n.uniform_buffers << " | " << n.push_constant_bytes
          << " | " << n.shared_memory_bytes << " | " << n.workgroup_size[0] << "x" << n.workgroup_size[1] << "x"
          << n.workgroup_size[2] << " | " << fits(vulkan12_required_limits(), n) << " | " << desktop << " |\n";
    if (desktop != "yes" && !kWithTestedFallback.count(name))
      ADD_FAILURE() << name << " (" << gens << ") needs more than " << kDesktopBaselineName
                    << " and has no tested fallback: " << does_not_fit_reason(desktop_baseline_2023_limits(), n);
  }
  std::cout << table.str();

  // docs/portability.md holds this table between its markers, as printed here.
  const fs::path doc = fs::path(VSGL_SOURCE_DIR) / "docs" / "portability.md";
  std::ifstream in(doc);
  ASSERT_TRUE(in) << doc;
  std::string documented;
  bool inside = false;
  for (std::string line; std::getline(in, line);) {
    if (line == "<!-- portability:end -->") inside = false;
    if (inside) documented += line + "\n";
    if (line == "<!-- portability:begin -->") inside = true;
  }
  EXPECT_EQ(documented, table.str()) << doc << " between <!-- portability:begin --> and <!-- portability:end --> "
                                     << "is not this test's table; replace it with the table printed above";
}

}  // namespace
}  // namespace vsgl
