#pragma once
// Every VSGL generator, in one table of descriptors (generator_descriptor.hpp): the paper's four
// first, then the extras. Adding a generator = its folder under generators/ + one line in
// generator_registry.cpp.
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "harness/core/generator_ids.hpp"  // kFisTok15 ..., the ids the descriptors carry
#include "harness/generators/generator_descriptor.hpp"
#include "harness/generators/vsgl_generator.hpp"

namespace vsgl {

const std::vector<GeneratorDescriptor>& generator_descriptors();

// Throws InputError naming the known generators when `name` is none of them.
const GeneratorDescriptor& generator_descriptor(std::string_view name);

// All generator names, in table order.
std::vector<std::string> generator_names();
// The names of one family, or of the paper's columns.
std::vector<std::string> generator_names(GeneratorFamily family);
std::vector<std::string> paper_generator_names();

bool generator_in_paper(const std::string& name);

// Builds the generator on an uploaded view; throws InputError for an unknown name, and whatever
// the generator's constructor throws (N = 0, N larger than the view's samplable texels, K <= 0).
std::unique_ptr<VsglGenerator> make_generator(const std::string& name, Device& device, const DeviceView& view,
                                              const GeneratorConfig& config);

// Wraps a built generator (same name, phases and output), e.g. to add work to it in a test.
using GeneratorWrapper = std::function<std::unique_ptr<VsglGenerator>(Device& device, std::unique_ptr<VsglGenerator> generator)>;

// Which files belong to which generator (Table 3 analog); throws InputError for an unknown name.
const SourceSet& generator_sources(const std::string& name);
// The same under `config` (whose FIS mipmapping strategy is resolved; see resolve_fis_config).
SourceSet generator_sources(const std::string& name, const GeneratorConfig& config);

}  // namespace vsgl
