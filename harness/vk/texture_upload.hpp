#pragma once
// A sampled 2D image filled from the host: every mip level given (level 0 first) goes through one
// staging buffer, and the image is left in SHADER_READ_ONLY_OPTIMAL for the fragment stage.
#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "harness/vk/image.hpp"

namespace vsgl {

class Device;

// One mip level's texels, tightly packed rows in the image's format.
struct TextureLevel {
  uint32_t width, height;
  const void* data;
  std::size_t bytes;
};

Image2D upload_texture_levels(Device& device, VkFormat format, const std::vector<TextureLevel>& levels,
                              const std::string& name);

}  // namespace vsgl
