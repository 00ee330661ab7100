#include "harness/vk/image.hpp"

#include "harness/vk/device.hpp"
#include "harness/core/error.hpp"
#include "harness/vk/vk_check.hpp"

namespace vsgl {

namespace {

// A device-local image with its memory bound, named: what every image of the harness starts as.
// The info's common fields (2D, one sample, optimal tiling, exclusive, undefined layout) are set here.
VkImage create_bound_image(Device& device, VkImageCreateInfo info, const std::string& name,
                           UniqueHandle<VkImage>& image_out, UniqueHandle<VkDeviceMemory>& memory_out) {
  VkDevice dev = device.get();
  info.imageType = VK_IMAGE_TYPE_2D;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkImage image = VK_NULL_HANDLE;
  VK_CHECK(vkCreateImage(dev, &info, nullptr, &image));
  image_out = UniqueHandle<VkImage>(dev, image, vkDestroyImage);
  device.set_name(image, VK_OBJECT_TYPE_IMAGE, name);
  VkMemoryRequirements req{};
  vkGetImageMemoryRequirements(dev, image, &req);
  memory_out = device.allocate_memory(req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, 0, "image " + name);
  VK_CHECK(vkBindImageMemory(dev, image, memory_out.get(), 0));
  return image;
}

}  // namespace

Image2D::Image2D(Device& device, uint32_t width, uint32_t height, VkFormat format, VkImageUsageFlags usage,
                 VkImageAspectFlags aspect, const std::string& name, uint32_t mip_levels)
    : format_(format), aspect_(aspect), width_(width), height_(height), mip_levels_(mip_levels) {
  VkDevice dev = device.get();
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.format = format;
  info.extent = {width, height, 1};
  info.mipLevels = mip_levels;
  info.arrayLayers = 1;
  info.usage = usage;
  const VkImage image = create_bound_image(device, info, name, image_, memory_);

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

namespace vsgl {

MipImage::MipImage(Device& device, uint32_t size, uint32_t levels, uint32_t layers, VkFormat format,
                   VkImageUsageFlags usage, const std::string& name)
    : format_(format), size_(size), levels_(levels), layers_(layers) {
  const DeviceLimits& limits = device.info().limits;
  if (size > limits.image_dimension_2d)
    throw DeviceLimitError(device.info().name + " cannot create image '" + name + "': it needs " +
                           std::to_string(size) + " texels per side where the device allows " +
                           std::to_string(limits.image_dimension_2d) + " (maxImageDimension2D)");
  if (layers > limits.image_array_layers)
    throw DeviceError(device.info().name + " cannot create image '" + name + "': it needs " + std::to_string(layers) +
                      " array layers where the device allows " + std::to_string(limits.image_array_layers) +
                      " (maxImageArrayLayers)");
  VkDevice dev = device.get();
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.format = format;
  info.extent = {size, size, 1};
  info.mipLevels = levels;
  info.arrayLayers = layers;
  info.usage = usage | VK_IMAGE_USAGE_TRANSFER_DST_BIT;  // the clear at creation
  const VkImage image = create_bound_image(device, info, name, image_, memory_);

  auto make_view = [&](uint32_t base, uint32_t count, const std::string& view_name) {
    VkImageViewCreateInfo v{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    v.image = image;
    v.viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
    v.format = format;
    v.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, base, count, 0, layers};
    VkImageView handle = VK_NULL_HANDLE;
    VK_CHECK(vkCreateImageView(dev, &v, nullptr, &handle));
    device.set_name(handle, VK_OBJECT_TYPE_IMAGE_VIEW, view_name);
    return UniqueHandle<VkImageView>(dev, handle, vkDestroyImageView);
  };
  view_ = make_view(0, levels, name + ".view");
  for (uint32_t l = 0; l < levels; ++l) level_views_.push_back(make_view(l, 1, name + ".level" + std::to_string(l)));

  // Untimed: every texel zero (the padding of the virtual square stays so), layout GENERAL.
  device.submit_and_wait(
      [&](VkCommandBuffer cmd) {
        const VkImageSubresourceRange all{VK_IMAGE_ASPECT_COLOR_BIT, 0, levels, 0, layers};
        change_layouts(cmd, {{0, levels, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL}},
                       VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
        const VkClearColorValue zero{};
        vkCmdClearColorImage(cmd, image, VK_IMAGE_LAYOUT_GENERAL, &zero, 1, &all);
        VkMemoryBarrier m{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        m.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        m.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 1, &m, 0,
                             nullptr, 0, nullptr);
      },
      "clearing " + name);
}

Sampler::Sampler(Device& device, const VkSamplerCreateInfo& info, const std::string& name) {
  VkSampler sampler = VK_NULL_HANDLE;
  VK_CHECK(vkCreateSampler(device.get(), &info, nullptr, &sampler));
  sampler_ = UniqueHandle<VkSampler>(device.get(), sampler, vkDestroySampler);
  device.set_name(sampler, VK_OBJECT_TYPE_SAMPLER, name);
}

void change_image_layouts(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, uint32_t layers,
                          const std::vector<ImageLevelLayout>& changes, VkPipelineStageFlags src_stages,
                          VkAccessFlags src_access, VkPipelineStageFlags dst_stages, VkAccessFlags dst_access) {
  std::vector<VkImageMemoryBarrier> barriers;
  for (const ImageLevelLayout& c : changes) {
    VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    b.srcAccessMask = src_access;
    b.dstAccessMask = dst_access;
    b.oldLayout = c.from;
    b.newLayout = c.to;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {aspect, c.base, c.count, 0, layers};
    barriers.push_back(b);
  }
  vkCmdPipelineBarrier(cmd, src_stages, dst_stages, 0, 0, nullptr, 0, nullptr, static_cast<uint32_t>(barriers.size()),
                       barriers.data());
}

void MipImage::change_layouts(VkCommandBuffer cmd, const std::vector<LevelLayout>& changes,
                              VkPipelineStageFlags src_stages, VkAccessFlags src_access,
                              VkPipelineStageFlags dst_stages, VkAccessFlags dst_access) const {
  change_image_layouts(cmd, image_.get(), VK_IMAGE_ASPECT_COLOR_BIT, layers_, changes, src_stages, src_access,
                       dst_stages, dst_access);
}

void Image2D::change_layouts(VkCommandBuffer cmd, const std::vector<ImageLevelLayout>& changes,
                             VkPipelineStageFlags src_stages, VkAccessFlags src_access,
                             VkPipelineStageFlags dst_stages, VkAccessFlags dst_access) const {
  change_image_layouts(cmd, image_.get(), aspect_, 1, changes, src_stages, src_access, dst_stages, dst_access);
}

}  // namespace vsgl
