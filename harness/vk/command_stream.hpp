#pragma once
// Records compute work into a command buffer and counts what it records: the dispatch count of
// Table 3 is what this class saw, not a typed-in number.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

namespace vsgl {

class BindingSet;
class ComputePipeline;

class CommandStream {
 public:
  explicit CommandStream(VkCommandBuffer cmd) : cmd_(cmd) {}

  VkCommandBuffer get() const { return cmd_; }

  void dispatch(const ComputePipeline& pipeline, const BindingSet& set, const void* push, uint32_t push_bytes,
                uint32_t groups_x, uint32_t groups_y = 1, uint32_t groups_z = 1);
  template <class Push>
  void dispatch(const ComputePipeline& pipeline, const BindingSet& set, const Push& push, uint32_t groups_x,
                uint32_t groups_y = 1, uint32_t groups_z = 1) {
    dispatch(pipeline, set, &push, sizeof(Push), groups_x, groups_y, groups_z);
  }

  // Compute writes -> later compute reads/writes (between dependent passes).
  void compute_barrier();
  // Everything before -> everything after (phase boundaries, before timestamps).
  void full_barrier();

  uint32_t dispatch_count() const { return dispatches_; }

  // One iteration of a repeated block (k-means' Lloyd iterations) opens and closes around its
  // recording, so Table 3 gives the dispatches per iteration beside the total (DESIGN.md §10).
  // Throws std::logic_error for a nested begin or an end without a begin.
  void begin_iteration();
  void end_iteration();
  // The dispatches each closed iteration recorded, in order.
  const std::vector<uint32_t>& iteration_dispatches() const { return iterations_; }

 private:
  VkCommandBuffer cmd_;
  uint32_t dispatches_ = 0;
  std::vector<uint32_t> iterations_;
  bool in_iteration_ = false;
  uint32_t iteration_start_ = 0;
};

inline uint32_t div_up(uint32_t n, uint32_t d) { return (n + d - 1) / d; }

}  // namespace vsgl
