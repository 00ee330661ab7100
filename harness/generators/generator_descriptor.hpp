#pragma once
// One generator, described once: its name, its labels, whether it is a column of the paper's
// tables, its family, how to build it, and which sources make it up (Table 3's analog). The
// registry (generator_registry.hpp), the table reports and their claims, the dashboard, `shade`,
// `quality` and `vsgl-gbench` read these descriptors and nothing else.
#include <memory>
#include <string>
#include <vector>

#include "harness/core/source_lines.hpp"
#include "harness/math/fis_params.hpp"

namespace vsgl {

class Device;
class VsglGenerator;
struct DeviceView;

// What a generator needs besides the view; each generator reads the fields that concern it.
struct GeneratorConfig {
  uint32_t vsgl_count = 0;            // N (camera view 2048, light view 1024 in the paper)
  float K = 1.0f;                     // FIS kernel-size parameter (DESIGN.md §6.1)
  uint32_t bisection_iterations = 12; // fis_modified's level search (DESIGN.md §6.1)
  uint32_t kmeans_iterations = 4;     // Lloyd iterations before the final assignment (DESIGN.md §6.2)
  uint32_t offset_bits = 0;           // Fibonacci lattice offset (DESIGN.md §5)
  PyramidPath pyramid = PyramidPath::kTexture;  // FIS pyramid: sampled images or storage buffer (DESIGN.md §6.1a)
  std::optional<MipStrategy> mipmapping;        // FIS texture path; unset = the device kind's default
};

// FIS generators filter a mip pyramid at a level per kernel (DESIGN.md §6.1), so their VSGLs have
// kernel footprints; k-means generators cluster texels (DESIGN.md §6.2).
enum class GeneratorFamily { kFis, kKmeans };

using GeneratorFactory = std::unique_ptr<VsglGenerator> (*)(Device& device, const DeviceView& view,
                                                            const GeneratorConfig& config);

struct GeneratorDescriptor {
  std::string name;         // stable id in every output (core/generator_ids.hpp)
  std::string label;        // the paper's column heading: "Ours (modified FIS)"
  std::string short_label;  // fits under a dashboard bar: "modified"
  bool in_paper = false;    // a column of the paper's Tables 1-3
  GeneratorFamily family = GeneratorFamily::kFis;
  std::vector<std::string> phases;  // in execution order; equal to VsglGenerator::phases() (tested)
  GeneratorFactory make = nullptr;  // throws InputError for N = 0, N > samplable texels, K <= 0
  // The host class and the compute kernels it dispatches (one pipeline each), and which marked
  // regions of those files its config counts (source_lines.hpp); the GLSL they #include is added
  // by count_generator_lines(). Shared infrastructure counts for no generator.
  SourceSet sources;
  // The sources the generator is built from under a given config (FIS: its pyramid path and
  // mipmapping strategy, DESIGN.md §6.1a, §10); null: always `sources`. `sources` is the default config's.
  SourceSet (*sources_for)(const GeneratorConfig& config) = nullptr;
};

}  // namespace vsgl
