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

GeneratorDescriptor kmeans_descriptor(KmeansSpace space, bool segmented_sum) {
  const bool two_d = space == KmeansSpace::k2d;
  // The kernels KmeansGenerator builds pipelines from; the sum pass is kmeans_sum.comp
  // (sequential, the paper's) or the two segmented-reduction kernels; the host's regions of the
  // same names are the lines of each (Table 3 counts the one the generator runs, DESIGN.md §10).
  SourceSet sources{
      {"harness/generators/kmeans/kmeans_generator.hpp", "harness/generators/kmeans/kmeans_generator.cpp"},
      {"kernels/kmeans_fill.comp", "kernels/kmeans_prepare.comp", "kernels/kmeans_pdf_mip.comp",
       "kernels/kmeans_seed.comp", "kernels/kmeans_grid_count.comp", "kernels/kmeans_grid_fill.comp",
       "kernels/kmeans_assign.comp", "kernels/kmeans_scan_blocks.comp", "kernels/kmeans_scan_add.comp",
       "kernels/kmeans_radix_histogram.comp", "kernels/kmeans_radix_scatter.comp", "kernels/kmeans_ranges.comp",
       "kernels/kmeans_update_pieces.comp", "kernels/kmeans_update_centres.comp"},
      {{"sequential_sum", !segmented_sum}, {"segmented_sum", segmented_sum}, {"verify", false}}};
  if (segmented_sum) {
    sources.kernels.push_back("kernels/kmeans_segsum_pieces.comp");
    sources.kernels.push_back("kernels/kmeans_segsum_clusters.comp");
  } else {
    sources.kernels.push_back("kernels/kmeans_sum.comp");
  }
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
