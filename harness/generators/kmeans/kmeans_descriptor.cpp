#include "harness/generators/kmeans/kmeans_descriptor.hpp"

#include "harness/generators/kmeans/kmeans_generator.hpp"

namespace vsgl {
namespace {

template <KmeansSpace space, bool segmented_sum>
std::unique_ptr<VsglGenerator> make_kmeans(Device& device, const DeviceView& view, const GeneratorConfig& config) {
  KmeansParams p;
  p.vsgl_count = config.vsgl_count;
  p.iterations = config.kmeans_iterations;
  p.segmented_sum = segmented_sum;
  p.offset_bits = config.offset_bits;
  return std::make_unique<KmeansGenerator>(device, view, space, p);
}

GeneratorFactory factory(KmeansSpace space, bool segmented_sum) {
  if (space == KmeansSpace::k2d) return segmented_sum ? &make_kmeans<KmeansSpace::k2d, true> : &make_kmeans<KmeansSpace::k2d, false>;
  return segmented_sum ? &make_kmeans<KmeansSpace::k3d, true> : &make_kmeans<KmeansSpace::k3d, false>;
}

}  // namespace

const char* kmeans_kernel_file(KmeansKernel kernel) {
  switch (kernel) {
    case KmeansKernel::kFill: return "kmeans_fill.comp";
    case KmeansKernel::kPrepare: return "kmeans_prepare.comp";
    case KmeansKernel::kPdfMip: return "kmeans_pdf_mip.comp";
    case KmeansKernel::kSeed: return "kmeans_seed.comp";
    case KmeansKernel::kGridCount: return "kmeans_grid_count.comp";
    case KmeansKernel::kGridFill: return "kmeans_grid_fill.comp";
    case KmeansKernel::kAssign: return "kmeans_assign.comp";
    case KmeansKernel::kScanBlocks: return "kmeans_scan_blocks.comp";
    case KmeansKernel::kScanAdd: return "kmeans_scan_add.comp";
    case KmeansKernel::kRadixHistogram: return "kmeans_radix_histogram.comp";
    case KmeansKernel::kRadixScatter: return "kmeans_radix_scatter.comp";
    case KmeansKernel::kRanges: return "kmeans_ranges.comp";
    case KmeansKernel::kUpdatePieces: return "kmeans_update_pieces.comp";
    case KmeansKernel::kUpdateCentres: return "kmeans_update_centres.comp";
    case KmeansKernel::kSum: return "kmeans_sum.comp";
    case KmeansKernel::kSegsumPieces: return "kmeans_segsum_pieces.comp";
    case KmeansKernel::kSegsumClusters: return "kmeans_segsum_clusters.comp";
  }
  return "";  // not reached: every enumerator is handled above
}

std::vector<KmeansKernel> kmeans_kernels(bool segmented_sum) {
  std::vector<KmeansKernel> out;
  for (int k = static_cast<int>(KmeansKernel::kFill); k <= static_cast<int>(KmeansKernel::kUpdateCentres); ++k)
    out.push_back(static_cast<KmeansKernel>(k));
  if (segmented_sum) {
    out.push_back(KmeansKernel::kSegsumPieces);
    out.push_back(KmeansKernel::kSegsumClusters);
  } else {
    out.push_back(KmeansKernel::kSum);
  }
  return out;
}

GeneratorDescriptor kmeans_descriptor(KmeansSpace space, bool segmented_sum) {
  const bool two_d = space == KmeansSpace::k2d;
  // The kernels KmeansGenerator builds pipelines from (kmeans_kernels); the host's regions named
  // after the sum are the lines of each (Table 3 counts the one the generator runs, DESIGN.md §10).
  SourceSet sources{
      {"harness/generators/kmeans/kmeans_generator.hpp", "harness/generators/kmeans/kmeans_generator.cpp"},
      {},
      {{"sequential_sum", !segmented_sum}, {"segmented_sum", segmented_sum}, {"verify", false}}};
  for (KmeansKernel k : kmeans_kernels(segmented_sum))
    sources.kernels.push_back(std::string("kernels/") + kmeans_kernel_file(k));
  return GeneratorDescriptor{
      .name = kmeans_generator_name(space, segmented_sum),
      .label = segmented_sum ? std::string(two_d ? "k-means 2D" : "k-means 3D") + ", segmented sum (extra)"
                             : std::string(two_d ? "k-means (2D image space)" : "k-means (3D world space)"),
      .short_label = std::string(two_d ? "km 2D" : "km 3D") + (segmented_sum ? " ss" : ""),
      .in_paper = !segmented_sum,
      .family = GeneratorFamily::kKmeans,
      .phases = {"cluster_assignment", "sort", "sum"},
      .make = factory(space, segmented_sum),
      .sources = std::move(sources),
  };
}

}  // namespace vsgl
