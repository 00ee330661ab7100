#include "harness/generators/fis/fis_generator.hpp"

#include <cmath>

#include "harness/vk/command_stream.hpp"
#include "harness/vk/device.hpp"
#include "harness/generators/device_view.hpp"
#include "harness/core/error.hpp"
#include "harness/math/vsgl_math.hpp"

namespace vsgl {
namespace {

constexpr uint32_t kMomentLayers = 3;
constexpr uint32_t kTile = 16;            // 16x16 threads per group in the per-texel passes
constexpr uint32_t kSamplingGroup = 64;   // threads per group in filtered sampling

struct AdditionalPush {
  uint32_t width, height, pyramid_total, camera_view;
  glm::vec4 source_position;
};
struct MipPush {
  uint32_t width, height, source_level;
};
struct SamplingPush {
  uint32_t width, height, count, offset_bits;
  float K;
};

FisParams checked(const FisParams& p, const DeviceView& view) {
  if (p.vsgl_count == 0) throw InputError("N = 0: at least one VSGL is needed");
  if (p.vsgl_count > view.samplable_texels)
    throw InputError("N = " + std::to_string(p.vsgl_count) + " is larger than the " +
                     std::to_string(view.samplable_texels) + " valid texels with nonzero PDF of the " + view.label);
  if (!(p.K > 0.0f) || !std::isfinite(p.K)) throw InputError("K must be a positive number (got " + std::to_string(p.K) + ")");
  if (p.bisection_iterations == 0 || p.bisection_iterations > 64)
    throw InputError("the bisection iteration count must be in [1, 64]");
  return p;
}

}  // namespace

FisGenerator::FisGenerator(Device& device, const DeviceView& view, FisVariant variant, const FisParams& params)
    : view_(view),
      variant_(variant),
      params_(checked(params, view)),
      pyramid_(device, VkDeviceSize{kMomentLayers} * view.square.total_texels() * sizeof(glm::vec4),
               MemoryUsage::kDeviceLocal, name() + "." + view.label + ".pyramid"),
      vsgls_(device, VkDeviceSize{params.vsgl_count} * sizeof(VsglRecord), MemoryUsage::kDeviceLocal,
             name() + "." + view.label + ".vsgls"),
      additional_(device, {"fis_additional.comp", 2, sizeof(AdditionalPush), {}}),
      mip_level_(device, {"fis_mip_level.comp", 1, sizeof(MipPush), {}}),
      filtered_sampling_(device, {"fis_filtered_sampling.comp", 2, sizeof(SamplingPush),
                                  {{0, kSamplingGroup},
                                   {1, variant == FisVariant::kTok15 ? 0u : 1u},
                                   {2, params.bisection_iterations}}}),
      additional_set_(device, additional_, {view.texels, pyramid_}, name() + ".additional"),
      mip_set_(device, mip_level_, {pyramid_}, name() + ".mipmapping"),
      sampling_set_(device, filtered_sampling_, {pyramid_, vsgls_}, name() + ".filtered_sampling") {}

void FisGenerator::record(CommandStream& stream, const std::function<void(VkCommandBuffer)>& boundary) {
  boundary(stream.get());
  record_additional(stream);
  boundary(stream.get());
  record_mipmapping(stream);
  boundary(stream.get());
  record_filtered_sampling(stream);
  boundary(stream.get());
}

// Moment layers of every texel into pyramid level 0 (SPEC §4, §7).
void FisGenerator::record_additional(CommandStream& stream) {
  const VirtualSquare& sq = view_.square;
  const AdditionalPush push{sq.width, sq.height, sq.total_texels(), view_.kind == ViewKind::kCamera ? 1u : 0u,
                            glm::vec4(view_.source_position, 0.0f)};
  stream.dispatch(additional_, additional_set_, push, div_up(sq.width, kTile), div_up(sq.height, kTile));
}

// Levels 1..L, each the 2x2 mean of the one below; a barrier orders consecutive levels.
void FisGenerator::record_mipmapping(CommandStream& stream) {
  const VirtualSquare& sq = view_.square;
  for (uint32_t l = 0; l < sq.levels; ++l) {
    if (l > 0) stream.compute_barrier();
    const MipPush push{sq.width, sq.height, l};
    stream.dispatch(mip_level_, mip_set_, push, div_up(sq.level_width(l + 1), kTile),
                    div_up(sq.level_height(l + 1), kTile));
  }
}

// One thread per VSGL: sample, choose the level, fetch, build (Eq. 1/4 or Eq. 3/5).
void FisGenerator::record_filtered_sampling(CommandStream& stream) {
  const VirtualSquare& sq = view_.square;
  const SamplingPush push{sq.width, sq.height, params_.vsgl_count, params_.offset_bits, params_.K};
  stream.dispatch(filtered_sampling_, sampling_set_, push, div_up(params_.vsgl_count, kSamplingGroup));
}

}  // namespace vsgl
