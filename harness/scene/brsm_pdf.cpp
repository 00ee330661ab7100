#include "harness/scene/brsm_pdf.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <optional>

#include "harness/vk/buffer.hpp"
#include "harness/vk/command_stream.hpp"
#include "harness/vk/compute_pipeline.hpp"
#include "harness/vk/device.hpp"
#include "harness/generators/device_view.hpp"
#include "harness/core/error.hpp"
#include "harness/core/program_name.hpp"
#include "harness/generators/fis/fis_generator.hpp"
#include "harness/vk/timestamp_pool.hpp"
#include "kernels/include/interface/brsm.h"

namespace vsgl {
float brsm_texel_weight(const ViewImage& rsm, uint32_t x, uint32_t y, glm::vec3 light_position,
                        const std::vector<VsglRecord>& camera_vsgls) {
  if (rsm.at(kValid, x, y) <= 0.5f) return 0.0f;
  const glm::vec3 P(rsm.at(kPX, x, y), rsm.at(kPY, x, y), rsm.at(kPZ, x, y));
  const glm::vec3 N(rsm.at(kNX, x, y), rsm.at(kNY, x, y), rsm.at(kNZ, x, y));
  const glm::vec3 fd(rsm.at(kDR, x, y), rsm.at(kDG, x, y), rsm.at(kDB, x, y));
  const glm::vec3 fs(rsm.at(kSR, x, y), rsm.at(kSG, x, y), rsm.at(kSB, x, y));
  const glm::vec3 flux = fd + fs;
  if (!(flux.r + flux.g + flux.b > 0.0f)) return 0.0f;
  const glm::vec3 to_light = light_position - P;
  const float d2 = glm::dot(to_light, to_light);
  const glm::vec3 wo = d2 > 0.0f ? to_light * (1.0f / std::sqrt(d2)) : N;
  float importance = 0.0f;
  for (const auto& cam : camera_vsgls)
    importance += vsgl_importance_to_texel(cam, P, N, wo, fd, fs, rsm.at(kRoughness, x, y));
  return importance;
}

struct BrsmPdfPass::State {
  std::optional<FisGenerator> camera_fis;
  FisParams params;
  uint32_t rsm_width = 0, rsm_height = 0;
  glm::vec3 light_position{0.0f};
  Buffer pdf;
  std::optional<ComputePipeline> pipeline;
  std::optional<BindingSet> set;
};

BrsmPdfPass::BrsmPdfPass(Device& device, const Capture& capture, const DeviceView& camera,
                         std::vector<BufferBinding> rsm_layers, uint32_t camera_vsgls)
    : state_(std::make_unique<State>()) {
  State& st = *state_;
  FisParams& params = st.params;
  params.vsgl_count = std::min(camera_vsgls, camera.samplable_texels);
  // The BRSM PDF is recorded data: the buffer path keeps it bit-exact with the CPU reference and
  // identical on every device (the texture path's filter precision is the device's). A G-buffer
  // whose buffer pyramid the device cannot bind (3840x2176 needs 358 MB a moment layer, lavapipe
  // binds 128 MiB) takes the texture path instead: recordable, no longer bit-identical across devices.
  params.pyramid = PyramidPath::kBuffer;
  try {
    st.camera_fis.emplace(device, camera, FisVariant::kModified, params);
  } catch (const DeviceLimitError& e) {
    params.pyramid = PyramidPath::kTexture;
    st.camera_fis.emplace(device, camera, FisVariant::kModified, params);
    std::cerr << program_name() << ": the BRSM PDF of '" << capture.meta.scene
              << "' is built on the texture path (its PDF is then the device's, not bit-identical across devices): "
              << e.what() << "\n";
  }
  const ViewImage& rsm = capture.rsm;
  st.rsm_width = rsm.width;
  st.rsm_height = rsm.height;
  st.light_position = capture.meta.light.position;
  st.pdf = Buffer(device, rsm.texels() * sizeof(float), MemoryUsage::kDeviceLocal, "brsm.pdf");
  st.pipeline.emplace(device, ComputePipelineDesc{"brsm_pdf.comp", 3, sizeof(gpu::BrsmPush),
                                                  work_group_size_2d(gpu::kBrsmGroupSize, gpu::kBrsmGroupSize)});
  st.set.emplace(device, *st.pipeline, buffer_bindings({std::move(rsm_layers), {st.camera_fis->vsgls()}, {st.pdf}}),
                 "brsm.set");
}

BrsmPdfPass::~BrsmPdfPass() = default;

void BrsmPdfPass::record(CommandStream& stream) {
  State& st = *state_;
  record_untimed(*st.camera_fis, stream);
  const gpu::BrsmPush push{st.rsm_width, st.rsm_height, st.params.vsgl_count, 0, glm::vec4(st.light_position, 1.0f)};
  stream.dispatch(*st.pipeline, *st.set, push, div_up(st.rsm_width, gpu::kBrsmGroupSize),
                  div_up(st.rsm_height, gpu::kBrsmGroupSize));
}

const Buffer& BrsmPdfPass::pdf() const { return state_->pdf; }
uint32_t BrsmPdfPass::camera_vsgls() const { return state_->params.vsgl_count; }
PyramidPath BrsmPdfPass::pyramid() const { return state_->params.pyramid; }

BrsmBuild build_brsm_pdf(Device& device, Capture& capture, uint32_t camera_vsgls) {
  const auto wall_start = std::chrono::steady_clock::now();
  const DeviceView camera = upload_view(device, capture, ViewKind::kCamera);
  const ViewImage& rsm = capture.rsm;
  const LayeredTexels rsm_texels = upload_layers(device, rsm, "brsm.rsm_texels");
  BrsmPdfPass pass(device, capture, camera, rsm_texels.layers(), camera_vsgls);

  std::optional<TimestampPool> timestamps;
  if (device.info().timestamps()) timestamps.emplace(device, 2, "brsm.timestamps");
  device.submit_and_wait(
      [&](VkCommandBuffer cmd) {
        CommandStream stream(cmd);
        if (timestamps) {
          timestamps->reset(cmd);
          timestamps->write(cmd);
        }
        pass.record(stream);
        if (timestamps) timestamps->write(cmd);
      },
      "brsm pdf");

  BrsmBuild out;
  out.camera_vsgls = pass.camera_vsgls();
  if (timestamps) {
    const auto ticks = timestamps->read_ticks();
    out.gpu_ms = timestamps->interval_ns(ticks[0], ticks[1]) * 1e-6;
  } else {
    out.gpu_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - wall_start).count();
  }
  auto& plane = capture.rsm.planes[kPdf];
  plane = download_vector<float>(device, pass.pdf(), rsm.texels());
  if (std::none_of(plane.begin(), plane.end(), [](float q) { return q > 0.0f; }))
    throw InputError("the BRSM PDF of scene '" + capture.meta.scene +
                     "' is zero everywhere: no texel lit by the spot light is seen by the camera");
  capture.rsm.has_pdf = true;
  capture.meta.brsm_build_ms = out.gpu_ms;
  capture.meta.brsm_pyramid = pass.pyramid();
  capture.meta.brsm_importance = std::string(kBrsmImportanceModel);
  capture.meta.brsm_bias_alpha = gpu::kBiasReductionAlpha;
  return out;
}

}  // namespace vsgl
