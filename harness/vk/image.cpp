#include "harness/vk/image.hpp"

#include "harness/vk/device.hpp"
#include "harness/vk/vk_check.hpp"

namespace vsgl {

Image2D::Image2D(Device& device, uint32_t width, uint32_t height, VkFormat format, VkImageUsageFlags usage,
                 VkImageAspectFlags aspect, const std::string& name, uint32_t mip_levels)
    : format_(format), width_(width), height_(height), mip_levels_(mip_levels) {
  VkDevice dev = device.get();
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {width, height, 1};
  info.mipLevels = mip_levels;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkImage image = VK_NULL_HANDLE;
  VK_CHECK(vkCreateImage(dev, &info, nullptr, &image));
  image_ = UniqueHandle<VkImage>(dev, image, vkDestroyImage);
  device.set_name(image, VK_OBJECT_TYPE_IMAGE, name);

  VkMemoryRequirements req{};
  vkGetImageMemoryRequirements(dev, image, &req);
  memory_ = device.allocate_memory(req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, 0, "image " + name);
  VkDeviceMemory memory = memory_.get();
  VK_CHECK(vkBindImageMemory(dev, image, memory, 0));

  VkImageViewCreateInfo view_info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  view_info.image = image;
  view_info.viewType = VK_IMAGE_VIEW_TYPE_2D;
  view_info.format = format;
  view_info.subresourceRange = {aspect, 0, mip_levels, 0, 1};
  VkImageView view = VK_NULL_HANDLE;
  VK_CHECK(vkCreateImageView(dev, &view_info, nullptr, &view));
  view_ = UniqueHandle<VkImageView>(dev, view, vkDestroyImageView);
  device.set_name(view, VK_OBJECT_TYPE_IMAGE_VIEW, name + ".view");
}

}  // namespace vsgl
