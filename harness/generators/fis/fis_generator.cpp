#include "harness/generators/fis/fis_generator.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>

#include "harness/vk/command_stream.hpp"
#include "harness/vk/device.hpp"
#include "harness/vk/device_info.hpp"
#include "harness/generators/device_view.hpp"
#include "harness/generators/generator_descriptor.hpp"
#include "harness/core/error.hpp"
#include "harness/core/program_name.hpp"
#include "harness/math/vsgl_math.hpp"
#include "kernels/include/interface/fis.h"

namespace vsgl {
namespace {

using gpu::FisAdditionalPush;
using gpu::FisMipPush;
using gpu::FisSamplingPush;
using gpu::kFisSamplingGroup;
using gpu::kFisSpdTileLevels;
using gpu::kFisTile;

using gpu::kFisSpdTailLevelSlots;
using gpu::kMomentLayers;

FisParams checked(const FisParams& p, const DeviceView& view) {
  if (p.vsgl_count == 0) throw InputError("N = 0: at least one VSGL is needed");
  if (p.vsgl_count > view.samplable_texels)
    throw InputError("N = " + std::to_string(p.vsgl_count) + " is larger than the " +
                     std::to_string(view.samplable_texels) + " valid texels with nonzero PDF of the " + view.label);
  if (!(p.K > 0.0f) || !std::isfinite(p.K)) throw InputError("K must be a positive number (got " + std::to_string(p.K) + ")");
  // table3: begin modified
  if (p.bisection_iterations == 0 || p.bisection_iterations > 64)
    throw InputError("the bisection iteration count must be in [1, 64]");
  // table3: end modified
  return p;
}

std::vector<SpecializationConstant> tile_constants() { return {{0, kFisTile}, {1, kFisTile}}; }

// table3: begin single_pass
// Levels 0..L of the square, in-bounds texels of levels 6..L (the single pass's hand-over).
VkDeviceSize spd_mid_texels(const VirtualSquare& sq) {
  VkDeviceSize n = 0;
  for (uint32_t l = kFisSpdTileLevels; l <= sq.levels; ++l) n += sq.level_texels(l);
  return std::max<VkDeviceSize>(n, 1);
}
// table3: end single_pass

std::vector<SpecializationConstant> sampling_constants(FisVariant variant, uint32_t bisection_iterations) {
  return {{0, kFisSamplingGroup}, {1, variant == FisVariant::kTok15 ? 0u : 1u}, {2, bisection_iterations}};
}

constexpr ImageSlot kStorageImage{VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1};

ComputePipelineDesc additional_pipeline(PyramidPath path) {
  // table3: begin buffer
  if (path == PyramidPath::kBuffer)
    return {"fis_additional.comp", 2, sizeof(FisAdditionalPush), tile_constants()};
  // table3: end buffer
  // table3: begin texture
  return {"fis_additional_texture.comp", 1, sizeof(FisAdditionalPush), tile_constants(), {kStorageImage}};
  // table3: end texture
}

ComputePipelineDesc sampling_pipeline(PyramidPath path, const std::vector<SpecializationConstant>& constants) {
  // table3: begin buffer
  if (path == PyramidPath::kBuffer) return {"fis_filtered_sampling.comp", 2, sizeof(FisSamplingPush), constants};
  // table3: end buffer
  // table3: begin texture
  return {"fis_filtered_sampling_texture.comp", 1, sizeof(FisSamplingPush), constants,
          {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1}}};
  // table3: end texture
}

// table3: begin single_pass
// The single pass's two dispatches: tiles to level 6, then levels 7..L (fis_mip_single_pass*.comp).
std::vector<ComputePipelineDesc> single_pass_pipelines() {
  return {{"fis_mip_single_pass.comp", 1, sizeof(FisMipPush), tile_constants(),
           {kStorageImage, {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kFisSpdTileLevels}}},
          {"fis_mip_single_pass_tail.comp", 1, sizeof(FisMipPush), tile_constants(),
           {{VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kFisSpdTailLevelSlots}}}};
}
// table3: end single_pass

std::vector<ComputePipelineDesc> mip_pipelines(PyramidPath path, MipStrategy strategy) {
  // table3: begin buffer
  if (path == PyramidPath::kBuffer) return {{"fis_mip_level.comp", 1, sizeof(FisMipPush), tile_constants()}};
  // table3: end buffer
  // table3: begin texture
  switch (strategy) {
    // table3: begin single_pass
    case MipStrategy::kSinglePass: return single_pass_pipelines();
    // table3: end single_pass
    // table3: begin per_level
    case MipStrategy::kPerLevel:
      return {{"fis_mip_level_texture.comp", 0, sizeof(FisMipPush), tile_constants(), {kStorageImage, kStorageImage}}};
    // table3: end per_level
    case MipStrategy::kBlit: break;  // every texture config compiles the whole switch (-Wswitch)
  }
  // table3: end texture
  return {};
}

constexpr MipStrategy kMipFallbackOrder[] = {MipStrategy::kBlit, MipStrategy::kPerLevel, MipStrategy::kSinglePass};

}  // namespace

