#include "harness/visibility/bvh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "harness/core/error.hpp"
#include "harness/visibility/segment_query.hpp"

namespace vsgl {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();
// SAH costs relative to one triangle test: a node visit costs as much as a triangle test.
constexpr float kTraversalCost = 1.0f;

struct Box {
  glm::vec3 lo{kInfinity};
  glm::vec3 hi{-kInfinity};
  void grow(const Box& b) {
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
  }
  // Half the surface area: what SAH weighs by (non-empty boxes only).
  float half_area() const {
    const glm::vec3 d = hi - lo;
    return d.x * d.y + d.y * d.z + d.z * d.x;
  }
};

struct Split {
  int axis = -1;       // -1: none (the centroids coincide on every axis)
  uint32_t plane = 0;  // bins [0, plane) go left
  uint32_t left_count = 0;
  float cost = kInfinity;  // half areas times triangle counts of both sides
};

class Builder {
 public:
  Builder(const TriangleSoup& soup, uint32_t max_depth) : max_depth_(max_depth) {
    const std::size_t n = soup.triangle_count();
    boxes_.resize(n);
    centroids_.resize(n);
    order_.resize(n);
    for (std::size_t t = 0; t < n; ++t) {
      const glm::vec3 v0 = soup.vertices[3 * t], v1 = soup.vertices[3 * t + 1], v2 = soup.vertices[3 * t + 2];
      boxes_[t].lo = glm::min(glm::min(v0, v1), v2);
      boxes_[t].hi = glm::max(glm::max(v0, v1), v2);
      centroids_[t] = (v0 + v1 + v2) / 3.0f;
      order_[t] = static_cast<uint32_t>(t);
    }
  }

  Bvh finish() && {
    Bvh bvh;
    if (!order_.empty()) build(0, static_cast<uint32_t>(order_.size()), 1);
    bvh.nodes = std::move(nodes_);
    bvh.triangle_order = std::move(order_);
    bvh.depth = depth_;
    return bvh;
  }

 private:
  static uint32_t bin_of(float c, float lo, float scale) {
    return std::min(static_cast<uint32_t>((c - lo) * scale), kBvhBins - 1);
  }

  Split best_sah_split(uint32_t begin, uint32_t end, const Box& centroids) const {
    Split best;
    for (int a = 0; a < 3; ++a) {
      const float extent = centroids.hi[a] - centroids.lo[a];
      const float scale = static_cast<float>(kBvhBins) / extent;
      if (!(extent > 0.0f) || !std::isfinite(scale)) continue;
      std::array<uint32_t, kBvhBins> count{};
      std::array<Box, kBvhBins> box{};
      for (uint32_t i = begin; i < end; ++i) {
        const uint32_t t = order_[i];
        const uint32_t b = bin_of(centroids_[t][a], centroids.lo[a], scale);
        ++count[b];
        box[b].grow(boxes_[t]);
      }
      std::array<float, kBvhBins> right_area{};
      std::array<uint32_t, kBvhBins> right_count{};
      Box right;
      uint32_t n = 0;
      for (uint32_t p = kBvhBins - 1; p >= 1; --p) {
        right.grow(box[p]);
        n += count[p];
        right_count[p] = n;
        right_area[p] = n > 0 ? right.half_area() : 0.0f;
      }
      Box left;
      n = 0;
      for (uint32_t p = 1; p < kBvhBins; ++p) {
        left.grow(box[p - 1]);
        n += count[p - 1];
        if (n == 0 || right_count[p] == 0) continue;
        const float cost =
            left.half_area() * static_cast<float>(n) + right_area[p] * static_cast<float>(right_count[p]);
        if (cost < best.cost) best = Split{a, p, n, cost};
      }
    }
    return best;
  }

