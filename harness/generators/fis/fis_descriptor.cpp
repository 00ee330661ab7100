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
  p.pyramid = config.pyramid;
  p.mipmapping = config.mipmapping;
  return std::make_unique<FisGenerator>(device, view, variant, p);
}

// Table 3 counts what the chosen path dispatches: one kernel per pipeline it binds.
SourceSet fis_sources(const GeneratorConfig& config) {
  SourceSet s{{"harness/generators/fis/fis_generator.hpp", "harness/generators/fis/fis_generator.cpp"}, {}};
  if (config.pyramid == PyramidPath::kBuffer) {
    s.kernels = {"kernels/fis_additional.comp", "kernels/fis_mip_level.comp", "kernels/fis_filtered_sampling.comp"};
    return s;
  }
  s.kernels.push_back("kernels/fis_additional_texture.comp");
  switch (config.mipmapping.value_or(MipStrategy::kSinglePass)) {
    case MipStrategy::kSinglePass:
      s.kernels.push_back("kernels/fis_mip_single_pass.comp");
      s.kernels.push_back("kernels/fis_mip_single_pass_tail.comp");
      break;
    case MipStrategy::kPerLevel: s.kernels.push_back("kernels/fis_mip_level_texture.comp"); break;
    case MipStrategy::kBlit: break;  // vkCmdBlitImage: no kernel of ours
  }
  s.kernels.push_back("kernels/fis_filtered_sampling_texture.comp");
  return s;
}

}  // namespace

GeneratorDescriptor fis_descriptor(FisVariant variant) {
  const bool tok15 = variant == FisVariant::kTok15;
  // Both variants are one source with a specialization constant, so they count the same lines
  // (the paper's ~10-line difference is choose_level()/estimate_power() of
  // kernels/include/fis_filtered_sampling.glsl, counted in both).
  return GeneratorDescriptor{
      .name = fis_variant_name(variant),
      .label = tok15 ? "[Tok15]" : "Ours (modified FIS)",
      .short_label = tok15 ? "Tok15" : "modified",
      .in_paper = true,
      .family = GeneratorFamily::kFis,
      .phases = {"additional", "mipmapping", "filtered_sampling"},
      .make = tok15 ? &make_fis<FisVariant::kTok15> : &make_fis<FisVariant::kModified>,
      .sources = fis_sources(GeneratorConfig{}),
      .sources_for = &fis_sources,
  };
}

}  // namespace vsgl
