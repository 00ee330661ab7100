#include "harness/vk/texture_upload.hpp"

#include <cstring>

#include "harness/vk/buffer.hpp"
#include "harness/vk/device.hpp"

namespace vsgl {

Image2D upload_texture_levels(Device& device, VkFormat format, const std::vector<TextureLevel>& levels,
                              const std::string& name) {
  std::vector<VkDeviceSize> offsets;
  VkDeviceSize total = 0;
  for (const TextureLevel& level : levels) {
    offsets.push_back(total);
    total += level.bytes;
    total = (total + 15) & ~VkDeviceSize{15};  // keeps every level at a multiple of the texel size
  }
  Buffer staging(device, total, MemoryUsage::kUpload, name + ".staging");
  for (std::size_t l = 0; l < levels.size(); ++l)
    std::memcpy(static_cast<unsigned char*>(staging.mapped()) + offsets[l], levels[l].data, levels[l].bytes);
  const auto mip_count = static_cast<uint32_t>(levels.size());
  Image2D image(device, levels.at(0).width, levels.at(0).height, format,
                VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, VK_IMAGE_ASPECT_COLOR_BIT, name,
                mip_count);
  device.submit_and_wait(
      [&](VkCommandBuffer cmd) {
        image.change_layouts(cmd, {{0, mip_count, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL}},
                             VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
                             VK_ACCESS_TRANSFER_WRITE_BIT);
        std::vector<VkBufferImageCopy> regions(levels.size());
        for (uint32_t l = 0; l < mip_count; ++l) {
          regions[l].bufferOffset = offsets[l];
          regions[l].imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, l, 0, 1};
          regions[l].imageExtent = {levels[l].width, levels[l].height, 1};
        }
        vkCmdCopyBufferToImage(cmd, staging.get(), image.get(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, mip_count,
                               regions.data());
        image.change_layouts(cmd,
                             {{0, mip_count, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL}},
                             VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                             VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT);
      },
      "upload texture " + name);
  return image;
}

}  // namespace vsgl
