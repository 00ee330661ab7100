#include "harness/generators/kmeans/kmeans_generator.hpp"

#include <algorithm>
#include <bit>

#include "harness/vk/command_stream.hpp"
#include "harness/vk/device.hpp"
#include "harness/generators/device_view.hpp"
#include "harness/generators/kmeans/kmeans_descriptor.hpp"
#include "harness/core/error.hpp"
#include "harness/math/vsgl_math.hpp"
#include "kernels/include/interface/kmeans.h"

namespace vsgl {
namespace {

// Work-group sizes and push constants: kernels/include/interface/kmeans.h, shared with the kernels.
constexpr uint32_t kTile = gpu::kKmeansImageGroupSize;  // kTile x kTile: per-texel passes over the image
constexpr uint32_t kWide = gpu::kKmeansWideGroupSize;   // fill, assign, scan
constexpr uint32_t kNarrow = gpu::kKmeansNarrowGroupSize;  // per-centre / per-cluster / per-chunk passes
constexpr uint32_t kRadix = gpu::kKmeansRadix;          // 8-bit digits
constexpr uint32_t kRadixGroup = gpu::kKmeansRadixGroupSize;  // one radix-kernel thread per digit
constexpr uint32_t kScanBlock = kWide * gpu::kKmeansScanItems;  // values per kmeans_scan_blocks group
constexpr uint32_t kRadixRounds = 8;    // 2048 elements per tile
// Radix scatter's shared memory: a cursor per digit and a kRadix-bit mask per digit.
constexpr uint32_t kRadixSharedBytes = (kRadix + kRadix * (kRadix / 32)) * 4;
// The largest work group of the k-means kernels.
constexpr uint32_t kLargestGroup = std::max({kTile * kTile, kWide, kNarrow, kRadixGroup});
// kernels/include/kmeans_grid.glsl: KMEANS_CELLS_PER_CENTRE cells per centre are aimed at; ceil()
// of the per-axis counts can multiply that by up to 2^3.
constexpr uint32_t kCellsPerCentre = 2;
constexpr uint32_t kGridCounts = 8;  // KMEANS_GRID_COUNTS: words before the cell counts

using gpu::KmeansAssignPush;
using gpu::KmeansFillPush;
using gpu::KmeansGridPush;
using gpu::KmeansMipPush;
using gpu::KmeansPiecesPush;
using gpu::KmeansPreparePush;
using gpu::KmeansRadixPush;
using gpu::KmeansRangesPush;
using gpu::KmeansScanPush;
using gpu::KmeansSeedPush;
using gpu::KmeansSumPush;
using gpu::KmeansUpdatePush;

// A k-means kernel: its storage buffers, push constants and 1D work-group size.
ComputePipelineDesc kernel_1d(KmeansKernel kernel, uint32_t buffers, uint32_t push_bytes, uint32_t group) {
  return {kmeans_kernel_file(kernel), buffers, push_bytes, work_group_size_1d(group)};
}

KmeansParams checked(const KmeansParams& p, const DeviceView& view, KmeansSpace space) {
  const std::string name = kmeans_generator_name(space, p.segmented_sum);
  if (p.vsgl_count == 0) throw InputError(name + ": N = 0: at least one VSGL is needed");
  if (p.vsgl_count > view.samplable_texels)
    throw InputError(name + ": N = " + std::to_string(p.vsgl_count) + " is larger than the " +
                     std::to_string(view.samplable_texels) + " valid texels with nonzero PDF of the " + view.label);
  return p;
}

uint32_t device_checked_texels(const Device& device, const DeviceView& view) {
  if (device.info().max_shared_memory < kRadixSharedBytes)
    throw DeviceError("k-means: the radix sort needs " + std::to_string(kRadixSharedBytes) +
                      " bytes of shared memory per workgroup; " + device.info().name + " offers " +
                      std::to_string(device.info().max_shared_memory));
  if (device.info().max_workgroup_invocations < kLargestGroup)
    throw DeviceError("k-means: workgroups of " + std::to_string(kLargestGroup) + " invocations are not supported by " +
                      device.info().name);
  return view.square.width * view.square.height;
}

template <class T>
VkDeviceSize bytes(uint64_t count) {
  return VkDeviceSize{count * sizeof(T)};
}

}  // namespace

KmeansGenerator::ScanPlan KmeansGenerator::plan_scan(uint32_t offset, uint32_t count) {
  ScanPlan plan;
  plan.levels.push_back({0u, offset, count});
  while (plan.levels.back().count > kScanBlock) {
    const uint32_t blocks = div_up(plan.levels.back().count, kScanBlock);
    plan.levels.push_back({1u, plan.aux_words, blocks});
    plan.aux_words += blocks;
  }
  plan.total_slot = plan.aux_words++;
  return plan;
}

KmeansGenerator::KmeansGenerator(Device& device, const DeviceView& view, KmeansSpace space, const KmeansParams& params)
    : device_(device),
      view_(view),
      space_(space),
      params_(checked(params, view, space)),
      texels_(device_checked_texels(device, view)),
      max_cells_(params.brute_force_grid ? 1u : 8 * kCellsPerCentre * params.vsgl_count),
      radix_passes_(std::max(1u, div_up(static_cast<uint32_t>(std::bit_width(params.vsgl_count)), 8))),
      radix_rounds_(kRadixRounds),
      radix_tiles_(div_up(texels_, kRadix * kRadixRounds)),
      pieces_(div_up(texels_, kKmeansChunk) + params.vsgl_count),
      grid_scan_(plan_scan(kGridCounts, max_cells_ + 1)),
      radix_scan_(plan_scan(0, kRadix * radix_tiles_)),
      features_(device, bytes<glm::vec4>(texels_), MemoryUsage::kDeviceLocal, name() + ".features"),
      pdf_pyramid_(device, bytes<glm::vec4>(view.square.total_texels()), MemoryUsage::kDeviceLocal,
                   name() + ".pdf_pyramid"),
      grid_(device, bytes<uint32_t>(kGridCounts + 2ull * max_cells_ + 1), MemoryUsage::kDeviceLocal, name() + ".grid"),
      cell_items_(device, bytes<uint32_t>(params.vsgl_count), MemoryUsage::kDeviceLocal, name() + ".cell_items"),
      centres_(device, bytes<glm::vec4>(params.vsgl_count), MemoryUsage::kDeviceLocal, name() + ".centres"),
      assignment_(device, bytes<uint32_t>(texels_), MemoryUsage::kDeviceLocal, name() + ".assignment"),
      sorted_(device, bytes<glm::uvec2>(texels_), MemoryUsage::kDeviceLocal, name() + ".sorted"),
      sort_scratch_(device, bytes<glm::uvec2>(texels_), MemoryUsage::kDeviceLocal, name() + ".sort_scratch"),
      histogram_(device, bytes<uint32_t>(uint64_t{kRadix} * radix_tiles_), MemoryUsage::kDeviceLocal,
                 name() + ".histogram"),
      scan_aux_(device, bytes<uint32_t>(std::max(grid_scan_.aux_words, radix_scan_.aux_words)),
                MemoryUsage::kDeviceLocal, name() + ".scan_aux"),
      ranges_(device, bytes<glm::uvec2>(params.vsgl_count), MemoryUsage::kDeviceLocal, name() + ".ranges"),
      centre_pieces_(device, bytes<glm::vec4>(pieces_), MemoryUsage::kDeviceLocal, name() + ".centre_pieces"),
      vsgls_(device, bytes<VsglRecord>(params.vsgl_count), MemoryUsage::kDeviceLocal,
             name() + "." + view.label + ".vsgls"),
      fill_(device, kernel_1d(KmeansKernel::kFill, 1, sizeof(KmeansFillPush), kWide)),
      prepare_(device, {kmeans_kernel_file(KmeansKernel::kPrepare), 4, sizeof(KmeansPreparePush),
                        work_group_size_2d(kTile, kTile)}),
      pdf_mip_(device,
               {kmeans_kernel_file(KmeansKernel::kPdfMip), 1, sizeof(KmeansMipPush), work_group_size_2d(kTile, kTile)}),
      seed_(device, kernel_1d(KmeansKernel::kSeed, 3, sizeof(KmeansSeedPush), kNarrow)),
      grid_count_(device, kernel_1d(KmeansKernel::kGridCount, 2, sizeof(KmeansGridPush), kNarrow)),
      grid_fill_(device, kernel_1d(KmeansKernel::kGridFill, 3, sizeof(KmeansGridPush), kNarrow)),
      assign_(device, kernel_1d(KmeansKernel::kAssign, 5, sizeof(KmeansAssignPush), kWide)),
      scan_blocks_(device, kernel_1d(KmeansKernel::kScanBlocks, 2, sizeof(KmeansScanPush), kWide)),
      scan_add_(device, kernel_1d(KmeansKernel::kScanAdd, 2, sizeof(KmeansScanPush), kWide)),
      radix_histogram_(device, kernel_1d(KmeansKernel::kRadixHistogram, 4, sizeof(KmeansRadixPush), kRadixGroup)),
      radix_scatter_(device, kernel_1d(KmeansKernel::kRadixScatter, 4, sizeof(KmeansRadixPush), kRadixGroup)),
      ranges_pipeline_(device, kernel_1d(KmeansKernel::kRanges, 2, sizeof(KmeansRangesPush), kNarrow)),
      update_pieces_(device, kernel_1d(KmeansKernel::kUpdatePieces, 3, sizeof(KmeansPiecesPush), kNarrow)),
      update_centres_(device, kernel_1d(KmeansKernel::kUpdateCentres, 3, sizeof(KmeansUpdatePush), kNarrow)),
      fill_grid_set_(device, fill_, {grid_}, name() + ".fill"),
      prepare_set_(device, prepare_, buffer_bindings({view.layers(), {features_}, {pdf_pyramid_}, {grid_}}),
                   name() + ".prepare"),
      pdf_mip_set_(device, pdf_mip_, {pdf_pyramid_}, name() + ".pdf_mip"),
      seed_set_(device, seed_, buffer_bindings({{pdf_pyramid_}, view.layers(), {centres_}}), name() + ".seed"),
      grid_count_set_(device, grid_count_, {grid_, centres_}, name() + ".grid_count"),
      grid_fill_set_(device, grid_fill_, {grid_, centres_, cell_items_}, name() + ".grid_fill"),
      assign_set_(device, assign_, {grid_, centres_, cell_items_, features_, assignment_}, name() + ".assign"),
      scan_blocks_grid_set_(device, scan_blocks_, {grid_, scan_aux_}, name() + ".scan_blocks.grid"),
      scan_add_grid_set_(device, scan_add_, {grid_, scan_aux_}, name() + ".scan_add.grid"),
      scan_blocks_radix_set_(device, scan_blocks_, {histogram_, scan_aux_}, name() + ".scan_blocks.radix"),
      scan_add_radix_set_(device, scan_add_, {histogram_, scan_aux_}, name() + ".scan_add.radix"),
      histogram_to_sorted_set_(device, radix_histogram_, {assignment_, sort_scratch_, sorted_, histogram_},
                               name() + ".radix_histogram.a"),
      histogram_to_scratch_set_(device, radix_histogram_, {assignment_, sorted_, sort_scratch_, histogram_},
                                name() + ".radix_histogram.b"),
      scatter_to_sorted_set_(device, radix_scatter_, {assignment_, sort_scratch_, sorted_, histogram_},
                             name() + ".radix_scatter.a"),
      scatter_to_scratch_set_(device, radix_scatter_, {assignment_, sorted_, sort_scratch_, histogram_},
                              name() + ".radix_scatter.b"),
      ranges_set_(device, ranges_pipeline_, {sorted_, ranges_}, name() + ".ranges"),
      update_pieces_set_(device, update_pieces_, {sorted_, features_, centre_pieces_}, name() + ".update_pieces"),
      update_centres_set_(device, update_centres_, {ranges_, centre_pieces_, centres_}, name() + ".update_centres") {
  // table3: begin segmented_sum
  if (params_.segmented_sum) {
    sum_pieces_.emplace(device, bytes<glm::vec4>(uint64_t{gpu::kKmeansPieceVec4s} * pieces_), MemoryUsage::kDeviceLocal,
                        name() + ".sum_pieces");
    segsum_pieces_.emplace(device, kernel_1d(KmeansKernel::kSegsumPieces, 3, sizeof(KmeansSumPush), kNarrow));
    segsum_clusters_.emplace(device, kernel_1d(KmeansKernel::kSegsumClusters, 4, sizeof(KmeansSumPush), kNarrow));
    segsum_pieces_set_.emplace(device, *segsum_pieces_, buffer_bindings({view.layers(), {sorted_}, {*sum_pieces_}}),
                               name() + ".segsum_pieces");
    segsum_clusters_set_.emplace(device, *segsum_clusters_,
                                 std::initializer_list<BufferBinding>{ranges_, *sum_pieces_, centres_, vsgls_},
                                 name() + ".segsum_clusters");
    return;
  }
  // table3: end segmented_sum
  // table3: begin sequential_sum
  sum_.emplace(device, kernel_1d(KmeansKernel::kSum, 5, sizeof(KmeansSumPush), kNarrow));
  sum_set_.emplace(device, *sum_, buffer_bindings({view.layers(), {sorted_}, {ranges_}, {centres_}, {vsgls_}}),
                   name() + ".sum");
  // table3: end sequential_sum
}

template <class Push>
void KmeansGenerator::dispatch_flat(CommandStream& stream, const ComputePipeline& pipeline, const BindingSet& set,
                                    const Push& push, uint32_t groups) {
  const uint32_t max_x = std::max(1u, device_.info().max_workgroup_count[0]);
  const uint32_t gx = std::min(std::max(groups, 1u), max_x);
  stream.dispatch(pipeline, set, push, gx, div_up(std::max(groups, 1u), gx));
}

// The paper's k-means baseline, in order: cluster assignment (seeding and Lloyd iterations), the
// sort of the texels by cluster, and the per-cluster sums that are the VSGLs.
const std::vector<VsglGenerator::Phase<KmeansGenerator>>& KmeansGenerator::phase_list() {
  static const std::vector<Phase<KmeansGenerator>> phases{
      {"cluster_assignment", &KmeansGenerator::record_cluster_assignment},
      {"sort", &KmeansGenerator::record_sort},
      {"sum", &KmeansGenerator::record_sum},
  };
  return phases;
}

void KmeansGenerator::record(CommandStream& stream, const std::function<void(VkCommandBuffer)>& boundary) {
  record_phases(*this, stream, boundary, phase_list());
}

// Seeding, then I Lloyd iterations (assign -> sort by cluster -> centre update), then the final
// assignment. The centre update needs the texels grouped by cluster; it reuses the `sort` phase's
// radix sort, and sums in a fixed chunked order (kmeans_update_pieces.comp) instead of float
// atomics, so the centres are the same on every run.
void KmeansGenerator::record_cluster_assignment(CommandStream& stream) {
  record_seeding(stream);
  for (uint32_t it = 0; it < params_.iterations; ++it) {
    stream.begin_iteration();  // Table 3: dispatches per iteration, as recorded
    stream.compute_barrier();
    record_grid_build(stream);
    stream.compute_barrier();
    record_assign(stream);
    stream.compute_barrier();
    record_radix_sort(stream);
    stream.compute_barrier();
    record_centre_update(stream);
    stream.end_iteration();
  }
  stream.compute_barrier();
  record_grid_build(stream);
  stream.compute_barrier();
  record_assign(stream);
}

void KmeansGenerator::record_sort(CommandStream& stream) { record_radix_sort(stream); }

void KmeansGenerator::record_sum(CommandStream& stream) {
  const VirtualSquare& sq = view_.square;
  const KmeansSumPush push{sq.width,
                     sq.height,
                     texels_,
                     params_.vsgl_count,
                     kKmeansChunk,
                     view_.kind == ViewKind::kCamera ? 1u : 0u,
                     space_ == KmeansSpace::k3d ? 1u : 0u,
                     sq.size,
                     glm::vec4(view_.source_position, 0.0f)};
  // table3: begin sequential_sum
  if (!params_.segmented_sum) {
    // The paper's Sum: one thread per cluster, its texels one after another.
    dispatch_flat(stream, *sum_, *sum_set_, push, div_up(params_.vsgl_count, kNarrow));
    return;
  }
  // table3: end sequential_sum
  // table3: begin segmented_sum
  dispatch_flat(stream, *segsum_pieces_, *segsum_pieces_set_, push, div_up(div_up(texels_, kKmeansChunk), kNarrow));
  stream.compute_barrier();
  dispatch_flat(stream, *segsum_clusters_, *segsum_clusters_set_, push, div_up(params_.vsgl_count, kNarrow));
  // table3: end segmented_sum
}

// Features, PDF pyramid level 0 and feature bounds; the PDF pyramid; the seeds (DESIGN.md §5).
void KmeansGenerator::record_seeding(CommandStream& stream) {
  const VirtualSquare& sq = view_.square;
  const uint32_t space3d = space_ == KmeansSpace::k3d ? 1u : 0u;
  dispatch_flat(stream, fill_, fill_grid_set_, KmeansFillPush{0, kGridCounts, 0u}, 1);  // bounds := empty
  stream.compute_barrier();
  const KmeansPreparePush prepare{sq.width, sq.height, view_.kind == ViewKind::kCamera ? 1u : 0u, space3d,
                            glm::vec4(view_.source_position, 0.0f)};
  stream.dispatch(prepare_, prepare_set_, prepare, div_up(sq.width, kTile), div_up(sq.height, kTile));
  for (uint32_t l = 0; l < sq.levels; ++l) {
    stream.compute_barrier();
    stream.dispatch(pdf_mip_, pdf_mip_set_, KmeansMipPush{sq.width, sq.height, l}, div_up(sq.level_width(l + 1), kTile),
                    div_up(sq.level_height(l + 1), kTile));
  }
  stream.compute_barrier();
  dispatch_flat(stream, seed_, seed_set_,
                KmeansSeedPush{sq.width, sq.height, params_.vsgl_count, params_.offset_bits, space3d},
                div_up(params_.vsgl_count, kNarrow));
}

// The uniform grid over the centres: clear -> count per cell -> exclusive scan -> scatter ids.
void KmeansGenerator::record_grid_build(CommandStream& stream) {
  const uint32_t words = 2 * max_cells_ + 1;
  dispatch_flat(stream, fill_, fill_grid_set_, KmeansFillPush{kGridCounts, words, 0u}, div_up(words, kWide));
  stream.compute_barrier();
  const KmeansGridPush push{params_.vsgl_count, max_cells_};
  dispatch_flat(stream, grid_count_, grid_count_set_, push, div_up(params_.vsgl_count, kNarrow));
  stream.compute_barrier();
  record_scan(stream, grid_scan_, scan_blocks_grid_set_, scan_add_grid_set_);
  stream.compute_barrier();
  dispatch_flat(stream, grid_fill_, grid_fill_set_, push, div_up(params_.vsgl_count, kNarrow));
}

void KmeansGenerator::record_assign(CommandStream& stream) {
  dispatch_flat(stream, assign_, assign_set_, KmeansAssignPush{texels_, params_.vsgl_count, max_cells_},
                div_up(texels_, kWide));
}

void KmeansGenerator::record_scan(CommandStream& stream, const ScanPlan& plan, const BindingSet& blocks,
                                  const BindingSet& add) {
  const auto& lv = plan.levels;
  for (std::size_t k = 0; k < lv.size(); ++k) {
    if (k > 0) stream.compute_barrier();
    const uint32_t out = k + 1 < lv.size() ? lv[k + 1].offset : plan.total_slot;
    dispatch_flat(stream, scan_blocks_, blocks, KmeansScanPush{lv[k].in_aux, lv[k].offset, lv[k].count, out},
                  div_up(lv[k].count, kScanBlock));
  }
  for (std::size_t k = lv.size() - 1; k-- > 0;) {
    stream.compute_barrier();
    dispatch_flat(stream, scan_add_, add, KmeansScanPush{lv[k].in_aux, lv[k].offset, lv[k].count, lv[k + 1].offset},
                  div_up(lv[k].count, kScanBlock));
  }
}

// Stable LSD radix sort of (assignment[i], i) by sort key, 8 bits per pass (histogram -> scan ->
// scatter), ping-ponging so that the last pass lands in sorted_; then each cluster's range.
void KmeansGenerator::record_radix_sort(CommandStream& stream) {
  for (uint32_t p = 0; p < radix_passes_; ++p) {
    const bool to_sorted = (radix_passes_ - 1 - p) % 2 == 0;
    const KmeansRadixPush push{texels_, params_.vsgl_count, 8 * p, p == 0 ? 1u : 0u, radix_tiles_, radix_rounds_};
    if (p > 0) stream.compute_barrier();
    dispatch_flat(stream, radix_histogram_, to_sorted ? histogram_to_sorted_set_ : histogram_to_scratch_set_, push,
                  radix_tiles_);
    stream.compute_barrier();
    record_scan(stream, radix_scan_, scan_blocks_radix_set_, scan_add_radix_set_);
    stream.compute_barrier();
    dispatch_flat(stream, radix_scatter_, to_sorted ? scatter_to_sorted_set_ : scatter_to_scratch_set_, push,
                  radix_tiles_);
  }
  stream.compute_barrier();
  dispatch_flat(stream, ranges_pipeline_, ranges_set_, KmeansRangesPush{texels_, params_.vsgl_count},
                div_up(params_.vsgl_count, kNarrow));
}

void KmeansGenerator::record_centre_update(CommandStream& stream) {
  dispatch_flat(stream, update_pieces_, update_pieces_set_, KmeansPiecesPush{texels_, kKmeansChunk},
                div_up(div_up(texels_, kKmeansChunk), kNarrow));
  stream.compute_barrier();
  dispatch_flat(stream, update_centres_, update_centres_set_, KmeansUpdatePush{params_.vsgl_count, kKmeansChunk},
                div_up(params_.vsgl_count, kNarrow));
}

}  // namespace vsgl
