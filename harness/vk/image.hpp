#pragma once
// A 2D image with its own memory and one view over all its mip levels: the recorder's render
// targets and the scenes' textures.
#include <vulkan/vulkan.h>

#include <string>

#include "harness/vk/unique_handle.hpp"

namespace vsgl {

class Device;

class Image2D {
 public:
  Image2D(Device& device, uint32_t width, uint32_t height, VkFormat format, VkImageUsageFlags usage,
          VkImageAspectFlags aspect, const std::string& name, uint32_t mip_levels = 1);
  Image2D(Image2D&&) noexcept = default;
  Image2D& operator=(Image2D&&) noexcept = default;

  VkImage get() const { return image_.get(); }
  VkImageView view() const { return view_.get(); }
  VkFormat format() const { return format_; }
  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }
  uint32_t mip_levels() const { return mip_levels_; }

 private:
  // Declared so that destruction runs view, image, then memory.
  UniqueHandle<VkDeviceMemory> memory_;
  UniqueHandle<VkImage> image_;
  UniqueHandle<VkImageView> view_;
  VkFormat format_;
  uint32_t width_, height_, mip_levels_;
};

}  // namespace vsgl