std::vector<ComputePipelineDesc> fis_pipelines(PyramidPath path, MipStrategy strategy) {
  std::vector<ComputePipelineDesc> out{additional_pipeline(path)};
  for (auto& d : mip_pipelines(path, strategy)) out.push_back(std::move(d));
  out.push_back(sampling_pipeline(path, sampling_constants(FisVariant::kModified, FisParams{}.bisection_iterations)));
  return out;
}

std::string fis_unfit_reason(const DeviceInfo& info, PyramidPath path, MipStrategy strategy) {
  // table3: begin texture
  if (path == PyramidPath::kTexture) {
    const std::string why = texture_path_unsupported_reason(info);
    if (!why.empty()) return why;
    // table3: begin blit
    const VkFormatFeatureFlags blit = VK_FORMAT_FEATURE_BLIT_SRC_BIT | VK_FORMAT_FEATURE_BLIT_DST_BIT;
    if (strategy == MipStrategy::kBlit && (info.rgba32f_features & blit) != blit)
      return "the device cannot blit RGBA32F images";
    // table3: end blit
  }
  // table3: end texture
  for (const auto& desc : fis_pipelines(path, strategy)) {
    const std::string why = does_not_fit_reason(info.limits, pipeline_needs(desc));
    if (!why.empty()) return why;
  }
  return {};
}

MipStrategy effective_mip_strategy(const DeviceInfo& info, std::optional<MipStrategy> requested, std::string* reason) {
  const MipStrategy wanted = requested.value_or(default_mip_strategy(info));
  const std::string why = fis_unfit_reason(info, PyramidPath::kTexture, wanted);
  if (why.empty()) return wanted;
  std::string all = std::string(mip_strategy_name(wanted)) + ": " + why;
  for (MipStrategy s : kMipFallbackOrder) {
    if (s == wanted) continue;
    const std::string other = fis_unfit_reason(info, PyramidPath::kTexture, s);
    if (other.empty()) {
      if (reason != nullptr)
        *reason = std::string("--mipmapping ") + mip_strategy_name(wanted) + " does not fit " + info.name + ": " + why +
                  "; " + mip_strategy_name(s) + " is used instead";
      return s;
    }
    all += "; " + std::string(mip_strategy_name(s)) + ": " + other;
  }
  throw DeviceError(info.name + " cannot build the texture pyramid's mip chain with any strategy (" + all + ")");
}

std::string texture_path_unsupported_reason(const DeviceInfo& info) {
  const VkFormatFeatureFlags f = info.rgba32f_features;
  if (!(f & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT))
    return "the device does not report VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT for RGBA32F";
  if (!(f & VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT)) return "the device cannot write RGBA32F storage images";
  return {};
}

