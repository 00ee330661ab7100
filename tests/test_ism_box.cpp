// Imperfect shadow maps against exact visibility in a closed box (DESIGN.md §8a.2), through the
// lookup the shading will use (kernels/include/ism_lookup.glsl, run by the test kernel
// kernels/test_ism_lookup.comp). The box is [-1, 1]^3, its six faces point-sampled; the maps look
// from points inside it. From inside a convex box every point of its faces is visible, so exact
// visibility is known; a wall put inside it makes a shadow, found exactly by a segment-rectangle
// test.
//
// What a lookup may say is read off its taps. The CPU mirrors where the lookup puts its (2r + 1)^2
// taps (the normal offset, then one texel apart) and what each tap's depth is made of: the points
// that landed in its texel, or, where none did, the points of the texels of level 1 that the push
// interpolates it from (all of them must hold a point, else the tap is left unclassified). A tap
// is "clear" of a surface when every one of those texels sees only that surface: its corners, edge
// midpoints and centre all look at it (a texel spans 4/64 rad at most, so the surface's edges,
// straight lines, cannot cross it unseen by these nine directions). Where a tap is clear of the
// receiver's own face, its depth is that face's depth near the receiver, which the bias must clear:
// the tap says visible. Near a concave edge of the box, taps read the other face, which is in front
// of the receiver's plane: they may say occluded, truly for their directions, and the PCF drops
// below 1 there by design; those taps are what the tests allow for, nothing more.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <random>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "gpu_test.hpp"
#include "harness/visibility/imperfect_shadow_maps.hpp"
#include "harness/visibility/paraboloid.hpp"
#include "harness/visibility/point_sampling.hpp"
#include "harness/vk/buffer.hpp"
#include "harness/vk/command_stream.hpp"
#include "harness/vk/compute_pipeline.hpp"
#include "kernels/include/interface/ism.h"

