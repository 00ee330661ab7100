#pragma once
// The FIS generators on the GPU (DESIGN.md §6.1): `fis_tok15` [Tok15] and `fis_modified` (the paper's
// "Ours"). Phases, as in Table 1: additional -> mipmapping -> filtered_sampling. The variants
// share every pass; the kernel include/fis_filtered_sampling.glsl differs only in choose_level()
// and estimate_power(), selected by a specialization constant.
//
// Two pyramid paths (DESIGN.md §6.1a): `texture` (default) keeps the moment layers in a sampled
// RGBA32F 2D-array image with a full mip chain and filters in hardware — one textureLod per
// trilinear lookup, as the paper's GPU did; `buffer` keeps them in a storage buffer with software
// filtering, bit-exact with the CPU reference. The texture path builds its mip chain with one of
// three strategies (MipStrategy): a single-pass downsampler, the API's vkCmdBlitImage chain, or
// one dispatch per level.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include "harness/vk/buffer.hpp"
#include "harness/vk/compute_pipeline.hpp"
#include "harness/vk/image.hpp"
#include "harness/math/fis_params.hpp"
#include "harness/generators/vsgl_generator.hpp"

namespace vsgl {

class Device;
struct DeviceInfo;
struct DeviceView;

// The image format and sampler of the texture path, and the device limits that bound how
// exactly its filter can agree with the CPU reference (recorded in every table, DESIGN.md §6.1a).
struct TextureFilterInfo {
  VkFormat format = VK_FORMAT_R32G32B32A32_SFLOAT;
  uint32_t sub_texel_precision_bits = 0;
  uint32_t mipmap_precision_bits = 0;
};
inline constexpr const char* kPyramidImageFormat = "R32G32B32A32_SFLOAT";
inline constexpr const char* kPyramidSampler =
    "min/mag LINEAR, mipmap LINEAR, clamp to border (transparent black), normalized coordinates";

// Why the device cannot run the texture path (empty: it can): RGBA32F must allow linear
// filtering when sampled and storage-image writes.
std::string texture_path_unsupported_reason(const DeviceInfo& info);
// The mipmapping strategy a run uses when none is given, by kind of device, and why (measured on
// lavapipe for CPU devices; the single-pass downsampler, unmeasured here, for GPUs).
MipStrategy default_mip_strategy(const DeviceInfo& info);
// table3: begin report
std::string default_mip_strategy_reason(const DeviceInfo& info);
// table3: end report
// The pyramid path a run takes for `requested` on this device: the texture path falls back to
// the buffer path (with `reason` set) when the device cannot filter RGBA32F or no mip strategy
// of it fits the device's limits. Throws DeviceError when the buffer path does not fit either.
PyramidPath effective_pyramid_path(const DeviceInfo& info, PyramidPath requested, std::string* reason = nullptr);

// The compute pipelines a FIS generator creates for `path` and (texture path) `strategy`, in
// creation order, for the variant with the paper's parameters: what fis_unfit_reason checks
// against a device before anything is created (DESIGN.md §9).
std::vector<ComputePipelineDesc> fis_pipelines(PyramidPath path, MipStrategy strategy);
// Why the device cannot run FIS on `path` with `strategy` (empty: it can): a pipeline over a
// limit (named, with its value and the need), or a format feature missing.
std::string fis_unfit_reason(const DeviceInfo& info, PyramidPath path, MipStrategy strategy);
// The mip strategy a run on the texture path uses: `requested` (else the device kind's default)
// when it fits the device, otherwise the first of blit, per-level, single-pass that does, with
// `reason` saying why. Throws DeviceError naming the limits when none fits.
MipStrategy effective_mip_strategy(const DeviceInfo& info, std::optional<MipStrategy> requested,
                                   std::string* reason = nullptr);

// table3: begin report
struct GeneratorConfig;
// `config` with the FIS pyramid path this device takes and its mipmapping strategy filled in
// (what Table 3 and the JSON report).
GeneratorConfig resolve_fis_config(const DeviceInfo& info, GeneratorConfig config);
// table3: end report

class FisGenerator : public VsglGenerator {
 public:
  // Throws InputError for N = 0, N larger than the view's samplable texels or K <= 0. A path or
  // mip strategy the device cannot run (limits, RGBA32F features) falls back, said on stderr
  // (effective_pyramid_path, effective_mip_strategy); DeviceError when nothing fits.
  FisGenerator(Device& device, const DeviceView& view, FisVariant variant, const FisParams& params);

  std::string name() const override { return fis_variant_name(variant_); }
  std::vector<std::string> phases() const override { return phase_names(phase_list()); }
  void record(CommandStream& stream, const std::function<void(VkCommandBuffer)>& boundary) override;
  const Buffer& vsgls() const override { return vsgls_; }
  uint32_t vsgl_count() const override { return params_.vsgl_count; }

  PyramidPath pyramid_path() const { return path_; }
  MipStrategy mip_strategy() const { return strategy_; }  // after any fallback to what fits
  // table3: begin verify
  // The 3 moment layers' pyramids (layer-major, VirtualSquare layout), read back from either
  // path's storage, for verify. Submits and waits.
  std::vector<glm::vec4> download_pyramid(Device& device) const;
  // table3: end verify

  // Records only the mipmapping phase (the microbenchmark times it alone).
  void record_mipmapping(CommandStream& stream);

 private:
  static const std::vector<Phase<FisGenerator>>& phase_list();
  void record_additional(CommandStream& stream);
  void record_filtered_sampling(CommandStream& stream);

  const DeviceView& view_;
  FisVariant variant_;
  FisParams params_;
  PyramidPath path_;
  MipStrategy strategy_;
  Buffer vsgls_;
  // table3: begin buffer
  Buffer pyramid_;
  // table3: end buffer
  // table3: begin texture
  std::optional<MipImage> image_;
  std::optional<Sampler> sampler_;
  // table3: begin single_pass
  Buffer spd_mid_;  // level-6 and coarser texels, handed from its first dispatch to its second
  // table3: end single_pass
  // table3: end texture
  // Pipelines and sets of the chosen path.
  std::optional<ComputePipeline> additional_;
  std::optional<ComputePipeline> mip_;
  // table3: begin single_pass
  std::optional<ComputePipeline> spd_tail_;  // levels 7..L
  // table3: end single_pass
  std::optional<ComputePipeline> filtered_sampling_;
  std::optional<BindingSet> additional_set_;
  std::vector<BindingSet> mip_sets_;  // buffer: one; single pass: tiles, tail; per-level: one per level
  std::optional<BindingSet> sampling_set_;
};

}  // namespace vsgl