MipStrategy default_mip_strategy(const DeviceInfo& info) {
  // Fixed per kind of device, never tuned at run time, so runs stay comparable (DESIGN.md §6.1a).
  // CPU devices: the fastest correct strategy measured on lavapipe (see default_mip_strategy_reason).
  if (info.type == VK_PHYSICAL_DEVICE_TYPE_CPU) return MipStrategy::kBlit;
  return MipStrategy::kSinglePass;
}

// table3: begin report
std::string default_mip_strategy_reason(const DeviceInfo& info) {
  if (info.type == VK_PHYSICAL_DEVICE_TYPE_CPU)
    return "fastest correct strategy measured on lavapipe (Mesa 22.3.6, llvmpipe) with vsgl-mipbench on the full-size "
           "atrium and conference captures: blit 360/10 ms (camera/light view, atrium), per-level 766/145 ms, "
           "single-pass 2327/231 ms (lavapipe runs the last group's levels 7..L on one thread)";
  return "not measured on this kind of device: the single-pass downsampler is the default for GPUs by design "
         "(one dispatch, no barrier per level); measure with vsgl-mipbench";
}
// table3: end report

PyramidPath effective_pyramid_path(const DeviceInfo& info, PyramidPath requested, std::string* reason) {
  const auto buffer = [&]() {
    const std::string why = fis_unfit_reason(info, PyramidPath::kBuffer, MipStrategy::kPerLevel);
    if (!why.empty()) throw DeviceError(info.name + " cannot run FIS on the storage-buffer pyramid: " + why);
    return PyramidPath::kBuffer;
  };
  if (requested == PyramidPath::kBuffer) return buffer();
  std::string why = texture_path_unsupported_reason(info);
  if (why.empty()) {
    bool any = false;
    for (MipStrategy s : kMipFallbackOrder) any = any || fis_unfit_reason(info, PyramidPath::kTexture, s).empty();
    if (any) return requested;
    why = "no mip strategy of the texture path fits the device (" +
          fis_unfit_reason(info, PyramidPath::kTexture, MipStrategy::kPerLevel) + ")";
  }
  if (reason != nullptr) *reason = why;
  return buffer();
}

// table3: begin report
GeneratorConfig resolve_fis_config(const DeviceInfo& info, GeneratorConfig config) {
  config.pyramid = effective_pyramid_path(info, config.pyramid);
  config.mipmapping = config.pyramid == PyramidPath::kTexture ? effective_mip_strategy(info, config.mipmapping)
                                                              : config.mipmapping.value_or(default_mip_strategy(info));
  return config;
}
// table3: end report

