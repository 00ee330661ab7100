#include "harness/quality/shading_pass.hpp"

#include <algorithm>
#include <numeric>

#include "harness/vk/buffer.hpp"
#include "harness/vk/command_stream.hpp"
#include "harness/vk/compute_pipeline.hpp"
#include "harness/vk/device.hpp"
#include "harness/generators/device_view.hpp"
#include "harness/core/error.hpp"
#include "harness/quality/shading_visibility.hpp"
#include "harness/visibility/imperfect_shadow_maps.hpp"
#include "harness/visibility/segment_query.hpp"
#include "kernels/include/interface/shading.h"

namespace vsgl {
uint32_t shaded_extent(uint32_t side, uint32_t stride) { return (side + stride - 1) / stride; }

uint32_t shade_chunk_vsgls(uint64_t pixels) {
  const uint64_t tile = uint64_t{gpu::kShadeGroupSize} * gpu::kShadeGroupSize;
  const uint64_t fit = kShadeEvaluationsPerDispatch / std::max<uint64_t>(pixels, 1);
  return static_cast<uint32_t>(std::max(tile, fit / tile * tile));
}

uint32_t shade_cost_factor(ShadingVisibility mode) {
  switch (mode) {
    case ShadingVisibility::kIsm: return kShadeIsmCostFactor;
    case ShadingVisibility::kExact: return kShadeExactCostFactor;
    case ShadingVisibility::kNone: break;
  }
  return 1;
}

uint32_t shade_chunk_vsgls(uint64_t pixels, ShadingVisibility mode) {
  if (mode == ShadingVisibility::kNone) return shade_chunk_vsgls(pixels);
  const uint64_t tile = uint64_t{gpu::kShadeGroupSize} * gpu::kShadeGroupSize;
  const uint64_t fit = kShadeEvaluationsPerDispatch / shade_cost_factor(mode) / std::max<uint64_t>(pixels, 1);
  const uint64_t chunk = fit >= tile ? fit / tile * tile : std::max<uint64_t>(fit, 1);
  return static_cast<uint32_t>(std::min<uint64_t>(chunk, UINT32_MAX));
}

uint32_t binding_window_vsgls(const Device& device, uint32_t vsgl_count, uint32_t chunk, uint32_t vsgls_per_binding) {
  const DeviceLimits& limits = device.info().limits;
  const uint64_t fits = vsgls_per_binding != 0 ? vsgls_per_binding : limits.storage_buffer_range / sizeof(VsglRecord);
  if (vsgl_count <= fits) return vsgl_count;
  // Every window starts on a chunk and at an offset the device can bind: a multiple of the
  // alignment (a power of two of at most 256 bytes by the Vulkan spec, so at most 8 records of 96 B).
  const uint64_t alignment = std::max<uint64_t>(1, limits.storage_buffer_offset_alignment);
  const uint64_t records_per_alignment = alignment / std::gcd(alignment, uint64_t{sizeof(VsglRecord)});
  const uint64_t step = std::lcm(uint64_t{chunk}, records_per_alignment);
  const uint64_t window = fits / step * step;
  if (window == 0)
    throw DeviceLimitError(device.info().name + " cannot bind one chunk of " + std::to_string(chunk) + " VSGLs (" +
                           std::to_string(uint64_t{chunk} * sizeof(VsglRecord)) +
                           " bytes) of the shading pass: maxStorageBufferRange is " +
                           std::to_string(limits.storage_buffer_range));
  return static_cast<uint32_t>(window);
}

RadianceImage shade_camera_view(Device& device, const DeviceView& camera, const Buffer& vsgls, uint32_t vsgl_count,
                                uint32_t stride, uint32_t vsgls_per_dispatch, uint32_t vsgls_per_binding) {
  return shade_camera_view(device, camera, vsgls, vsgl_count, stride, ShadeVisibility{}, vsgls_per_dispatch,
                           vsgls_per_binding);
}

ShadingRecording::ShadingRecording(Device& device, const DeviceView& camera, const Buffer& vsgls, uint32_t vsgl_count,
                                   uint32_t stride, const ShadeVisibility& visibility, uint32_t vsgls_per_dispatch,
                                   uint32_t vsgls_per_binding)
    : device_(&device) {
  if (stride == 0) throw InputError("shading pass: the stride must be at least 1");
  if (camera.kind != ViewKind::kCamera)
    throw InputError("shading pass: it shades the camera view (G-buffer), not the " + camera.label);
  if (vsgl_count == 0) throw InputError("shading pass: no VSGLs to shade with");
  if (vsgls.size() < VkDeviceSize{vsgl_count} * sizeof(VsglRecord))
    throw InputError("shading pass: the VSGL buffer '" + vsgls.name() + "' holds fewer than " +
                     std::to_string(vsgl_count) + " records");
  width_ = shaded_extent(camera.square.width, stride);
  height_ = shaded_extent(camera.square.height, stride);
  const std::size_t count = std::size_t{width_} * height_;
  mode_ = visibility.mode;
  gpu::ShadeVisibilityParams vis{};
  std::vector<BufferBinding> occluder_bindings;
  const char* kernel = "shade_vsgls.comp";
  uint32_t push_bytes = sizeof(gpu::ShadePush);
  if (mode_ == ShadingVisibility::kIsm) {
    if (visibility.maps == nullptr || visibility.maps->map_count() < vsgl_count)
      throw InputError("shading pass: shading " + std::to_string(vsgl_count) +
                       " VSGLs with imperfect shadow maps needs one map per VSGL");
    vis.ism = visibility.maps->params();
    occluder_bindings = {visibility.maps->maps()};
    kernel = "shade_vsgls_ism.comp";
  } else if (mode_ == ShadingVisibility::kExact) {
    if (visibility.occluders == nullptr)
      throw InputError("shading pass: exact visibility needs the occluders on the device");
    vis.node_count = visibility.occluders->node_count();
    vis.epsilon = visibility.occluders->epsilon();
    kernel = "shade_vsgls_exact.comp";
  }
  if (mode_ != ShadingVisibility::kNone) push_bytes = sizeof(gpu::ShadeVisibilityPush);
  const uint32_t chunk = vsgls_per_dispatch != 0 ? vsgls_per_dispatch : shade_chunk_vsgls(count, mode_);
  if (mode_ == ShadingVisibility::kExact) {
    // Each chunk's segments are answered before its dispatch (prepare_chunk) into one buffer of
    // chunk x pixels answers, from the receivers' positions and the VSGLs' means read back here.
    occluders_ = visibility.occluders;
    const uint32_t square_width = camera.square.width;
    const std::vector<glm::vec4> layer =
        download_vector<glm::vec4>(device, camera.texels.buffer, std::size_t{square_width} * camera.square.height);
    positions_.resize(count);
    for (uint32_t y = 0; y < height_; ++y)
      for (uint32_t x = 0; x < width_; ++x)
        positions_[std::size_t{y} * width_ + x] =
            layer[std::size_t{y} * stride * square_width + std::size_t{x} * stride];
    records_ = download_vector<VsglRecord>(device, vsgls, vsgl_count);
    visible_ = Buffer(device, std::size_t{std::min(chunk, vsgl_count)} * count * sizeof(uint32_t),
                      MemoryUsage::kDeviceLocal, "shade.visible");
    occluder_bindings = {visible_};
  }

  radiance_ = Buffer(device, count * sizeof(glm::vec4), MemoryUsage::kDeviceLocal, "shade.radiance");
  pipeline_.emplace(device, ComputePipelineDesc{kernel, static_cast<uint32_t>(3 + occluder_bindings.size()), push_bytes,
                                                work_group_size_2d(gpu::kShadeGroupSize, gpu::kShadeGroupSize)});
  const uint32_t window = binding_window_vsgls(device, vsgl_count, chunk, vsgls_per_binding);
  // One binding of at most `window` VSGLs at a time (the records past maxStorageBufferRange cannot
  // be bound at once); its chunks in order, each its own dispatch (shade_camera_view submits each on
  // its own): no chunk holds more than kShadeEvaluationsPerDispatch VSGL evaluations.
  for (uint32_t window_first = 0; window_first < vsgl_count; window_first += window) {
    const uint32_t window_count = std::min(window, vsgl_count - window_first);
    sets_.emplace_back(device, *pipeline_,
                       buffer_bindings({camera.layers(),
                                        {BufferBinding(vsgls, VkDeviceSize{window_first} * sizeof(VsglRecord),
                                                       VkDeviceSize{window_count} * sizeof(VsglRecord))},
                                        {radiance_},
                                        occluder_bindings}),
                       "shade.set");
    for (uint32_t first = window_first; first < window_first + window_count; first += chunk) {
      const uint32_t n = std::min(chunk, window_first + window_count - first);
      const gpu::ShadePush push{camera.square.width,
                                camera.square.height,
                                width_,
                                height_,
                                stride,
                                n,
                                first - window_first,
                                first == 0 ? 0u : 1u,
                                glm::vec4(camera.source_position, 1.0f)};
      // The maps follow the VSGLs' order: the binding's first VSGL has map window_first.
      vis.map_first = window_first;
      chunks_.push_back({sets_.size() - 1, gpu::ShadeVisibilityPush{push, vis}, first, n});
    }
  }
}

ShadingRecording::~ShadingRecording() = default;

void ShadingRecording::prepare_chunk(std::size_t index) const {
  if (mode_ != ShadingVisibility::kExact) return;
  const Chunk& c = chunks_.at(index);
  const std::size_t pixels = positions_.size();
  // Answer k * pixels + p: VSGL first + k seen from pixel p; 1 where the pixel has no surface (the
  // kernel does not read it there).
  std::vector<uint32_t> answers(std::size_t{c.count} * pixels, 1u);
  std::vector<gpu::SegmentQuery> queries;
  std::vector<std::size_t> where;
  queries.reserve(answers.size());
  where.reserve(answers.size());
  for (uint32_t k = 0; k < c.count; ++k) {
    const glm::vec3 mean = records_[c.first + k].mu();
    for (std::size_t p = 0; p < pixels; ++p) {
      if (!(positions_[p].w > 0.5f)) continue;
      queries.push_back(make_segment_query(glm::vec3(positions_[p]), mean, occluders_->epsilon()));
      where.push_back(std::size_t{k} * pixels + p);
    }
  }
  const std::vector<uint32_t> visible = occluders_->visible(queries);
  for (std::size_t q = 0; q < where.size(); ++q) answers[where[q]] = visible[q];
  upload(*device_, visible_, answers.data(), answers.size() * sizeof(uint32_t));
}

void ShadingRecording::record_chunk(CommandStream& stream, std::size_t index) const {
  const Chunk& c = chunks_.at(index);
  // The VSGLs (and an earlier chunk's sums) were written before, by this or an earlier submission.
  stream.full_barrier();
  const uint32_t groups_x = div_up(width_, gpu::kShadeGroupSize);
  const uint32_t groups_y = div_up(height_, gpu::kShadeGroupSize);
  if (mode_ == ShadingVisibility::kNone) {
    stream.dispatch(*pipeline_, sets_[c.set], c.push.shade, groups_x, groups_y);
  } else {
    stream.dispatch(*pipeline_, sets_[c.set], c.push, groups_x, groups_y);
  }
}

void ShadingRecording::record(CommandStream& stream) const {
  if (mode_ == ShadingVisibility::kExact)
    throw InputError(
        "shading pass: exact visibility answers each chunk's segments before its dispatch; shade it "
        "with shade_camera_view, not in one recording");
  for (std::size_t i = 0; i < chunks_.size(); ++i) record_chunk(stream, i);
}

RadianceImage ShadingRecording::read() const {
  RadianceImage image;
  image.width = width_;
  image.height = height_;
  image.pixels = download_vector<glm::vec4>(*device_, radiance_, std::size_t{width_} * height_);
  return image;
}

RadianceImage shade_camera_view(Device& device, const DeviceView& camera, const Buffer& vsgls, uint32_t vsgl_count,
                                uint32_t stride, const ShadeVisibility& visibility, uint32_t vsgls_per_dispatch,
                                uint32_t vsgls_per_binding) {
  const ShadingRecording shading(device, camera, vsgls, vsgl_count, stride, visibility, vsgls_per_dispatch,
                                 vsgls_per_binding);
  // One submission per chunk: a driver's watchdog (about 2 s on Windows) limits each submission.
  for (std::size_t i = 0; i < shading.chunk_count(); ++i) {
    shading.prepare_chunk(i);
    device.submit_and_wait(
        [&](VkCommandBuffer cmd) {
          CommandStream stream(cmd);
          shading.record_chunk(stream, i);
        },
        "shading pass");
  }
  return shading.read();
}

glm::vec4 shade_pixel_reference(const ViewImage& gbuffer, uint32_t x, uint32_t y, glm::vec3 camera_position,
                                const std::vector<VsglRecord>& vsgls) {
  // Every VSGL fully visible: multiplying by 1 is exact, so this is the no-visibility twin bit for bit.
  return shade_pixel_reference(gbuffer, x, y, camera_position, vsgls,
                               [](uint32_t, glm::vec3, glm::vec3) { return 1.0f; });
}

glm::vec4 shade_pixel_reference(const ViewImage& gbuffer, uint32_t x, uint32_t y, glm::vec3 camera_position,
                                const std::vector<VsglRecord>& vsgls, const VsglVisibility& visibility) {
  if (gbuffer.at(kValid, x, y) <= 0.5f) return glm::vec4(0.0f);
  const glm::vec3 P(gbuffer.at(kPX, x, y), gbuffer.at(kPY, x, y), gbuffer.at(kPZ, x, y));
  const glm::vec3 N(gbuffer.at(kNX, x, y), gbuffer.at(kNY, x, y), gbuffer.at(kNZ, x, y));
  const glm::vec3 rho_d(gbuffer.at(kDR, x, y), gbuffer.at(kDG, x, y), gbuffer.at(kDB, x, y));
  const glm::vec3 rho_s(gbuffer.at(kSR, x, y), gbuffer.at(kSG, x, y), gbuffer.at(kSB, x, y));
  const float roughness = gbuffer.at(kRoughness, x, y);
  const glm::vec3 wo = glm::normalize(camera_position - P);
  glm::vec3 sum(0.0f);
  for (uint32_t n = 0; n < vsgls.size(); ++n) {
    glm::vec3 L = vsgl_radiance_surface(vsgls[n], P, N, wo, rho_d, rho_s, roughness);
    if (L.r + L.g + L.b > 0.0f) L *= visibility(n, P, N);
    sum += L;
  }
  return glm::vec4(sum, 1.0f);
}

}  // namespace vsgl
