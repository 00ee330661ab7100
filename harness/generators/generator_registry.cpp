#include "harness/generators/generator_registry.hpp"

#include "harness/core/error.hpp"
#include "harness/generators/fis/fis_descriptor.hpp"
#include "harness/generators/kmeans/kmeans_descriptor.hpp"

namespace vsgl {

const std::vector<GeneratorDescriptor>& generator_descriptors() {
  // One line per generator, in table order: the paper's four, then the extras.
  static const std::vector<GeneratorDescriptor> table = {
      fis_descriptor(FisVariant::kTok15),
      fis_descriptor(FisVariant::kModified),
      kmeans_descriptor(KmeansSpace::k2d, /*segmented_sum=*/false),
      kmeans_descriptor(KmeansSpace::k3d, /*segmented_sum=*/false),
      kmeans_descriptor(KmeansSpace::k2d, /*segmented_sum=*/true),
      kmeans_descriptor(KmeansSpace::k3d, /*segmented_sum=*/true),
  };
  return table;
}

const GeneratorDescriptor& generator_descriptor(std::string_view name) {
  std::string known;
  for (const auto& d : generator_descriptors()) {
    if (d.name == name) return d;
    known += (known.empty() ? "" : ", ") + d.name;
  }
  throw InputError("unknown generator '" + std::string(name) + "' (known: " + known + ")");
}

std::vector<std::string> generator_names() {
  std::vector<std::string> out;
  for (const auto& d : generator_descriptors()) out.push_back(d.name);
  return out;
}

std::vector<std::string> generator_names(GeneratorFamily family) {
  std::vector<std::string> out;
  for (const auto& d : generator_descriptors())
    if (d.family == family) out.push_back(d.name);
  return out;
}

std::vector<std::string> paper_generator_names() {
  std::vector<std::string> out;
  for (const auto& d : generator_descriptors())
    if (d.in_paper) out.push_back(d.name);
  return out;
}

bool generator_in_paper(const std::string& name) { return generator_descriptor(name).in_paper; }

std::unique_ptr<VsglGenerator> make_generator(const std::string& name, Device& device, const DeviceView& view,
                                              const GeneratorConfig& config) {
  return generator_descriptor(name).make(device, view, config);
}

const SourceSet& generator_sources(const std::string& name) { return generator_descriptor(name).sources; }

SourceSet generator_sources(const std::string& name, const GeneratorConfig& config) {
  const GeneratorDescriptor& d = generator_descriptor(name);
  return d.sources_for != nullptr ? d.sources_for(config) : d.sources;
}

}  // namespace vsgl
