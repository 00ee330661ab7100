#pragma once
// The k-means generators on the GPU (DESIGN.md §6.2): `kmeans_2d` / `kmeans_3d` (feature: texel centre
// in pixels / world position), and the `_segsum` variants whose `sum` is a parallel segmented
// reduction (beyond the paper). Phases, as in the paper's Table 1:
//   cluster_assignment: seeding (the kernel centres of DESIGN.md §5 on the view's PDF), I Lloyd
//     iterations (grid build, exact nearest-centre assignment, sort by cluster, deterministic
//     centre update), then grid build + final assignment;
//   sort: stable LSD radix sort of (cluster id, texel index) by cluster, and each cluster's range;
//   sum: per cluster, the moments of its texels and the VSGL (DESIGN.md §7).
// The CPU reference is harness/reference/kmeans_reference.hpp.
#include <optional>

#include "harness/vk/buffer.hpp"
#include "harness/vk/compute_pipeline.hpp"
#include "harness/reference/kmeans_reference.hpp"
#include "harness/generators/vsgl_generator.hpp"

namespace vsgl {

class Device;
struct DeviceView;

class KmeansGenerator : public VsglGenerator {
 public:
  // Throws InputError for N = 0 or N larger than the view's samplable texels (naming the view),
  // and DeviceError when the device's compute limits cannot hold the sort's workgroups.
  KmeansGenerator(Device& device, const DeviceView& view, KmeansSpace space, const KmeansParams& params);

  std::string name() const override { return kmeans_generator_name(space_, params_.segmented_sum); }
  std::vector<std::string> phases() const override { return phase_names(phase_list()); }
  void record(CommandStream& stream, const std::function<void(VkCommandBuffer)>& boundary) override;
  const Buffer& vsgls() const override { return vsgls_; }
  uint32_t vsgl_count() const override { return params_.vsgl_count; }

  // table3: begin verify
  // Intermediate results, for verify and the tests:
  const Buffer& features() const { return features_; }      // W*H vec4: (feature, q), q = -1: no cluster
  const Buffer& centres() const { return centres_; }        // N vec4: the centres of the final assignment
  const Buffer& assignment() const { return assignment_; }  // W*H uint: cluster id or 0xFFFFFFFF
  const Buffer& sorted_pairs() const { return sorted_; }    // W*H uvec2: (cluster id, texel), stable
  const Buffer& ranges() const { return ranges_; }          // N uvec2: [begin, end) in sorted_pairs

  // table3: end verify

 private:
  // A multi-level exclusive scan of `count` uints starting at word `offset` of a target buffer.
  struct ScanLevel {
    uint32_t in_aux;
    uint32_t offset;
    uint32_t count;
  };
  struct ScanPlan {
    std::vector<ScanLevel> levels;
    uint32_t total_slot = 0;  // aux word receiving the grand total
    uint32_t aux_words = 0;
  };
  static ScanPlan plan_scan(uint32_t offset, uint32_t count);

  // Phases.
  static const std::vector<Phase<KmeansGenerator>>& phase_list();
  void record_cluster_assignment(CommandStream& stream);
  void record_sort(CommandStream& stream);
  void record_sum(CommandStream& stream);
  // Steps of the phases.
  void record_seeding(CommandStream& stream);
  void record_grid_build(CommandStream& stream);
  void record_assign(CommandStream& stream);
  void record_radix_sort(CommandStream& stream);
  void record_centre_update(CommandStream& stream);
  void record_scan(CommandStream& stream, const ScanPlan& plan, const BindingSet& blocks, const BindingSet& add);
  // A 1D workload of `groups` workgroups, folded into rows of at most maxComputeWorkGroupCount[0].
  template <class Push>
  void dispatch_flat(CommandStream& stream, const ComputePipeline& pipeline, const BindingSet& set, const Push& push,
                     uint32_t groups);

  Device& device_;
  const DeviceView& view_;
  KmeansSpace space_;
  KmeansParams params_;
  uint32_t texels_;         // W * H
  uint32_t max_cells_;      // capacity of the grid
  uint32_t radix_passes_;   // 8-bit digits of the largest key (N)
  uint32_t radix_rounds_;   // 256-element rounds per tile
  uint32_t radix_tiles_;
  uint32_t pieces_;         // slots of the chunked segmented sums
  ScanPlan grid_scan_;
  ScanPlan radix_scan_;

  Buffer features_;
  Buffer pdf_pyramid_;
  Buffer grid_;        // bounds, cell counts/starts, fill cursors (kernels/include/kmeans_grid.glsl)
  Buffer cell_items_;
  Buffer centres_;
  Buffer assignment_;
  Buffer sorted_;
  Buffer sort_scratch_;
  Buffer histogram_;
  Buffer scan_aux_;
  Buffer ranges_;
  Buffer centre_pieces_;
  Buffer vsgls_;
  // table3: begin segmented_sum
  std::optional<Buffer> sum_pieces_;
  // table3: end segmented_sum

  ComputePipeline fill_;
  ComputePipeline prepare_;
  ComputePipeline pdf_mip_;
  ComputePipeline seed_;
  ComputePipeline grid_count_;
  ComputePipeline grid_fill_;
  ComputePipeline assign_;
  ComputePipeline scan_blocks_;
  ComputePipeline scan_add_;
  ComputePipeline radix_histogram_;
  ComputePipeline radix_scatter_;
  ComputePipeline ranges_pipeline_;
  ComputePipeline update_pieces_;
  ComputePipeline update_centres_;
  // table3: begin sequential_sum
  std::optional<ComputePipeline> sum_;
  // table3: end sequential_sum
  // table3: begin segmented_sum
  std::optional<ComputePipeline> segsum_pieces_;
  std::optional<ComputePipeline> segsum_clusters_;
  // table3: end segmented_sum

  BindingSet fill_grid_set_;
  BindingSet prepare_set_;
  BindingSet pdf_mip_set_;
  BindingSet seed_set_;
  BindingSet grid_count_set_;
  BindingSet grid_fill_set_;
  BindingSet assign_set_;
  BindingSet scan_blocks_grid_set_;
  BindingSet scan_add_grid_set_;
  BindingSet scan_blocks_radix_set_;
  BindingSet scan_add_radix_set_;
  BindingSet histogram_to_sorted_set_;  // source = scratch, destination = sorted
  BindingSet histogram_to_scratch_set_;
  BindingSet scatter_to_sorted_set_;
  BindingSet scatter_to_scratch_set_;
  BindingSet ranges_set_;
  BindingSet update_pieces_set_;
  BindingSet update_centres_set_;
  // table3: begin sequential_sum
  std::optional<BindingSet> sum_set_;
  // table3: end sequential_sum
  // table3: begin segmented_sum
  std::optional<BindingSet> segsum_pieces_set_;
  std::optional<BindingSet> segsum_clusters_set_;
  // table3: end segmented_sum
};

}  // namespace vsgl
