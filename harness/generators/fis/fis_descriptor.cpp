#include "harness/generators/fis/fis_descriptor.hpp"

#include "harness/generators/fis/fis_generator.hpp"

namespace vsgl {
namespace {

template <FisVariant variant>
std::unique_ptr<VsglGenerator> make_fis(Device& device, const DeviceView& view, const GeneratorConfig& config) {
  FisParams p;
  p.vsgl_count = config.vsgl_count;
  p.K = config.K;
  p.bisection_iterations = config.bisection_iterations;
  p.offset_bits = config.offset_bits;
  return std::make_unique<FisGenerator>(device, view, variant, p);
}

}  // namespace

GeneratorDescriptor fis_descriptor(FisVariant variant) {
  const bool tok15 = variant == FisVariant::kTok15;
  // Both variants are one source with a specialization constant, so they count the same lines
  // (the paper's ~10-line difference is choose_level()/estimate_power() of
  // kernels/fis_filtered_sampling.comp, counted in both).
  return GeneratorDescriptor{
      .name = fis_variant_name(variant),
      .label = tok15 ? "[Tok15]" : "Ours (modified FIS)",
      .short_label = tok15 ? "Tok15" : "modified",
      .in_paper = true,
      .family = GeneratorFamily::kFis,
      .phases = {"additional", "mipmapping", "filtered_sampling"},
      .make = tok15 ? &make_fis<FisVariant::kTok15> : &make_fis<FisVariant::kModified>,
      .sources = {{"harness/generators/fis/fis_generator.hpp", "harness/generators/fis/fis_generator.cpp"},
                  {"kernels/fis_additional.comp", "kernels/fis_mip_level.comp", "kernels/fis_filtered_sampling.comp"}},
  };
}

}  // namespace vsgl
