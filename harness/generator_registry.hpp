#pragma once
// Every VSGL generator by name, for the timing harness, `tables` and `vsgl-gbench`: how to build
// one on an uploaded view, and which source files make it up (Table 3's lines of code).
#include <memory>
#include <string>
#include <vector>

#include "harness/vsgl_generator.hpp"

namespace vsgl {

class Device;
struct DeviceView;

// What a generator needs besides the view; each generator reads the fields that concern it.
struct GeneratorConfig {
  uint32_t vsgl_count = 0;            // N (camera view 2048, light view 1024 in the paper)
  float K = 1.0f;                     // FIS kernel-size parameter (SPEC §6.1)
  uint32_t bisection_iterations = 12; // fis_modified's level search (SPEC §6.1)
  uint32_t kmeans_iterations = 4;     // Lloyd iterations before the final assignment (SPEC §6.2)
  uint32_t offset_bits = 0;           // Fibonacci lattice offset (SPEC §5)
};

// The source files of one generator, relative to the source tree (see generator_sources()).
struct GeneratorSources {
  std::vector<std::string> host;     // C++ files
  std::vector<std::string> kernels;  // kernels/*.comp it dispatches (one pipeline each)
};

// All generator names, the paper's four first, then the extras (the k-means segmented sums).
std::vector<std::string> generator_names();
// True for the generators that are columns of the paper's tables.
bool generator_in_paper(const std::string& name);

// Throws InputError naming the known generators when `name` is not one of them, and whatever the
// generator's constructor throws (N = 0, N larger than the view's samplable texels, K <= 0).
std::unique_ptr<VsglGenerator> make_generator(const std::string& name, Device& device, const DeviceView& view,
                                              const GeneratorConfig& config);

// Which files belong to which generator (Table 3 analog). Definition: the generator's host
// class (harness/<family>_generator.hpp/.cpp) and the compute kernels it dispatches; the
// GLSL files those kernels #include are added by count_generator_lines() (transitively).
// Shared infrastructure (Vulkan wrappers, buffers, the capture, the timing harness) is not
// counted for any generator. Both FIS variants are one source with a specialization
// constant, so they count the same lines (the paper's 10-line difference is the two
// `FIS_VARIANT == 0u` branches of kernels/fis_filtered_sampling.comp, counted in both).
// Throws InputError for an unknown name.
GeneratorSources generator_sources(const std::string& name);

}  // namespace vsgl
