// CPU reference of the k-means generators (DESIGN.md §6.2); the float expressions that must match the
// GPU bit for bit follow the kernels' operation order (kernels/kmeans_*.comp).
#include "harness/reference/kmeans_reference.hpp"

#include <algorithm>
#include <string>

#include "harness/core/error.hpp"
#include "harness/core/generator_ids.hpp"
#include "harness/reference/fis_reference.hpp"
#include "harness/math/virtual_square.hpp"

namespace vsgl {

namespace {

struct TexelView {
  bool valid;
  TexelMoments moments;
};

TexelView texel_at(const ViewImage& view, std::size_t t, glm::vec3 source_pos) {
  const auto& pl = view.planes;
  const float pdf = pl[kPdf].empty() ? 0.0f : pl[kPdf][t];
  const bool valid = pl[kValid][t] != 0.0f;
  return {valid, texel_moments(valid, {pl[kPX][t], pl[kPY][t], pl[kPZ][t]}, {pl[kNX][t], pl[kNY][t], pl[kNZ][t]},
                               {pl[kDR][t], pl[kDG][t], pl[kDB][t]}, {pl[kSR][t], pl[kSG][t], pl[kSB][t]},
                               pl[kRoughness][t], pdf, source_pos, view.kind == ViewKind::kCamera)};
}

// The sort key: a cluster id, or N for "no cluster" (sorted last).
uint32_t sort_key(uint32_t cluster, uint32_t N) { return std::min(cluster, N); }

}  // namespace

const char* kmeans_generator_name(KmeansSpace space, bool segmented_sum) {
  // The ids are string literals (core/generator_ids.hpp): data() ends in a '\0'.
  if (space == KmeansSpace::k2d) return (segmented_sum ? kKmeans2dSegsum : kKmeans2d).data();
  return (segmented_sum ? kKmeans3dSegsum : kKmeans3d).data();
}

std::vector<glm::vec4> kmeans_features(const ViewImage& view, glm::vec3 source_pos, KmeansSpace space) {
  std::vector<glm::vec4> out(view.texels());
  for (uint32_t y = 0; y < view.height; ++y) {
    for (uint32_t x = 0; x < view.width; ++x) {
      const std::size_t t = std::size_t{y} * view.width + x;
      const TexelView tv = texel_at(view, t, source_pos);
      // Valid flag 0, or no power and no PDF weight: in no cluster (DESIGN.md §6.2).
      const bool member = tv.valid && !(tv.moments.m0.w == 0.0f && tv.moments.m2.w == 0.0f);
      const glm::vec3 f = space == KmeansSpace::k3d
                              ? glm::vec3(view.planes[kPX][t], view.planes[kPY][t], view.planes[kPZ][t])
                              : glm::vec3(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f, 0.0f);
      out[t] = glm::vec4(f, member ? tv.moments.m2.w : -1.0f);
    }
  }
  return out;
}

std::vector<glm::vec4> kmeans_seeds(const ViewImage& view, glm::vec3 source_pos, KmeansSpace space, uint32_t N,
                                    uint32_t offset_bits) {
  std::vector<glm::vec4> q(view.texels());
  for (std::size_t t = 0; t < q.size(); ++t) q[t] = glm::vec4(0.0f, 0.0f, 0.0f, texel_at(view, t, source_pos).moments.m2.w);
  const MipPyramid pyramid = MipPyramid::build(q, view.width, view.height);
  const std::vector<SamplePoint> samples = reference_samples(pyramid, N, offset_bits);
  std::vector<glm::vec4> seeds(N);
  for (uint32_t i = 0; i < N; ++i) {
    const SamplePoint& s = samples[i];
    if (space == KmeansSpace::k3d) {
      const std::size_t t = std::size_t{s.texel.y} * view.width + s.texel.x;
      seeds[i] = glm::vec4(view.planes[kPX][t], view.planes[kPY][t], view.planes[kPZ][t], 0.0f);
    } else {
      seeds[i] = glm::vec4(s.x * static_cast<float>(pyramid.size()), 0.0f, 0.0f);
    }
  }
  return seeds;
}

float kmeans_distance2(glm::vec3 a, glm::vec3 b) {
  const float dx = a.x - b.x;
  const float dy = a.y - b.y;
  const float dz = a.z - b.z;
  const float r = dx * dx + dy * dy;
  return r + dz * dz;
}

std::vector<uint32_t> brute_force_assignment(const std::vector<glm::vec4>& features,
                                             const std::vector<glm::vec4>& centres) {
  std::vector<uint32_t> out(features.size(), kNoCluster);
  for (std::size_t t = 0; t < features.size(); ++t) {
    if (features[t].w < 0.0f) continue;
    const glm::vec3 f(features[t]);
    float best = 0.0f;
    for (std::size_t k = 0; k < centres.size(); ++k) {
      const float d = kmeans_distance2(f, glm::vec3(centres[k]));
      if (k == 0 || d < best) {
        best = d;
        out[t] = static_cast<uint32_t>(k);
      }
    }
  }
  return out;
}

KmeansSort sort_by_cluster(const std::vector<uint32_t>& assignment, uint32_t N) {
  KmeansSort s;
  s.pairs.resize(assignment.size());
  for (std::size_t i = 0; i < assignment.size(); ++i) s.pairs[i] = {assignment[i], static_cast<uint32_t>(i)};
  std::stable_sort(s.pairs.begin(), s.pairs.end(), [N](const glm::uvec2& a, const glm::uvec2& b) {
    return sort_key(a.x, N) < sort_key(b.x, N);
  });
  s.ranges.assign(N, glm::uvec2(0u));
  uint32_t pos = 0;
  for (uint32_t k = 0; k < N; ++k) {
    const uint32_t begin = pos;
    while (pos < s.pairs.size() && s.pairs[pos].x == k) ++pos;
    s.ranges[k] = {begin, pos};
  }
  return s;
}

std::vector<glm::vec4> kmeans_update_centres(const std::vector<glm::vec4>& features, const KmeansSort& sorted,
                                             const std::vector<glm::vec4>& centres) {
  std::vector<glm::vec4> out = centres;
  const auto weighted = [&](uint32_t texel) {
    const glm::vec4 f = features[texel];
    return glm::vec4(f.x * f.w, f.y * f.w, f.z * f.w, f.w);
  };
  for (std::size_t k = 0; k < centres.size(); ++k) {
    const glm::uvec2 r = sorted.ranges[k];
    if (r.x == r.y) continue;
    // Pieces: the cluster's elements inside each chunk of kKmeansChunk sorted positions, summed
    // sequentially; then the pieces in chunk order (kmeans_update_pieces / _centres.comp).
    glm::vec4 total(0.0f);
    for (uint32_t chunk = r.x / kKmeansChunk; chunk <= (r.y - 1) / kKmeansChunk; ++chunk) {
      const uint32_t b = std::max(r.x, chunk * kKmeansChunk);
      const uint32_t e = std::min(r.y, (chunk + 1) * kKmeansChunk);
      glm::vec4 piece = weighted(sorted.pairs[b].y);
      for (uint32_t i = b + 1; i < e; ++i) piece = piece + weighted(sorted.pairs[i].y);
      total = chunk == r.x / kKmeansChunk ? piece : total + piece;
    }
    if (!(total.w > 0.0f)) continue;
    out[k] = glm::vec4(total.x / total.w, total.y / total.w, total.z / total.w, 0.0f);
  }
  return out;
}

std::vector<ClusterSums> reference_cluster_sums(const ViewImage& view, glm::vec3 source_pos, const KmeansSort& sorted) {
  std::vector<ClusterSums> out(sorted.ranges.size());
  for (std::size_t k = 0; k < out.size(); ++k) {
    ClusterSums& s = out[k];
    for (uint32_t i = sorted.ranges[k].x; i < sorted.ranges[k].y; ++i) {
      const uint32_t t = sorted.pairs[i].y;
      const TexelMoments m = texel_at(view, t, source_pos).moments;
      s.m0 += glm::dvec4(m.m0);
      s.m1 += glm::dvec4(m.m1);
      s.m2 += glm::dvec4(m.m2);
      s.m3 += glm::dvec4(m.m3);
      s.m4 += glm::dvec4(m.m4);
      s.pixels += glm::dvec2(static_cast<double>(t % view.width) + 0.5, static_cast<double>(t / view.width) + 0.5);
      ++s.texels;
    }
  }
  return out;
}

std::vector<VsglRecord> cluster_vsgls(const std::vector<ClusterSums>& sums, const std::vector<glm::vec4>& centres,
                                      KmeansSpace space, uint32_t square_size) {
  const auto S = static_cast<float>(square_size);
  std::vector<VsglRecord> out(sums.size());
  for (std::size_t k = 0; k < sums.size(); ++k) {
    const ClusterSums& s = sums[k];
    glm::vec2 center = glm::vec2(centres[k]) / S;
    if (space == KmeansSpace::k3d)
      center = s.texels > 0 ? glm::vec2(s.pixels / static_cast<double>(s.texels)) / S : glm::vec2(0.0f);
    const TexelMoments m{glm::vec4(s.m0), glm::vec4(s.m1), glm::vec4(s.m2), glm::vec4(s.m3), glm::vec4(s.m4)};
    out[k] = vsgl_from_moments(m, 1.0f, -1.0f, center, 0.0f, static_cast<float>(s.texels));
  }
  return out;
}

KmeansResult reference_kmeans(const ViewImage& view, glm::vec3 source_pos, KmeansSpace space,
                              const KmeansParams& params) {
  const std::string name = kmeans_generator_name(space, params.segmented_sum);
  const uint32_t N = params.vsgl_count;
  if (N == 0) throw InputError(name + ": the number of VSGLs N must be positive");
  KmeansResult r;
  r.features = kmeans_features(view, source_pos, space);
  std::size_t samplable = 0;
  for (std::size_t t = 0; t < view.texels(); ++t)
    if (view.planes[kValid][t] != 0.0f && !view.planes[kPdf].empty() && view.planes[kPdf][t] > 0.0f) ++samplable;
  if (N > samplable)
    throw InputError(name + ": N = " + std::to_string(N) + " exceeds the " + std::to_string(samplable) +
                     " valid texels with nonzero PDF of the " + view_label(view.kind));
  r.seeds = kmeans_seeds(view, source_pos, space, N, params.offset_bits);
  r.centres = r.seeds;
  for (uint32_t it = 0; it < params.iterations; ++it) {
    const KmeansSort s = sort_by_cluster(brute_force_assignment(r.features, r.centres), N);
    r.centres = kmeans_update_centres(r.features, s, r.centres);
  }
  r.assignment = brute_force_assignment(r.features, r.centres);
  r.sorted = sort_by_cluster(r.assignment, N);
  const uint32_t S = VirtualSquare::make(view.width, view.height, view_label(view.kind)).size;
  r.vsgls = cluster_vsgls(reference_cluster_sums(view, source_pos, r.sorted), r.centres, space, S);
  return r;
}

}  // namespace vsgl
