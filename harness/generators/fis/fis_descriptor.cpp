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

// Table 3 counts what the chosen path compiles and runs (DESIGN.md §10): one kernel per pipeline
// it binds, and of the shared files the regions of its pyramid path, mip strategy and variant.
template <FisVariant variant>
SourceSet fis_sources(const GeneratorConfig& config) {
  const bool buffer = config.pyramid == PyramidPath::kBuffer;
  const MipStrategy mip = config.mipmapping.value_or(MipStrategy::kSinglePass);
  SourceSet s{{"harness/generators/fis/fis_generator.hpp", "harness/generators/fis/fis_generator.cpp"},
              {},
              {{"buffer", buffer},
               {"texture", !buffer},
               {"single_pass", !buffer && mip == MipStrategy::kSinglePass},
               {"per_level", !buffer && mip == MipStrategy::kPerLevel},
               {"blit", !buffer && mip == MipStrategy::kBlit},
               {"tok15", variant == FisVariant::kTok15},
               {"modified", variant == FisVariant::kModified},
               {"verify", false},
               {"report", false}}};
  if (buffer) {
    s.kernels = {"kernels/fis_additional.comp", "kernels/fis_mip_level.comp", "kernels/fis_filtered_sampling.comp"};
    return s;
  }
  s.kernels.push_back("kernels/fis_additional_texture.comp");
  switch (mip) {
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
  // Both variants are one source with a specialization constant; the regions `tok15` and
  // `modified` (choose_level()/estimate_power() of kernels/include/fis_filtered_sampling.glsl) are
  // the lines each specialization keeps, so their counts differ as the paper's do.
  return GeneratorDescriptor{
      .name = fis_variant_name(variant),
      .label = tok15 ? "[Tok15]" : "Ours (modified FIS)",
      .short_label = tok15 ? "Tok15" : "modified",
      .in_paper = true,
      .family = GeneratorFamily::kFis,
      .phases = {"additional", "mipmapping", "filtered_sampling"},
      .make = tok15 ? &make_fis<FisVariant::kTok15> : &make_fis<FisVariant::kModified>,
      .sources = tok15 ? fis_sources<FisVariant::kTok15>(GeneratorConfig{})
                       : fis_sources<FisVariant::kModified>(GeneratorConfig{}),
      .sources_for = tok15 ? &fis_sources<FisVariant::kTok15> : &fis_sources<FisVariant::kModified>,
  };
}

}  // namespace vsgl
