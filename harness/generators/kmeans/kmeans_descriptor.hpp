#pragma once
// The descriptors of the k-means generators (DESIGN.md §6.2): 2D image space or 3D world space, with
// the paper's sequential per-cluster sum or the segmented-reduction extra.
#include "harness/generators/generator_descriptor.hpp"
#include "harness/reference/kmeans_reference.hpp"

namespace vsgl {

GeneratorDescriptor kmeans_descriptor(KmeansSpace space, bool segmented_sum);

}  // namespace vsgl