FisGenerator::FisGenerator(Device& device, const DeviceView& view, FisVariant variant, const FisParams& params)
    : view_(view),
      variant_(variant),
      params_(checked(params, view)),
      path_(PyramidPath::kBuffer),
      strategy_(MipStrategy::kBlit),
      vsgls_(device, VkDeviceSize{params.vsgl_count} * sizeof(VsglRecord), MemoryUsage::kDeviceLocal,
             name() + "." + view.label + ".vsgls") {
  std::string fallback;
  path_ = effective_pyramid_path(device.info(), params.pyramid, &fallback);
  if (!fallback.empty())
    std::cerr << program_name() << ": " << fallback << "; " << name() << " uses the storage-buffer pyramid instead\n";
  std::string mip_fallback;
  strategy_ = path_ == PyramidPath::kTexture ? effective_mip_strategy(device.info(), params.mipmapping, &mip_fallback)
                                             : params.mipmapping.value_or(default_mip_strategy(device.info()));
  if (!mip_fallback.empty()) std::cerr << program_name() << ": " << mip_fallback << " (" << name() << ")\n";
  const VirtualSquare& sq = view.square;
  const auto sampling = sampling_pipeline(path_, sampling_constants(variant, params.bisection_iterations));
  const std::string base = name() + "." + view.label;

  // table3: begin buffer
  if (path_ == PyramidPath::kBuffer) {
    pyramid_ = Buffer(device, VkDeviceSize{kMomentLayers} * sq.total_texels() * sizeof(glm::vec4),
                      MemoryUsage::kDeviceLocal, base + ".pyramid");
    additional_.emplace(device, additional_pipeline(path_));
    mip_.emplace(device, mip_pipelines(path_, strategy_).front());
    filtered_sampling_.emplace(device, sampling);
    additional_set_.emplace(device, *additional_, buffer_bindings({view.layers(), {pyramid_}}), base + ".additional");
    mip_sets_.emplace_back(device, *mip_, std::vector<BufferBinding>{pyramid_}, base + ".mipmapping");
    sampling_set_.emplace(device, *filtered_sampling_, std::vector<BufferBinding>{pyramid_, vsgls_},
                          base + ".filtered_sampling");
    return;
  }
  // table3: end buffer

  // table3: begin texture
  image_.emplace(device, sq.size, sq.levels + 1, kMomentLayers, VK_FORMAT_R32G32B32A32_SFLOAT,
                 VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                     VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                 base + ".pyramid_image");
  VkSamplerCreateInfo si{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  si.magFilter = VK_FILTER_LINEAR;
  si.minFilter = VK_FILTER_LINEAR;
  si.mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
  si.addressModeU = si.addressModeV = si.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER;
  si.borderColor = VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK;  // zero outside the square (DESIGN.md §4)
  si.minLod = 0.0f;
  si.maxLod = static_cast<float>(sq.levels);
  si.unnormalizedCoordinates = VK_FALSE;
  sampler_.emplace(device, si, base + ".sampler");

  additional_.emplace(device, additional_pipeline(path_));
  additional_set_.emplace(device, *additional_, view.layers(), std::vector<ImageBinding>{{{image_->level_view(0)}}},
                          base + ".additional");
  filtered_sampling_.emplace(device, sampling);
  sampling_set_.emplace(device, *filtered_sampling_, std::vector<BufferBinding>{vsgls_},
                        std::vector<ImageBinding>{{{image_->view()}, sampler_->get()}}, base + ".filtered_sampling");

  // table3: begin single_pass
  if (strategy_ == MipStrategy::kSinglePass) {
    if (sq.levels > kFisSpdTileLevels + kFisSpdTailLevelSlots)
      throw InputError("the single-pass downsampler supports squares of at most 2^" +
                       std::to_string(kFisSpdTileLevels + kFisSpdTailLevelSlots) + " texels");
    spd_mid_ = Buffer(device, VkDeviceSize{kMomentLayers} * spd_mid_texels(sq) * sizeof(glm::vec4),
                      MemoryUsage::kDeviceLocal, base + ".spd_mid");
    const auto descs = single_pass_pipelines();
    mip_.emplace(device, descs[0]);
    spd_tail_.emplace(device, descs[1]);
    // Entries above L repeat level L; they are never written.
    ImageBinding tile_levels, tail_levels;
    for (uint32_t l = 1; l <= kFisSpdTileLevels; ++l) tile_levels.views.push_back(image_->level_view(std::min(l, sq.levels)));
    for (uint32_t l = kFisSpdTileLevels + 1; l <= kFisSpdTileLevels + kFisSpdTailLevelSlots; ++l)
      tail_levels.views.push_back(image_->level_view(std::min(l, sq.levels)));
    mip_sets_.emplace_back(device, *mip_, std::vector<BufferBinding>{spd_mid_},
                           std::vector<ImageBinding>{{{image_->level_view(0)}}, tile_levels}, base + ".mipmapping");
    mip_sets_.emplace_back(device, *spd_tail_, std::vector<BufferBinding>{spd_mid_},
                           std::vector<ImageBinding>{tail_levels}, base + ".mipmapping.tail");
  }
  // table3: end single_pass
  // table3: begin per_level
  if (strategy_ == MipStrategy::kPerLevel) {
    mip_.emplace(device, mip_pipelines(path_, strategy_).front());
    for (uint32_t l = 0; l < sq.levels; ++l)
      mip_sets_.emplace_back(device, *mip_, std::vector<BufferBinding>{},
                             std::vector<ImageBinding>{{{image_->level_view(l)}}, {{image_->level_view(l + 1)}}},
                             base + ".mipmapping.level" + std::to_string(l));
  }
  // table3: end per_level
  // table3: end texture
}

// The paper's three passes, in order (DESIGN.md §7): the moments of every texel, their mip
// pyramid, and one thread per VSGL sampling and filtering it.
const std::vector<VsglGenerator::Phase<FisGenerator>>& FisGenerator::phase_list() {
  static const std::vector<Phase<FisGenerator>> phases{
      {"additional", &FisGenerator::record_additional},
      {"mipmapping", &FisGenerator::record_mipmapping},
      {"filtered_sampling", &FisGenerator::record_filtered_sampling},
  };
  return phases;
}

void FisGenerator::record(CommandStream& stream, const std::function<void(VkCommandBuffer)>& boundary) {
  record_phases(*this, stream, boundary, phase_list());
}

// Moment layers of every texel into pyramid level 0 (DESIGN.md §4, §7); only in-bounds texels.
void FisGenerator::record_additional(CommandStream& stream) {
  const VirtualSquare& sq = view_.square;
  FisAdditionalPush push{};
  push.source_position = glm::vec4(view_.source_position, 0.0f);
  push.width = sq.width;
  push.height = sq.height;
  push.pyramid_total = sq.total_texels();
  push.camera_view = view_.kind == ViewKind::kCamera ? 1u : 0u;
  stream.dispatch(*additional_, *additional_set_, push, div_up(sq.width, kFisTile), div_up(sq.height, kFisTile));
}

// Levels 1..L, each texel the 2x2 mean of its children (DESIGN.md §4).
void FisGenerator::record_mipmapping(CommandStream& stream) {
  const VirtualSquare& sq = view_.square;
  // table3: begin buffer|per_level
  if (path_ == PyramidPath::kBuffer || strategy_ == MipStrategy::kPerLevel) {
    // One dispatch per level; a barrier orders consecutive levels.
    for (uint32_t l = 0; l < sq.levels; ++l) {
      if (l > 0) stream.compute_barrier();
      const FisMipPush push{sq.width, sq.height, l, 0};
      const BindingSet& set = path_ == PyramidPath::kBuffer ? mip_sets_.front() : mip_sets_[l];
      stream.dispatch(*mip_, set, push, div_up(sq.level_width(l + 1), kFisTile), div_up(sq.level_height(l + 1), kFisTile));
    }
    return;
  }
  // table3: end buffer|per_level
  // table3: begin single_pass
  if (strategy_ == MipStrategy::kSinglePass) {
    // One group per 64x64 tile of level 0 (= one per in-bounds level-6 texel) builds levels 1..6;
    // then one group builds levels 7..L from the level-6 texels.
    const bool tail = sq.levels > kFisSpdTileLevels;
    const uint32_t gx = tail ? sq.level_width(kFisSpdTileLevels) : 1;
    const uint32_t gy = tail ? sq.level_height(kFisSpdTileLevels) : 1;
    const FisMipPush push{sq.width, sq.height, 0, 0};
    stream.dispatch(*mip_, mip_sets_[0], push, gx, gy);
    if (tail) {
      stream.compute_barrier();
      stream.dispatch(*spd_tail_, mip_sets_[1], push, 1, 1);
    }
    return;
  }
  // table3: end single_pass
  // table3: begin blit
  // vkCmdBlitImage chain. A linear 2:1 blit samples each destination texel exactly between its
  // four sources (weights 1/2 x 1/2), i.e. their mean. An odd extent does not halve exactly, so
  // each blit reads the even-rounded region 2*ceil(w/2) x 2*ceil(h/2) of level l — its extra
  // column/row is the zero padding of the virtual square — and writes only the in-bounds extent
  // of level l + 1: the §4 mean with missing children zero (summation order is the driver's).
  // Each level is in the transfer layout of its role: level l a source once level l + 1 waits
  // as a destination; all back to GENERAL for the sampling pass.
  if (sq.levels == 0) return;  // a one-texel square: level 0 is the whole pyramid
  using Layout = MipImage::LevelLayout;
  constexpr VkImageLayout kGeneral = VK_IMAGE_LAYOUT_GENERAL;
  constexpr VkImageLayout kSrc = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  constexpr VkImageLayout kDst = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  const VkCommandBuffer cmd = stream.get();
  image_->change_layouts(cmd, {Layout{0, 1, kGeneral, kSrc}, Layout{1, sq.levels, kGeneral, kDst}},
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT);
  for (uint32_t l = 0; l < sq.levels; ++l) {
    if (l > 0)
      image_->change_layouts(cmd, {Layout{l, 1, kDst, kSrc}}, VK_PIPELINE_STAGE_TRANSFER_BIT,
                             VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
    const auto w = static_cast<int32_t>(sq.level_width(l + 1));
    const auto h = static_cast<int32_t>(sq.level_height(l + 1));
    VkImageBlit region{};
    region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, l, 0, kMomentLayers};
    region.srcOffsets[1] = {2 * w, 2 * h, 1};
    region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, l + 1, 0, kMomentLayers};
    region.dstOffsets[1] = {w, h, 1};
    vkCmdBlitImage(cmd, image_->get(), kSrc, image_->get(), kDst, 1, &region, VK_FILTER_LINEAR);
  }
  image_->change_layouts(cmd, {Layout{0, sq.levels, kSrc, kGeneral}, Layout{sq.levels, 1, kDst, kGeneral}},
                         VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
  // table3: end blit
}

// One thread per VSGL: sample, choose the level, fetch, build (Eq. 1/4 or Eq. 3/5).
void FisGenerator::record_filtered_sampling(CommandStream& stream) {
  const VirtualSquare& sq = view_.square;
  const FisSamplingPush push{sq.width, sq.height, params_.vsgl_count, params_.offset_bits, params_.K};
  stream.dispatch(*filtered_sampling_, *sampling_set_, push, div_up(params_.vsgl_count, kFisSamplingGroup));
}

// table3: begin verify
std::vector<glm::vec4> FisGenerator::download_pyramid(Device& device) const {
  const VirtualSquare& sq = view_.square;
  const std::size_t count = std::size_t{kMomentLayers} * sq.total_texels();
  if (path_ == PyramidPath::kBuffer) return download_vector<glm::vec4>(device, pyramid_, count);
  Buffer readback(device, count * sizeof(glm::vec4), MemoryUsage::kReadback, name() + ".pyramid_readback");
  std::vector<VkBufferImageCopy> regions;
  for (uint32_t layer = 0; layer < kMomentLayers; ++layer)
    for (uint32_t l = 0; l <= sq.levels; ++l) {
      VkBufferImageCopy r{};
      r.bufferOffset = (VkDeviceSize{layer} * sq.total_texels() + sq.level_offset(l)) * sizeof(glm::vec4);
      r.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, l, layer, 1};
      r.imageExtent = {sq.level_width(l), sq.level_height(l), 1};
      regions.push_back(r);
    }
  device.submit_and_wait(
      [&](VkCommandBuffer cmd) {
        CommandStream(cmd).full_barrier();
        const uint32_t all = sq.levels + 1;
        image_->change_layouts(cmd, {{0, all, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL}},
                               VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_MEMORY_WRITE_BIT,
                               VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
        vkCmdCopyImageToBuffer(cmd, image_->get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.get(),
                               static_cast<uint32_t>(regions.size()), regions.data());
        image_->change_layouts(cmd, {{0, all, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL}},
                               VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                               VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT);
        VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        b.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        b.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &b, 0, nullptr, 0,
                             nullptr);
      },
      "reading back " + name() + "'s pyramid image");
  std::vector<glm::vec4> out(count);
  std::memcpy(out.data(), readback.mapped(), count * sizeof(glm::vec4));
  return out;
}
// table3: end verify

}  // namespace vsgl
