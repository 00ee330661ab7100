#pragma once
// One view of a capture uploaded for the generators: a device-local buffer of 4 layers of
// W*H vec4 texels — (P, valid), (N, pdf), (diffuse, roughness), (specular, 0) — plus what the
// host needs to size and check the passes. Uploads happen before any timing (DESIGN.md §9).
// Kernels bind the layers as the 4 descriptors of one array binding (kernels/include/
// view_layers.glsl), a range each, so a view binds wherever one layer fits maxStorageBufferRange:
// a 3840x2176 G-buffer is 134 MB a layer, 535 MB in all.
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "harness/vk/buffer.hpp"
#include "harness/vk/compute_pipeline.hpp"
#include "harness/capture/capture.hpp"
#include "harness/math/virtual_square.hpp"

namespace vsgl {

class Device;

// The 4 layers of a view in one device-local buffer, layer k at k * layer_stride.
struct LayeredTexels {
  Buffer buffer;
  VkDeviceSize layer_bytes = 0;   // W*H vec4
  VkDeviceSize layer_stride = 0;  // layer_bytes rounded up to minStorageBufferOffsetAlignment

  // The layers, in order, for a kernel's `view_layers[4]` binding.
  std::vector<BufferBinding> layers() const;
};

LayeredTexels upload_layers(Device& device, const ViewImage& view, const std::string& name);

struct DeviceView {
  ViewKind kind = ViewKind::kCamera;
  VirtualSquare square;
  glm::vec3 source_position{0.0f};  // camera (G-buffer) or spot light (RSM) position
  uint32_t valid_texels = 0;
  uint32_t samplable_texels = 0;    // valid texels with a positive PDF weight
  std::string label;                // "camera_view" | "light_view"
  LayeredTexels texels;

  std::vector<BufferBinding> layers() const { return texels.layers(); }
};

const char* view_name(ViewKind kind);  // "camera_view" | "light_view" (the tables' names)

// Throws InputError when the view has no PDF (an RSM recorded before its BRSM PDF was built)
// or an all-zero PDF.
DeviceView upload_view(Device& device, const Capture& capture, ViewKind kind);

// The same layout on the host (tests and the CPU references use it).
std::vector<glm::vec4> interleave_view(const ViewImage& view);

}  // namespace vsgl
