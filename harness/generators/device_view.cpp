#include "harness/generators/device_view.hpp"

#include <algorithm>

#include "harness/vk/device.hpp"
#include "harness/core/error.hpp"

namespace vsgl {

const char* view_name(ViewKind kind) { return kind == ViewKind::kCamera ? "camera_view" : "light_view"; }

std::vector<glm::vec4> interleave_view(const ViewImage& v) {
  const std::size_t n = v.texels();
  std::vector<glm::vec4> out(4 * n);
  const auto& p = v.planes;
  for (std::size_t i = 0; i < n; ++i) {
    out[i] = {p[kPX][i], p[kPY][i], p[kPZ][i], p[kValid][i]};
    out[n + i] = {p[kNX][i], p[kNY][i], p[kNZ][i], p[kPdf][i]};
    out[2 * n + i] = {p[kDR][i], p[kDG][i], p[kDB][i], p[kRoughness][i]};
    out[3 * n + i] = {p[kSR][i], p[kSG][i], p[kSB][i], 0.0f};
  }
  return out;
}

DeviceView upload_view(Device& device, const Capture& capture, ViewKind kind) {
  const ViewImage& v = capture.view(kind);
  const std::string what = std::string(view_file_name(kind));
  if (!v.has_pdf)
    throw InputError(what + ": the capture has no BRSM PDF for the light view; record it again with "
                            "`vsgl-bench record` (which builds the PDF)");
  DeviceView out;
  out.kind = kind;
  out.square = VirtualSquare::make(v.width, v.height, what);
  out.source_position = kind == ViewKind::kCamera ? capture.meta.camera.position : capture.meta.light.position;
  out.label = view_name(kind);
  for (std::size_t i = 0; i < v.texels(); ++i) {
    if (v.planes[kValid][i] == 0.0f) continue;
    ++out.valid_texels;
    if (v.planes[kPdf][i] > 0.0f) ++out.samplable_texels;
  }
  if (out.samplable_texels == 0)
    throw InputError(what + ": all-zero PDF on the valid texels: no texel can be sampled");
  out.texels = upload_layers(device, v, std::string(out.label) + ".texels");
  return out;
}

LayeredTexels upload_layers(Device& device, const ViewImage& view, const std::string& name) {
  const auto texels = interleave_view(view);
  LayeredTexels out;
  out.layer_bytes = VkDeviceSize{view.texels()} * sizeof(glm::vec4);
  const VkDeviceSize align = std::max<VkDeviceSize>(device.info().limits.storage_buffer_offset_alignment, 1);
  out.layer_stride = (out.layer_bytes + align - 1) / align * align;
  out.buffer = Buffer(device, 4 * out.layer_stride, MemoryUsage::kDeviceLocal, name);
  for (uint32_t layer = 0; layer < 4; ++layer)
    upload(device, out.buffer, texels.data() + std::size_t{layer} * view.texels(), out.layer_bytes,
           layer * out.layer_stride);
  return out;
}

std::vector<BufferBinding> LayeredTexels::layers() const {
  std::vector<BufferBinding> out;
  for (uint32_t layer = 0; layer < 4; ++layer) out.emplace_back(buffer, layer * layer_stride, layer_bytes);
  return out;
}

}  // namespace vsgl
