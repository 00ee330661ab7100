#include "harness/vk/command_stream.hpp"

#include <stdexcept>

#include "harness/vk/compute_pipeline.hpp"

namespace vsgl {

void CommandStream::dispatch(const ComputePipeline& pipeline, const BindingSet& set, const void* push,
                             uint32_t push_bytes, uint32_t groups_x, uint32_t groups_y, uint32_t groups_z) {
  vkCmdBindPipeline(cmd_, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.get());
  VkDescriptorSet ds = set.get();
  vkCmdBindDescriptorSets(cmd_, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.layout(), 0, 1, &ds, 0, nullptr);
  if (push_bytes > 0) vkCmdPushConstants(cmd_, pipeline.layout(), VK_SHADER_STAGE_COMPUTE_BIT, 0, push_bytes, push);
  vkCmdDispatch(cmd_, groups_x, groups_y, groups_z);
  ++dispatches_;
}

void CommandStream::begin_iteration() {
  if (in_iteration_) throw std::logic_error("CommandStream::begin_iteration inside an open iteration");
  in_iteration_ = true;
  iteration_start_ = dispatches_;
}

void CommandStream::end_iteration() {
  if (!in_iteration_) throw std::logic_error("CommandStream::end_iteration without begin_iteration");
  in_iteration_ = false;
  iterations_.push_back(dispatches_ - iteration_start_);
}

void CommandStream::compute_barrier() {
  VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  b.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  b.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
  vkCmdPipelineBarrier(cmd_, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &b, 0,
                       nullptr, 0, nullptr);
}

void CommandStream::full_barrier() {
  VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  b.srcAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
  b.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
  vkCmdPipelineBarrier(cmd_, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 1, &b, 0,
                       nullptr, 0, nullptr);
}

}  // namespace vsgl
