#pragma once
// The FIS generators on the GPU (SPEC §6.1): `fis_tok15` [Tok15] and `fis_modified` (the paper's
// "Ours"). Phases, as in Table 1: additional -> mipmapping -> filtered_sampling. The variants
// share every pass; the kernel fis_filtered_sampling.comp differs only in choose_level() and
// estimate_power(), selected by a specialization constant.
#include <memory>

#include "harness/vk/buffer.hpp"
#include "harness/vk/compute_pipeline.hpp"
#include "harness/math/fis_params.hpp"
#include "harness/generators/vsgl_generator.hpp"

namespace vsgl {

class Device;
struct DeviceView;

class FisGenerator : public VsglGenerator {
 public:
  // Throws InputError for N = 0, N larger than the view's samplable texels, or K <= 0.
  FisGenerator(Device& device, const DeviceView& view, FisVariant variant, const FisParams& params);

  std::string name() const override { return fis_variant_name(variant_); }
  std::vector<std::string> phases() const override { return {"additional", "mipmapping", "filtered_sampling"}; }
  void record(CommandStream& stream, const std::function<void(VkCommandBuffer)>& boundary) override;
  const Buffer& vsgls() const override { return vsgls_; }
  uint32_t vsgl_count() const override { return params_.vsgl_count; }

  // The 3 moment layers' pyramids (layer-major, VirtualSquare layout), for verify.
  const Buffer& pyramid() const { return pyramid_; }

 private:
  void record_additional(CommandStream& stream);
  void record_mipmapping(CommandStream& stream);
  void record_filtered_sampling(CommandStream& stream);

  const DeviceView& view_;
  FisVariant variant_;
  FisParams params_;
  Buffer pyramid_;
  Buffer vsgls_;
  ComputePipeline additional_;
  ComputePipeline mip_level_;
  ComputePipeline filtered_sampling_;
  BindingSet additional_set_;
  BindingSet mip_set_;
  BindingSet sampling_set_;
};

}  // namespace vsgl