  // Triangles [begin, end) of order_ become the subtree of a node at `level` (the root: 1).
  // Invariant: bvh_median_levels(end - begin) <= max_depth_ - level + 1, so a node at the last
  // level holds at most kBvhLeafSize triangles, and a median split always keeps it.
  void build(uint32_t begin, uint32_t end, uint32_t level) {
    const uint32_t n = end - begin;
    Box bounds, centroids;
    for (uint32_t i = begin; i < end; ++i) {
      bounds.grow(boxes_[order_[i]]);
      centroids.grow(Box{centroids_[order_[i]], centroids_[order_[i]]});
    }
    const uint32_t self = static_cast<uint32_t>(nodes_.size());
    nodes_.push_back(
        gpu::BvhNode{bounds.lo.x, bounds.lo.y, bounds.lo.z, begin, bounds.hi.x, bounds.hi.y, bounds.hi.z, n});
    const uint32_t levels_below = max_depth_ - level;
    uint32_t mid = begin;
    if (n > 1 && levels_below > 0) {
      const Split sah = best_sah_split(begin, end, centroids);
      const bool sah_fits =
          sah.axis >= 0 && bvh_median_levels(std::max(sah.left_count, n - sah.left_count)) <= levels_below;
      const bool split = n > gpu::kBvhLeafSize || (sah_fits && kTraversalCost * bounds.half_area() + sah.cost <
                                                                   static_cast<float>(n) * bounds.half_area());
      if (split && sah_fits) {
        const float scale = static_cast<float>(kBvhBins) / (centroids.hi[sah.axis] - centroids.lo[sah.axis]);
        const float lo = centroids.lo[sah.axis];
        const auto middle = std::stable_partition(order_.begin() + begin, order_.begin() + end, [&](uint32_t t) {
          return bin_of(centroids_[t][sah.axis], lo, scale) < sah.plane;
        });
        mid = static_cast<uint32_t>(middle - order_.begin());
        if (mid - begin != sah.left_count) throw std::logic_error("BVH build: the SAH partition lost its count");
      } else if (split) {
        mid = median_split(begin, end, centroids);
      }
    }
    if (mid == begin) {  // a leaf
      if (n > gpu::kBvhLeafSize) throw std::logic_error("BVH build: a leaf of more than kBvhLeafSize triangles");
      depth_ = std::max(depth_, level);
      return;
    }
    build(begin, mid, level + 1);
    nodes_[self].index = static_cast<uint32_t>(nodes_.size());
    nodes_[self].count = 0;
    build(mid, end, level + 1);
  }

  // Halves [begin, end) at the median centroid on the axis of widest centroid spread (ties: the
  // lower axis, then the lower triangle index), so the larger half holds ceil(n / 2).
  uint32_t median_split(uint32_t begin, uint32_t end, const Box& centroids) {
    const glm::vec3 extent = centroids.hi - centroids.lo;
    const int a = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    const uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end, [&](uint32_t s, uint32_t t) {
      const float cs = centroids_[s][a], ct = centroids_[t][a];
      return cs < ct || (cs == ct && s < t);
    });
    return mid;
  }

  uint32_t max_depth_;
  std::vector<Box> boxes_;
  std::vector<glm::vec3> centroids_;
  std::vector<uint32_t> order_;
  std::vector<gpu::BvhNode> nodes_;
  uint32_t depth_ = 0;
};

void require_built_over(const Bvh& bvh, const TriangleSoup& soup) {
  if (bvh.triangle_order.size() != soup.triangle_count())
    throw InputError("BVH of " + std::to_string(bvh.triangle_order.size()) + " triangles used with a soup of " +
                     std::to_string(soup.triangle_count()));
}

}  // namespace

uint32_t bvh_median_levels(uint64_t n) {
  uint32_t levels = 1;
  for (; n > gpu::kBvhLeafSize; n = (n + 1) / 2) ++levels;
  return levels;
}

