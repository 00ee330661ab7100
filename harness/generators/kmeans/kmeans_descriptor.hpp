#pragma once
// The descriptors of the k-means generators (DESIGN.md §6.2): 2D image space or 3D world space, with
// the paper's sequential per-cluster sum or the segmented-reduction extra.
#include <string>
#include <vector>

#include "harness/generators/generator_descriptor.hpp"
#include "harness/reference/kmeans_reference.hpp"

namespace vsgl {

// Every kernel of the k-means generators, in the order KmeansGenerator builds their pipelines. The
// sum pass is kSum (sequential, the paper's) or kSegsumPieces and kSegsumClusters (the segmented
// reduction); the other kernels serve both.
enum class KmeansKernel {
  kFill,
  kPrepare,
  kPdfMip,
  kSeed,
  kGridCount,
  kGridFill,
  kAssign,
  kScanBlocks,
  kScanAdd,
  kRadixHistogram,
  kRadixScatter,
  kRanges,
  kUpdatePieces,
  kUpdateCentres,
  kSum,
  kSegsumPieces,
  kSegsumClusters,
};

// The kernel's file under kernels/, the one place its name is spelled: "kmeans_fill.comp".
const char* kmeans_kernel_file(KmeansKernel kernel);

// The kernels a generator with this sum builds a pipeline from, in that order; Table 3 counts
// these (the descriptor's sources, DESIGN.md §10).
std::vector<KmeansKernel> kmeans_kernels(bool segmented_sum);

GeneratorDescriptor kmeans_descriptor(KmeansSpace space, bool segmented_sum);

}  // namespace vsgl
