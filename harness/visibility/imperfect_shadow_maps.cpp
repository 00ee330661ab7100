#include "harness/visibility/imperfect_shadow_maps.hpp"

#include <bit>
#include <cmath>
#include <limits>
#include <string>

#include "harness/core/error.hpp"
#include "harness/vk/command_stream.hpp"
#include "harness/vk/compute_pipeline.hpp"
#include "harness/vk/device.hpp"

namespace vsgl {
namespace {

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

uint32_t checked_count(std::size_t n, const char* what) {
  if (n > std::numeric_limits<uint32_t>::max())
    throw InputError(std::string("imperfect shadow maps: ") + std::to_string(n) + " " + what +
                     " is more than 2^32 - 1");
  return static_cast<uint32_t>(n);
}

}  // namespace

std::vector<IsmMapOrigin> map_origins(const std::vector<VsglRecord>& vsgls) {
  std::vector<IsmMapOrigin> out;
  out.reserve(vsgls.size());
  for (const VsglRecord& v : vsgls) out.push_back({v.mu(), v.normal()});
  return out;
}

struct ImperfectShadowMaps::Kernels {
  ComputePipeline splat, pull, push;
  BindingSet splat_set, pull_set, push_set;
};

ImperfectShadowMaps::ImperfectShadowMaps(Device& device, const std::vector<SurfacePoint>& points,
                                         const std::vector<IsmMapOrigin>& origins, const IsmSettings& settings)
    : device_(&device),
      params_(ism_params(settings, checked_count(points.size(), "points"), checked_count(origins.size(), "maps"))) {
  // The frame of a map (paraboloid.glsl) needs a unit axis; a VSGL's filtered normal is one
  // (DESIGN.md §7: (0,0,1) where the normals cancel).
  for (std::size_t m = 0; m < origins.size(); ++m) {
    const IsmMapOrigin& o = origins[m];
    if (!finite(o.position) || !finite(o.normal) || std::abs(glm::length(o.normal) - 1.0f) > 1e-3f)
      throw InputError("imperfect shadow maps: map " + std::to_string(m) +
                       " has a non-finite origin or a normal that is not unit length");
  }
  require_ism_fits(device.info().limits, params_, device.info().name);

  std::vector<glm::vec4> positions(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) positions[i] = glm::vec4(points[i].position, 1.0f);
  std::vector<gpu::IsmOrigin> records(origins.size());
  for (std::size_t m = 0; m < origins.size(); ++m)
    records[m] = {glm::vec4(origins[m].position, 1.0f), glm::vec4(origins[m].normal, 0.0f)};
  points_ = Buffer(device, positions.size() * sizeof(glm::vec4), MemoryUsage::kDeviceLocal, "ism.points");
  origins_ = Buffer(device, records.size() * sizeof(gpu::IsmOrigin), MemoryUsage::kDeviceLocal, "ism.origins");
  maps_ = Buffer(device, VkDeviceSize{params_.map_count} * params_.map_stride * sizeof(uint32_t),
                 MemoryUsage::kDeviceLocal, "ism.maps");
  upload(device, points_, positions.data(), positions.size() * sizeof(glm::vec4));
  upload(device, origins_, records.data(), records.size() * sizeof(gpu::IsmOrigin));
  fill_holes_ = settings.fill_holes;
  const auto group = work_group_size_1d(gpu::kIsmGroupSize);
  ComputePipeline splat(device, {"ism_splat.comp", 3, sizeof(gpu::IsmParams), group});
  ComputePipeline pull(device, {"ism_pull.comp", 1, sizeof(gpu::IsmPyramidPush), group});
  ComputePipeline push(device, {"ism_push.comp", 1, sizeof(gpu::IsmPyramidPush), group});
  BindingSet splat_set(device, splat, {points_, origins_, maps_}, "ism.splat.set");
  BindingSet pull_set(device, pull, {maps_}, "ism.pull.set");
  BindingSet push_set(device, push, {maps_}, "ism.push.set");
  kernels_.reset(new Kernels{std::move(splat), std::move(pull), std::move(push), std::move(splat_set),
                             std::move(pull_set), std::move(push_set)});
  device.submit_and_wait(
      [&](VkCommandBuffer cmd) {
        CommandStream stream(cmd);
        record_build(stream);
        dispatches_ = stream.dispatch_count();
      },
      "imperfect shadow maps");
}

ImperfectShadowMaps::~ImperfectShadowMaps() = default;
ImperfectShadowMaps::ImperfectShadowMaps(ImperfectShadowMaps&&) noexcept = default;
ImperfectShadowMaps& ImperfectShadowMaps::operator=(ImperfectShadowMaps&&) noexcept = default;

void ImperfectShadowMaps::record_build(CommandStream& stream) const {
  const Kernels& k = *kernels_;
  VkCommandBuffer cmd = stream.get();
  const uint32_t levels = ism_level_count(params_.side);
  // Level l (side >> l) and the next coarser, for one dispatch of the pull or the push.
  const auto step = [&](uint32_t l) {
    return gpu::IsmPyramidPush{params_.map_count, params_.map_stride, ism_level_offset(params_.side, l),
                               params_.side >> l, ism_level_offset(params_.side, l + 1)};
  };
  stream.full_barrier();  // the uploads, or the origins' and points' writers
  vkCmdFillBuffer(cmd, maps_.get(), 0, VK_WHOLE_SIZE, gpu::kIsmEmpty);
  stream.full_barrier();
  stream.dispatch(k.splat, k.splat_set, params_, div_up(params_.points_per_map, gpu::kIsmGroupSize), params_.map_count);
  if (!fill_holes_) return;
  // Pull: each level from the finer one, down to 1 x 1; push: each level's empty texels from the
  // coarser one, back up to level 0. Each dispatch reads what the previous wrote.
  for (uint32_t l = 0; l + 1 < levels; ++l) {
    const uint32_t coarse = params_.side >> (l + 1);
    stream.compute_barrier();
    stream.dispatch(k.pull, k.pull_set, step(l), div_up(coarse * coarse, gpu::kIsmGroupSize), params_.map_count);
  }
  for (uint32_t l = levels - 1; l-- > 0;) {
    const uint32_t fine = params_.side >> l;
    stream.compute_barrier();
    stream.dispatch(k.push, k.push_set, step(l), div_up(fine * fine, gpu::kIsmGroupSize), params_.map_count);
  }
}

std::vector<float> ImperfectShadowMaps::read_level0() const {
  const std::size_t texels = std::size_t{params_.side} * params_.side;
  const std::vector<uint32_t> all =
      download_vector<uint32_t>(*device_, maps_, std::size_t{params_.map_count} * params_.map_stride);
  std::vector<float> out(texels * params_.map_count);
  for (std::size_t m = 0; m < params_.map_count; ++m)
    for (std::size_t t = 0; t < texels; ++t) {
      const uint32_t bits = all[m * params_.map_stride + t];
      out[m * texels + t] =
          bits == gpu::kIsmEmpty ? std::numeric_limits<float>::infinity() : std::bit_cast<float>(bits);
    }
  return out;
}

}  // namespace vsgl
