#pragma once
// A 2D image with its own memory and one view over all its mip levels: the recorder's render
// targets and the scenes' textures.
#include <vulkan/vulkan.h>

#include <string>
#include <vector>

#include "harness/vk/unique_handle.hpp"

namespace vsgl {

class Device;

// Levels [base, base + count) of every layer of an image, from one layout to another.
struct ImageLevelLayout {
  uint32_t base, count;
  VkImageLayout from, to;
};

// One vkCmdPipelineBarrier with an image barrier per entry over `layers` array layers of `aspect`;
// the contents are kept.
void change_image_layouts(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, uint32_t layers,
                          const std::vector<ImageLevelLayout>& changes, VkPipelineStageFlags src_stages,
                          VkAccessFlags src_access, VkPipelineStageFlags dst_stages, VkAccessFlags dst_access);

class Image2D {
 public:
  Image2D(Device& device, uint32_t width, uint32_t height, VkFormat format, VkImageUsageFlags usage,
          VkImageAspectFlags aspect, const std::string& name, uint32_t mip_levels = 1);
  Image2D(Image2D&&) noexcept = default;
  Image2D& operator=(Image2D&&) noexcept = default;

  // Levels of the image from one layout to another (change_image_layouts).
  void change_layouts(VkCommandBuffer cmd, const std::vector<ImageLevelLayout>& changes, VkPipelineStageFlags src_stages,
                      VkAccessFlags src_access, VkPipelineStageFlags dst_stages, VkAccessFlags dst_access) const;

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
  VkImageAspectFlags aspect_;
  uint32_t width_, height_, mip_levels_;
};

}  // namespace vsgl

namespace vsgl {

// A 2D array image with a full mip chain: the sampled-image pyramid of DESIGN.md §6.1a (array layers =
// moment layers). One view of every level and layer (for sampling) and one per level (for
// storage writes). Created in VK_IMAGE_LAYOUT_GENERAL with every texel zero. The compute passes
// and the sampling keep it there (storage images need GENERAL); transfers (the blit chain, the
// readback) move the levels they touch to the TRANSFER_SRC/DST layouts and back, as a real
// renderer's mip generation does (GENERAL may cost compression on some GPUs).
class MipImage {
 public:
  // Levels [base, base + count) of every layer, from one layout to another.
  using LevelLayout = ImageLevelLayout;
  // One vkCmdPipelineBarrier with an image barrier per entry; the contents are kept.
  void change_layouts(VkCommandBuffer cmd, const std::vector<LevelLayout>& changes, VkPipelineStageFlags src_stages,
                      VkAccessFlags src_access, VkPipelineStageFlags dst_stages, VkAccessFlags dst_access) const;

  MipImage(Device& device, uint32_t size, uint32_t levels, uint32_t layers, VkFormat format, VkImageUsageFlags usage,
           const std::string& name);
  MipImage(MipImage&&) noexcept = default;
  MipImage& operator=(MipImage&&) noexcept = default;

  VkImage get() const { return image_.get(); }
  VkImageView view() const { return view_.get(); }                    // all levels and layers
  VkImageView level_view(uint32_t level) const { return level_views_.at(level).get(); }
  VkFormat format() const { return format_; }
  uint32_t size() const { return size_; }  // side of level 0 (square)
  uint32_t levels() const { return levels_; }
  uint32_t layers() const { return layers_; }

 private:
  UniqueHandle<VkDeviceMemory> memory_;
  UniqueHandle<VkImage> image_;
  UniqueHandle<VkImageView> view_;
  std::vector<UniqueHandle<VkImageView>> level_views_;
  VkFormat format_;
  uint32_t size_, levels_, layers_;
};

// A sampler object (RAII).
class Sampler {
 public:
  Sampler(Device& device, const VkSamplerCreateInfo& info, const std::string& name);
  VkSampler get() const { return sampler_.get(); }

 private:
  UniqueHandle<VkSampler> sampler_;
};

}  // namespace vsgl