Bvh build_bvh(const TriangleSoup& soup, const BvhBuildOptions& options) {
  require_valid_soup(soup);
  const uint64_t n = soup.triangle_count();
  constexpr uint64_t kMaxTriangles = uint64_t{1} << 31;
  if (n > kMaxTriangles)
    throw InputError("BVH: " + std::to_string(n) + " triangles, more than the " + std::to_string(kMaxTriangles) +
                     " that 32-bit node indices can address");
  if (options.max_depth > gpu::kBvhMaxDepth)
    throw InputError(
        "BVH: a maximum depth of " + std::to_string(options.max_depth) +
        " levels is deeper than the traversal stack allows (kBvhMaxDepth = " + std::to_string(gpu::kBvhMaxDepth) + ")");
  if (n > 0 && options.max_depth < bvh_median_levels(n))
    throw InputError("BVH: " + std::to_string(n) + " triangles need at least " + std::to_string(bvh_median_levels(n)) +
                     " levels (leaves of " + std::to_string(gpu::kBvhLeafSize) + "), more than the maximum depth of " +
                     std::to_string(options.max_depth));
  Bvh bvh = Builder(soup, options.max_depth).finish();
  if (bvh.depth > options.max_depth) throw std::logic_error("BVH build: the depth bound did not hold");
  bvh.soup_hash = soup_content_hash(soup);
  return bvh;
}

std::vector<gpu::BvhTriangle> bvh_triangles(const Bvh& bvh, const TriangleSoup& soup) {
  require_built_over(bvh, soup);
  std::vector<gpu::BvhTriangle> out;
  out.reserve(bvh.triangle_order.size());
  for (const uint32_t t : bvh.triangle_order)
    out.push_back({glm::vec4(soup.vertices[3 * std::size_t{t}], 0.0f),
                   glm::vec4(soup.vertices[3 * std::size_t{t} + 1], 0.0f),
                   glm::vec4(soup.vertices[3 * std::size_t{t} + 2], 0.0f)});
  return out;
}

bool segment_occluded(const Bvh& bvh, const TriangleSoup& soup, const gpu::SegmentQuery& query) {
  require_built_over(bvh, soup);
  if (bvh.nodes.empty()) return false;
  // The second children of the interior nodes on the path; at most depth - 1 of them.
  std::array<uint32_t, gpu::kBvhMaxDepth> stack;
  uint32_t size = 0;
  uint32_t node = 0;
  for (;;) {
    const gpu::BvhNode& n = bvh.nodes[node];
    if (segment_overlaps_box(query, {n.min_x, n.min_y, n.min_z}, {n.max_x, n.max_y, n.max_z})) {
      if (n.count == 0) {
        if (size == stack.size()) throw InputError("a BVH deeper than kBvhMaxDepth levels (not made by build_bvh)");
        stack[size++] = n.index;
        node = node + 1;
        continue;
      }
      for (uint32_t k = n.index; k < n.index + n.count; ++k) {
        const std::size_t t = bvh.triangle_order[k];
        if (segment_hits_triangle(query, soup.vertices[3 * t], soup.vertices[3 * t + 1], soup.vertices[3 * t + 2]))
          return true;
      }
    }
    if (size == 0) return false;
    node = stack[--size];
  }
}

bool segment_occluded(const Bvh& bvh, const TriangleSoup& soup, glm::vec3 from, glm::vec3 to, float epsilon) {
  return segment_occluded(bvh, soup, make_segment_query(from, to, epsilon));
}

bool segment_occluded_brute_force(const TriangleSoup& soup, glm::vec3 from, glm::vec3 to, float epsilon) {
  const gpu::SegmentQuery query = make_segment_query(from, to, epsilon);
  for (std::size_t t = 0; t < soup.triangle_count(); ++t)
    if (segment_hits_triangle(query, soup.vertices[3 * t], soup.vertices[3 * t + 1], soup.vertices[3 * t + 2]))
      return true;
  return false;
}

}  // namespace vsgl
