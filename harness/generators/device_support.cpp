#include "harness/generators/device_support.hpp"

#include <algorithm>

#include "harness/core/error.hpp"
#include "harness/generators/fis/fis_generator.hpp"
#include "harness/generators/generator_descriptor.hpp"
#include "harness/generators/generator_registry.hpp"
#include "harness/vk/compute_pipeline.hpp"
#include "harness/vk/shader_registry.hpp"
#include "harness/vk/spirv_reflection.hpp"
#include "kernels/include/interface/kmeans.h"

namespace vsgl {

PipelineNeeds kernel_needs_bound(const std::string& kernel) {
  // A kernel whose y size follows specialization constant 1 is a 2D image pass (16 x 16);
  // otherwise constant 0 is its 1D size, at most the widest k-means group.
  const auto probe = reflect_kernel(find_shader(kernel), {{1, 2}});
  const bool two_d = probe.workgroup_size[1] == 2;
  ComputePipelineDesc desc;
  desc.shader = kernel;
  if (two_d)
    desc.constants = {{0, gpu::kKmeansImageGroupSize}, {1, gpu::kKmeansImageGroupSize}};
  else
    desc.constants = {{0, std::max(gpu::kKmeansWideGroupSize, gpu::kKmeansRadixGroupSize)}};
  return pipeline_needs(desc);
}

std::vector<PipelineNeeds> generator_pipeline_needs(const std::string& generator) {
  std::vector<PipelineNeeds> out;
  if (generator_descriptor(generator).family == GeneratorFamily::kFis) {
    for (MipStrategy m : {MipStrategy::kSinglePass, MipStrategy::kBlit, MipStrategy::kPerLevel})
      for (const auto& d : fis_pipelines(PyramidPath::kTexture, m)) out.push_back(pipeline_needs(d));
    for (const auto& d : fis_pipelines(PyramidPath::kBuffer, MipStrategy::kPerLevel)) out.push_back(pipeline_needs(d));
  } else {
    for (const auto& k : generator_sources(generator).kernels)
      out.push_back(kernel_needs_bound(k.substr(k.find_last_of('/') + 1)));
  }
  // One entry per kernel.
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  out.erase(std::unique(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.name == b.name; }),
            out.end());
  return out;
}

DeviceSupport device_support(const DeviceInfo& info) {
  DeviceSupport out;
  if (!info.usable()) return out;
  for (MipStrategy m : {MipStrategy::kSinglePass, MipStrategy::kBlit, MipStrategy::kPerLevel}) {
    const std::string why = fis_unfit_reason(info, PyramidPath::kTexture, m);
    out.mipmapping[mip_strategy_name(m)] = {why.empty(), why};
  }
  for (const auto& g : generator_names()) {
    GeneratorSupport s{{true, ""}, {}, {}, {}, {}};
    if (generator_descriptor(g).family == GeneratorFamily::kFis) {
      try {
        std::string path_reason, mip_reason;
        const PyramidPath path = effective_pyramid_path(info, PyramidPath::kTexture, &path_reason);
        s.pyramid = pyramid_path_name(path);
        if (!path_reason.empty()) s.pyramid_fallback_reason = path_reason;
        if (path == PyramidPath::kTexture) {
          s.mipmapping = mip_strategy_name(effective_mip_strategy(info, std::nullopt, &mip_reason));
          if (!mip_reason.empty()) s.mipmapping_fallback_reason = mip_reason;
        }
      } catch (const DeviceError& e) {
        s.verdict = {false, e.what()};
      }
    } else {
      for (const auto& n : generator_pipeline_needs(g)) {
        const std::string why = does_not_fit_reason(info.limits, n);
        if (!why.empty()) {
          s.verdict = {false, why};
          break;
        }
      }
    }
    out.generators[g] = s;
  }
  return out;
}

}  // namespace vsgl
