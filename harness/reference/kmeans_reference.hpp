#pragma once
// The CPU reference of the k-means generators `kmeans_2d` and `kmeans_3d` (DESIGN.md §6.2): features,
// seeds, Lloyd iterations with brute-force assignment, the stable sort by cluster, and the
// per-cluster sums and VSGLs (DESIGN.md §7).
//
// Exactness: the seeds come from reference_samples() (bit-exact with the GPU on lavapipe), the
// squared distance and the centre update use the GPU kernels' float operation order (the update
// sums in the chunked order of kmeans_update_pieces.comp / kmeans_update_centres.comp), so on a
// device whose float division is correctly rounded the whole clustering matches bit for bit.
// The cluster sums are done in double (a tolerance is needed against the GPU's float sums).
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "harness/capture/capture.hpp"
#include "harness/math/vsgl_math.hpp"

namespace vsgl {

enum class KmeansSpace {
  k2d,  // feature: the texel centre in image space, in pixels
  k3d,  // feature: the texel's world position
};

// The generator id (core/generator_ids.hpp): kKmeans2d or kKmeans3d, or with the segmented-reduction
// sum kKmeans2dSegsum or kKmeans3dSegsum.
const char* kmeans_generator_name(KmeansSpace space, bool segmented_sum);

struct KmeansParams {
  uint32_t vsgl_count = 0;     // N (clusters)
  uint32_t iterations = 4;     // Lloyd iterations before the final assignment
  bool segmented_sum = false;  // false: the paper's sequential per-cluster sum
  uint32_t offset_bits = 0;    // Fibonacci lattice offset of the seeds (DESIGN.md §5)
  // GPU only: a one-cell grid, i.e. the assignment by brute force over all centres (same result;
  // it exists to measure what the grid saves).
  bool brute_force_grid = false;
};

inline constexpr uint32_t kNoCluster = 0xFFFFFFFFu;
// Elements per piece of the chunked segmented sums (centre update and the segsum variant).
inline constexpr uint32_t kKmeansChunk = 256;

// Per texel: (feature.xyz, q) for a texel in some cluster, (feature.xyz, -1) for one in none
// (valid flag 0, or w = 0 and q = 0). 2D: (x + 0.5, y + 0.5, 0); 3D: the world position.
std::vector<glm::vec4> kmeans_features(const ViewImage& view, glm::vec3 source_pos, KmeansSpace space);

// The N seeds: the kernel centres of DESIGN.md §5 on the view's PDF (the q of texel_moments()):
// 2D: x_i * S (pixels); 3D: the world position of the chosen texel.
std::vector<glm::vec4> kmeans_seeds(const ViewImage& view, glm::vec3 source_pos, KmeansSpace space, uint32_t N,
                                    uint32_t offset_bits);

// |a - b|^2 in the GPU's order: (dx*dx + dy*dy) + dz*dz.
float kmeans_distance2(glm::vec3 a, glm::vec3 b);

// Nearest centre of every clustered texel by brute force (ties: lower id); kNoCluster otherwise.
std::vector<uint32_t> brute_force_assignment(const std::vector<glm::vec4>& features,
                                             const std::vector<glm::vec4>& centres);

// (cluster id, texel index) pairs stably sorted by cluster (kNoCluster last), and each cluster's
// [begin, end) in them.
struct KmeansSort {
  std::vector<glm::uvec2> pairs;
  std::vector<glm::uvec2> ranges;
};
KmeansSort sort_by_cluster(const std::vector<uint32_t>& assignment, uint32_t N);

// One centre update: each non-empty cluster with positive total q moves to the q-weighted mean of
// its features, summed in the GPU's chunked order; the others keep their centre.
std::vector<glm::vec4> kmeans_update_centres(const std::vector<glm::vec4>& features, const KmeansSort& sorted,
                                             const std::vector<glm::vec4>& centres);

// Sums of a cluster's texel moments (texel_moments()), in double.
struct ClusterSums {
  glm::dvec4 m0{0.0}, m1{0.0}, m2{0.0}, m3{0.0}, m4{0.0};
  glm::dvec2 pixels{0.0};  // sum of texel centres in pixels
  uint32_t texels = 0;
};
std::vector<ClusterSums> reference_cluster_sums(const ViewImage& view, glm::vec3 source_pos, const KmeansSort& sorted);
// The clusters' VSGLs as the `sum` kernels build them (power = flux sum, level -1, density 0,
// texel count; centre: 2D the cluster centre / S, 3D the mean texel centre / S).
std::vector<VsglRecord> cluster_vsgls(const std::vector<ClusterSums>& sums, const std::vector<glm::vec4>& centres,
                                      KmeansSpace space, uint32_t square_size);

struct KmeansResult {
  std::vector<glm::vec4> features;
  std::vector<glm::vec4> seeds;
  std::vector<glm::vec4> centres;  // after the last update (those of the final assignment)
  std::vector<uint32_t> assignment;
  KmeansSort sorted;
  std::vector<VsglRecord> vsgls;
};
// The whole generator. Throws InputError for N = 0 or N larger than the view's valid texels with
// a positive PDF.
KmeansResult reference_kmeans(const ViewImage& view, glm::vec3 source_pos, KmeansSpace space,
                              const KmeansParams& params);

}  // namespace vsgl