namespace vsgl {
namespace {

// A rectangle centre + a u + b v, a, b in [-1, 1], facing `inward`.
struct BoxRect {
  glm::vec3 centre, u, v, inward;
  glm::vec3 at(float a, float b) const { return centre + a * u + b * v; }
};

// The six inner faces of [-1, 1]^3; face 2 axis + (0 for -1, 1 for +1).
std::vector<BoxRect> box_faces() {
  std::vector<BoxRect> faces;
  for (int axis = 0; axis < 3; ++axis)
    for (float sign : {-1.0f, 1.0f}) {
      glm::vec3 c(0.0f), u(0.0f), v(0.0f);
      c[axis] = sign;
      u[(axis + 1) % 3] = 1.0f;
      v[(axis + 2) % 3] = 1.0f;
      faces.push_back({c, u, v, -c});
    }
  return faces;
}

// Two triangles per rectangle, wound so that their geometric normal is `inward`.
void add_rect(std::vector<glm::vec3>& soup, const BoxRect& r) {
  glm::vec3 a = r.at(-1, -1), b = r.at(1, -1), c = r.at(1, 1), d = r.at(-1, 1);
  if (glm::dot(glm::cross(b - a, c - a), r.inward) < 0.0f) std::swap(b, d);
  soup.insert(soup.end(), {a, b, c, a, c, d});
}

// The face a ray from inside the box leaves it through.
int exit_face(glm::vec3 o, glm::vec3 d) {
  int face = 0;
  float nearest = std::numeric_limits<float>::infinity();
  for (int axis = 0; axis < 3; ++axis) {
    if (d[axis] == 0.0f) continue;
    const float t = ((d[axis] > 0.0f ? 1.0f : -1.0f) - o[axis]) / d[axis];
    if (t < nearest) {
      nearest = t;
      face = 2 * axis + (d[axis] > 0.0f ? 1 : 0);
    }
  }
  return face;
}

// Where the ray from o along unit d meets the rectangle, if it does (t > 0).
std::optional<float> ray_hits_rect(glm::vec3 o, glm::vec3 d, const BoxRect& r) {
  const glm::vec3 n = glm::cross(r.u, r.v);
  const float denom = glm::dot(d, n);
  if (std::abs(denom) < 1e-12f) return std::nullopt;
  const float t = glm::dot(r.centre - o, n) / denom;
  if (t <= 0.0f) return std::nullopt;
  const glm::vec3 x = o + t * d - r.centre;
  if (std::abs(glm::dot(x, r.u)) > glm::dot(r.u, r.u) || std::abs(glm::dot(x, r.v)) > glm::dot(r.v, r.v))
    return std::nullopt;
  return t;
}

// The GPU query path: ism_visibility() for each query (test_ism_lookup.comp).
std::vector<float> ism_lookups(Device& device, const ImperfectShadowMaps& ism,
                               const std::vector<gpu::IsmQuery>& queries) {
  Buffer in(device, queries.size() * sizeof(gpu::IsmQuery), MemoryUsage::kDeviceLocal, "test.ism.queries");
  Buffer out(device, queries.size() * sizeof(float), MemoryUsage::kDeviceLocal, "test.ism.visibility");
  upload(device, in, queries.data(), queries.size() * sizeof(gpu::IsmQuery));
  ComputePipeline pipeline(
      device, {"test_ism_lookup.comp", 4, sizeof(gpu::IsmQueryPush), work_group_size_1d(gpu::kIsmGroupSize)});
  BindingSet set(device, pipeline, {ism.origins(), in, ism.maps(), out}, "test.ism.set");
  const auto count = static_cast<uint32_t>(queries.size());
  device.submit_and_wait([&](VkCommandBuffer cmd) {
    CommandStream stream(cmd);
    stream.full_barrier();
    stream.dispatch(pipeline, set, gpu::IsmQueryPush{ism.params(), count}, div_up(count, gpu::kIsmGroupSize));
  });
  return download_vector<float>(device, out, queries.size());
}

// What a direction from a map's origin sees: a face of the box (0..5) or the wall (-1).
using SurfaceOf = std::function<int(glm::vec3 origin, glm::vec3 direction)>;

// The lookup's taps (ism_lookup.glsl) for receiver x with normal n, mirrored in float: for each,
// the texels float rounding could put it in (1e-3 texel either way), and whether it surely lies
// in the disk (the lookup leaves out taps whose point lies outside). Empty when the offset receiver
// is behind the map's plane (the lookup then says 1 without reading).
struct MirroredTap {
  std::vector<glm::uvec2> texels;
  bool surely_read = true;
};
std::vector<MirroredTap> mirrored_taps(const IsmMapOrigin& o, glm::vec3 x, glm::vec3 n, const IsmSettings& s) {
  const ParaboloidFrame frame = paraboloid_frame(o.normal);
  glm::vec3 v = x - o.position;
  float dist = glm::length(v);
  glm::vec2 p = paraboloid_project(frame.local(v / dist));
  const glm::vec3 facing = glm::dot(n, v / dist) > 0.0f ? -n : n;
  const glm::vec3 xo = x + facing * (s.normal_offset * paraboloid_texel_angle(p, s.side) * dist);
  v = xo - o.position;
  dist = glm::length(v);
  if (glm::dot(v, o.normal) <= 1e-4f * dist) return {};
  p = paraboloid_project(frame.local(v / dist));
  const float step = 2.0f / static_cast<float>(s.side);
  const float e = 1e-3f * step;
  const int r = static_cast<int>(s.pcf_radius);
  std::vector<MirroredTap> taps;
  for (int j = -r; j <= r; ++j)
    for (int i = -r; i <= r; ++i) {
      const glm::vec2 q = p + glm::vec2(static_cast<float>(i), static_cast<float>(j)) * step;
      const bool centre = i == 0 && j == 0;
      const float r2 = glm::dot(q, q);
      if (!centre && r2 > 1.0f + 1e-4f) continue;
      MirroredTap tap;
      tap.surely_read = centre || r2 < 1.0f - 1e-4f;
      for (const glm::vec2 jitter : {glm::vec2(-e, -e), glm::vec2(e, -e), glm::vec2(-e, e), glm::vec2(e, e)}) {
        const glm::uvec2 t = paraboloid_texel(q + jitter, s.side);
        if (std::find(tap.texels.begin(), tap.texels.end(), t) == tap.texels.end()) tap.texels.push_back(t);
      }
      taps.push_back(tap);
    }
  return taps;
}

// The texels of level 0 whose points make texel t's depth: t where a point landed in it, else
// the 2x2 blocks of the level-1 texels the push interpolates it from (ism_push.comp), all of which
// must hold a point (std::nullopt otherwise: its source lies further out).
std::optional<std::vector<glm::uvec2>> depth_sources(glm::uvec2 t, const std::vector<float>& splatted, uint32_t side) {
  const auto splat = [&](uint32_t x, uint32_t y) { return !std::isinf(splatted[std::size_t{y} * side + x]); };
  if (splat(t.x, t.y)) return std::vector<glm::uvec2>{t};
  const int half = static_cast<int>(side / 2);
  const auto coarse_taps = [&](uint32_t f) {
    const int i0 = static_cast<int>(std::floor((static_cast<float>(f) + 0.5f) * 0.5f - 0.5f));
    return std::pair<int, int>{std::clamp(i0, 0, half - 1), std::clamp(i0 + 1, 0, half - 1)};
  };
  const auto [x0, x1] = coarse_taps(t.x);
  const auto [y0, y1] = coarse_taps(t.y);
  std::vector<glm::uvec2> out;
  for (int cy : {y0, y1})
    for (int cx : {x0, x1}) {
      bool any = false;
      for (uint32_t k = 0; k < 4; ++k) {
        const glm::uvec2 f(2 * static_cast<uint32_t>(cx) + k % 2, 2 * static_cast<uint32_t>(cy) + k / 2);
        if (!splat(f.x, f.y)) continue;
        any = true;
        out.push_back(f);
      }
      if (!any) return std::nullopt;
    }
  return out;
}

// Whether every direction of texel t (corners, edge midpoints, centre inside the disk) sees `want`.
bool texel_sees_only(glm::uvec2 t, const IsmMapOrigin& o, uint32_t side, const SurfaceOf& surface_of, int want) {
  const ParaboloidFrame frame = paraboloid_frame(o.normal);
  const float step = 2.0f / static_cast<float>(side);
  int seen = 0;
  for (int b = 0; b <= 2; ++b)
    for (int a = 0; a <= 2; ++a) {
      const glm::vec2 p = (glm::vec2(t) + 0.5f * glm::vec2(static_cast<float>(a), static_cast<float>(b))) * step - 1.0f;
      if (glm::dot(p, p) > 1.0f) continue;
      if (surface_of(o.position, frame.world(paraboloid_unproject(p))) != want) return false;
      ++seen;
    }
  return seen > 0;
}

// Taps the lookup may read, and of them those whose depth comes only from surface `want`.
struct TapCount {
  uint32_t possible = 0;
  uint32_t clear = 0;
};
TapCount taps_clear_of(const std::vector<MirroredTap>& taps, const IsmMapOrigin& o, const std::vector<float>& splatted,
                       uint32_t side, const SurfaceOf& surface_of, int want) {
  TapCount count;
  for (const MirroredTap& tap : taps) {
    ++count.possible;
    if (!tap.surely_read) continue;
    bool clear = true;
    for (const glm::uvec2 t : tap.texels) {
      const auto sources = depth_sources(t, splatted, side);
      clear = clear && sources.has_value();
      for (std::size_t k = 0; clear && k < sources->size(); ++k)
        clear = texel_sees_only((*sources)[k], o, side, surface_of, want);
    }
    count.clear += clear ? 1 : 0;
  }
  return count;
}

// `per_map` random points on the inner faces in each map's hemisphere, the face's normal with each.
std::vector<gpu::IsmQuery> face_queries(const std::vector<IsmMapOrigin>& origins, uint32_t per_map, uint64_t seed) {
  const auto faces = box_faces();
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::vector<gpu::IsmQuery> out;
  for (uint32_t m = 0; m < origins.size(); ++m)
    for (uint32_t found = 0; found < per_map;) {
      const BoxRect& f = faces[rng() % 6];
      const glm::vec3 q = f.at(u(rng), u(rng));
      if (glm::dot(q - origins[m].position, origins[m].normal) <= 0.0f) continue;
      out.push_back(gpu::IsmQuery{glm::vec4(q, 1.0f), glm::vec4(f.inward, 0.0f), m, 0, 0, 0});
      ++found;
    }
  return out;
}

int face_of_query(const gpu::IsmQuery& q) {
  const glm::vec3 n(q.normal);
  for (int axis = 0; axis < 3; ++axis)
    if (n[axis] != 0.0f) return 2 * axis + (n[axis] < 0.0f ? 1 : 0);  // inward -x: the face at x = +1
  return -2;
}

// The maps and their points: `origins` over the soup, with and without pull-push (the latter
// tells which texels a point landed in).
struct BuiltMaps {
  ImperfectShadowMaps filled;
  std::vector<float> splatted;  // level 0 of every map before pull-push
};
BuiltMaps build_maps(Device& device, const std::vector<glm::vec3>& soup, const std::vector<IsmMapOrigin>& origins,
                     IsmSettings settings, uint64_t seed) {
  const auto points = sample_triangle_soup(soup, settings.points_per_map * static_cast<uint32_t>(origins.size()), seed);
  settings.fill_holes = false;
  const std::vector<float> splatted = ImperfectShadowMaps(device, points, origins, settings).read_level0();
  settings.fill_holes = true;
  return {ImperfectShadowMaps(device, points, origins, settings), splatted};
}

class IsmBoxTest : public test::GpuTest {};

// Every point of the box's inner faces is visible from inside. A lookup whose taps are all clear of
// its own face must say 1 (>= 0.99: the next value below 1 is 8/9 with 9 taps); one near a
// concave edge at least the share of its taps that are clear. The maps are the defaults, with
// disjoint subsets of 8192 points; their origins are at the centre, near a face, near a corner.
// At 64^2 a texel spans 2 to 3.6 degrees and the taps with the push's sources reach 3 to 5
// texels, so the box's 12 edges leave about a quarter of the receivers with every tap on their
// own face (1024 of 3600 on lavapipe).
TEST_F(IsmBoxTest, EveryInnerFacePointIsVisibleFromInsideTheBox) {
  const std::vector<IsmMapOrigin> origins = {
      {{0.0f, 0.0f, 0.0f}, {0, 0, 1}},                                      // the centre
      {{0.5f, -0.3f, 0.2f}, glm::normalize(glm::vec3(1, 1, 0))},            // toward an edge
      {{-0.7f, 0.6f, -0.5f}, {0, -1, 0}},                                   // off centre, down
      {{0.8f, 0.8f, 0.8f}, glm::normalize(glm::vec3(-1, -1, -1))},          // in a corner
      {{-0.2f, -0.9f, 0.4f}, {0, 1, 0}},                                    // near the floor, up
      {{0.3f, 0.1f, -0.95f}, glm::normalize(glm::vec3(0.3f, 0.2f, 1.0f))},  // near a face, askew
  };
  std::vector<glm::vec3> soup;
  for (const BoxRect& f : box_faces()) add_rect(soup, f);
  const IsmSettings settings;
  const BuiltMaps maps = build_maps(device(), soup, origins, settings, 77);
  const auto queries = face_queries(origins, 600, 5);
  const std::vector<float> visibility = ism_lookups(device(), maps.filled, queries);
  const std::size_t texels = std::size_t{settings.side} * settings.side;
  const SurfaceOf face = [](glm::vec3 o, glm::vec3 d) { return exit_face(o, d); };

  uint32_t all_clear = 0;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const gpu::IsmQuery& q = queries[i];
    const IsmMapOrigin& o = origins[q.map];
    const std::vector<float> splatted(maps.splatted.begin() + static_cast<std::ptrdiff_t>(q.map * texels),
                                      maps.splatted.begin() + static_cast<std::ptrdiff_t>((q.map + 1) * texels));
    const auto taps = mirrored_taps(o, glm::vec3(q.position), glm::vec3(q.normal), settings);
    if (taps.empty()) {
      EXPECT_EQ(visibility[i], 1.0f) << "query " << i << ": behind the map after the offset";
      continue;
    }
    const TapCount count = taps_clear_of(taps, o, splatted, settings.side, face, face_of_query(q));
    const float least = static_cast<float>(count.clear) / static_cast<float>(count.possible);
    if (count.clear == count.possible) {
      ++all_clear;
      EXPECT_GE(visibility[i], 0.99f) << "query " << i << " (map " << q.map << ") sees only its own face";
    } else {
      EXPECT_GE(visibility[i], least - 1e-6f) << "query " << i << " (map " << q.map << "): " << count.clear << " of "
                                              << count.possible << " taps see only its own face";
    }
  }
  EXPECT_GT(all_clear, queries.size() / 5) << "too few queries with every tap on its own face";
}

// A wall inside the box between a map's origin and part of the far faces. ISM and exact visibility
// (the segment from the origin to the receiver crosses the wall or not) must agree wherever every
// tap is clear of the receiver's exact answer (its own face where visible, the wall where not).
// The rest is the band the map's resolution leaves along the shadow's edge and the box's edges:
// the receivers whose taps, a texel apart around the offset receiver, or the texels a hole's push
// reads, 2 further, see another surface in some direction; it spans 3 to 5 texels (11 to 18 degrees
// at the disk's centre) either side of an edge. The ISM says visible where the lookup is >= 0.5.
// The wall gets 1.44/25.44 of 32768 points per map: at its distance, 0.9 to 1.3, about 4 per
// texel it covers, so that e^-4, 2 %, of its texels let a background point through (an ISM's light
// leak) and a receiver in its shadow is called lit only if 5 of its 9 taps leak. On lavapipe 749
// of the 6000 receivers (12.5 %) disagree, all in the band of 3596 (60 %).
TEST_F(IsmBoxTest, AWallShadowsTheFarFacesAsExactVisibilitySaysOutsideTheEdgeBand) {
  const std::vector<IsmMapOrigin> origins = {
      {{0.0f, 0.0f, -0.7f}, {0, 0, 1}},
      {{0.6f, -0.5f, -0.9f}, glm::normalize(glm::vec3(-0.3f, 0.3f, 1.0f))},
  };
  // x in [-0.8, 0.4], y in [-0.6, 0.6], at z = 0.2, facing the origins.
  const BoxRect wall{{-0.2f, 0.0f, 0.2f}, {0.6f, 0, 0}, {0, 0.6f, 0}, {0, 0, -1}};
  std::vector<glm::vec3> soup;
  for (const BoxRect& f : box_faces()) add_rect(soup, f);
  add_rect(soup, wall);
  IsmSettings settings;
  settings.points_per_map = 32768;
  const BuiltMaps maps = build_maps(device(), soup, origins, settings, 78);
  const auto queries = face_queries(origins, 3000, 6);
  const std::vector<float> visibility = ism_lookups(device(), maps.filled, queries);
  const std::size_t texels = std::size_t{settings.side} * settings.side;
  const SurfaceOf surface = [&wall](glm::vec3 o, glm::vec3 d) {
    const auto t = ray_hits_rect(o, d, wall);
    return t.has_value() ? -1 : exit_face(o, d);
  };

  uint32_t band = 0, disagree = 0, shadowed_outside_band = 0, lit_outside_band = 0;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const gpu::IsmQuery& q = queries[i];
    const IsmMapOrigin& o = origins[q.map];
    const glm::vec3 x(q.position);
    const auto wall_hit = ray_hits_rect(o.position, glm::normalize(x - o.position), wall);
    const bool exact_visible = !wall_hit.has_value() || *wall_hit >= glm::length(x - o.position);
    const bool ism_visible = visibility[i] >= 0.5f;
    disagree += exact_visible != ism_visible ? 1 : 0;
    const std::vector<float> splatted(maps.splatted.begin() + static_cast<std::ptrdiff_t>(q.map * texels),
                                      maps.splatted.begin() + static_cast<std::ptrdiff_t>((q.map + 1) * texels));
    const auto taps = mirrored_taps(o, x, glm::vec3(q.normal), settings);
    const TapCount count =
        taps.empty() ? TapCount{}
                     : taps_clear_of(taps, o, splatted, settings.side, surface, exact_visible ? face_of_query(q) : -1);
    if (taps.empty() || count.clear < count.possible) {
      ++band;
      continue;
    }
    (exact_visible ? lit_outside_band : shadowed_outside_band) += 1;
    EXPECT_EQ(ism_visible, exact_visible) << "query " << i << " (map " << q.map << ") outside the band: ISM "
                                          << visibility[i] << ", exact " << (exact_visible ? "visible" : "occluded");
  }
  // Disagreements lie in the band only, so the band's share bounds theirs; it must leave receivers,
  // lit and shadowed, to test.
  EXPECT_LE(disagree, band);
  EXPECT_LT(band, queries.size() * 2 / 3) << "the band covers most receivers";
  EXPECT_GT(shadowed_outside_band, 500u);
  EXPECT_GT(lit_outside_band, 1000u);
  RecordProperty("queries", static_cast<int>(queries.size()));
  RecordProperty("band", static_cast<int>(band));
  RecordProperty("disagreements", static_cast<int>(disagree));
}

}  // namespace
}  // namespace vsgl
