// The k-means generators on the GPU against their CPU reference (DESIGN.md §6.2, §11): features and
// seeds bit-exact, the grid-accelerated assignment equal to brute force over the GPU's own
// centres for every texel, the sort a stable permutation with correct ranges, the per-cluster
// sums equal to double-precision sums, sum of cluster power = total flux, the segmented sum equal
// to the sequential one, and adversarial cases (one cluster, empty clusters, N = samplable
// texels, a PDF concentrated in a corner).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "gpu_test.hpp"
#include "tiny_capture.hpp"
#include "harness/scene/capture_recorder.hpp"
#include "harness/vk/command_stream.hpp"
#include "harness/generators/device_view.hpp"
#include "harness/core/error.hpp"
#include "harness/generators/kmeans/kmeans_generator.hpp"
#include "harness/reference/kmeans_reference.hpp"
#include "harness/scene/scene.hpp"

namespace vsgl {
namespace {

struct GpuResult {
  std::vector<glm::vec4> features;
  std::vector<glm::vec4> centres;
  std::vector<uint32_t> assignment;
  KmeansSort sorted;
  std::vector<VsglRecord> vsgls;
};

// Tolerance of a float sum of n positive terms against the exact (double) sum: n * eps relative,
// with eps = 2^-24, generously 4x (sequential float summation error bound).
double float_sum_tolerance(double sum_of_abs, std::size_t terms) {
  return 4.0 * static_cast<double>(terms) * 0x1p-24 * sum_of_abs + 1e-12;
}

class KmeansGeneratorTest : public test::GpuTest {
 protected:
  // Recorded once for the whole suite.
  static const Capture& tiny_capture(Device& device) {
    static const Capture capture = test::record_tiny_with_flux_pdf(device);
    return capture;
  }
  const Capture& tiny() { return tiny_capture(device()); }

  GpuResult run(const DeviceView& view, KmeansSpace space, const KmeansParams& params) {
    KmeansGenerator gen(device(), view, space, params);
    run_untimed(device(), gen);
    const std::size_t n = std::size_t{view.square.width} * view.square.height;
    const uint32_t N = params.vsgl_count;
    GpuResult r;
    r.features = download_vector<glm::vec4>(device(), gen.features(), n);
    r.centres = download_vector<glm::vec4>(device(), gen.centres(), N);
    r.assignment = download_vector<uint32_t>(device(), gen.assignment(), n);
    r.sorted.pairs = download_vector<glm::uvec2>(device(), gen.sorted_pairs(), n);
    r.sorted.ranges = download_vector<glm::uvec2>(device(), gen.ranges(), N);
    r.vsgls = download_vector<VsglRecord>(device(), gen.vsgls(), N);
    return r;
  }

  // Every property of DESIGN.md §11 that holds for any centres: checked against the GPU's own centres.
  static void check_consistency(const ViewImage& image, const DeviceView& view, KmeansSpace space,
                                const GpuResult& gpu) {
    const std::vector<glm::vec4> features = kmeans_features(image, view.source_position, space);
    ASSERT_EQ(gpu.features.size(), features.size());
    for (std::size_t t = 0; t < features.size(); ++t) ASSERT_EQ(gpu.features[t], features[t]) << "feature of texel " << t;

    // Exact nearest centre for every texel, equal to brute force (ties to the lower id).
    const std::vector<uint32_t> brute = brute_force_assignment(features, gpu.centres);
    for (std::size_t t = 0; t < brute.size(); ++t) ASSERT_EQ(gpu.assignment[t], brute[t]) << "texel " << t;

    // The stable sort is unique: equal to std::stable_sort of the same assignment; the ranges too.
    const uint32_t N = static_cast<uint32_t>(gpu.centres.size());
    const KmeansSort expected = sort_by_cluster(gpu.assignment, N);
    ASSERT_EQ(gpu.sorted.pairs, expected.pairs);
    ASSERT_EQ(gpu.sorted.ranges, expected.ranges);

    // Per-cluster sums against double sums of the same clusters.
    const std::vector<ClusterSums> sums = reference_cluster_sums(image, view.source_position, gpu.sorted);
    const std::vector<VsglRecord> ref = cluster_vsgls(sums, gpu.centres, space, view.square.size);
    double total_flux = 0.0, total_power = 0.0;
    for (uint32_t k = 0; k < N; ++k) {
      SCOPED_TRACE("cluster " + std::to_string(k));
      const VsglRecord& g = gpu.vsgls[k];
      const VsglRecord& e = ref[k];
      const std::size_t size = sums[k].texels;
      ASSERT_EQ(g.center_pdf.w, static_cast<float>(size)) << "texel count";
      EXPECT_EQ(g.level(), -1.0f);
      EXPECT_EQ(g.density(), 0.0f);
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(g.power_sharpness[c], sums[k].m0[c], float_sum_tolerance(sums[k].m0[c], size)) << "power " << c;
        total_power += static_cast<double>(g.power_sharpness[c]);
        total_flux += sums[k].m0[c];
      }
      if (size == 0) {
        EXPECT_EQ(g.power(), glm::vec3(0.0f));
        continue;
      }
      if (!(sums[k].m0.w > 0.0)) continue;  // only q: no power, no shape
      // mu is a ratio of float sums: relative to the scene's coordinate scale.
      const float scale = std::max(1.0f, glm::length(e.mu()));
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(g.position_variance[c], e.position_variance[c], 1e-4f * scale) << "mu";
      EXPECT_NEAR(g.center_pdf.x, e.center_pdf.x, 1e-5f);
      EXPECT_NEAR(g.center_pdf.y, e.center_pdf.y, 1e-5f);
      // The filtered normal and the specular lobe's axis are ratios of sums too (skip those whose
      // mean length nearly cancels).
      const float normal_length = static_cast<float>(glm::length(glm::dvec3(sums[k].m2)) / sums[k].m0.w);
      if (normal_length > 1e-2f) {
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(g.normal_length[c], e.normal_length[c], 1e-3f) << "normal";
      }
      const double specular = sums[k].m3.r + sums[k].m3.g + sums[k].m3.b;
      const float lobe_length =
          specular > 0.0 ? static_cast<float>(glm::length(glm::dvec3(sums[k].m4)) / specular) : 0.0f;
      if (lobe_length > 1e-2f) {
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(g.axis_level[c], e.axis_level[c], 1e-3f) << "axis";
      }
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(g.specular_power[c], sums[k].m3[c], float_sum_tolerance(sums[k].m3[c], size)) << "specular " << c;
    }
    // Sum of cluster power = the total flux (importance, camera view) of the clustered texels.
    EXPECT_NEAR(total_power, total_flux, 1e-5 * total_flux);
  }

  // Everything, plus the whole CPU reference (seeds, Lloyd iterations, final assignment).
  void check_against_reference(const ViewImage& image, KmeansSpace space, const KmeansParams& params,
                               const DeviceView& view, const GpuResult& gpu) {
    check_consistency(image, view, space, gpu);
    // The whole run equals the CPU's only where division is correctly rounded (lavapipe): a seed
    // one ulp off elsewhere may flip an equidistant texel, after which both Lloyd runs are right
    // but differ. check_consistency() above holds on every device.
    if (!test::division_is_correctly_rounded()) return;
    const KmeansResult ref = reference_kmeans(image, view.source_position, space, params);
    for (uint32_t k = 0; k < params.vsgl_count; ++k)
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(gpu.centres[k][c], ref.centres[k][c], 1e-6f * std::max(1.0f, std::abs(ref.centres[k][c])))
            << "centre " << k;
    std::size_t differing = 0;
    for (std::size_t t = 0; t < gpu.assignment.size(); ++t) differing += gpu.assignment[t] != ref.assignment[t];
    EXPECT_EQ(differing, 0u) << "texels assigned differently from the CPU reference";
  }
};

TEST_F(KmeansGeneratorTest, MatchesTheCpuReferenceOnBothViews) {
  for (KmeansSpace space : {KmeansSpace::k2d, KmeansSpace::k3d}) {
    for (ViewKind kind : {ViewKind::kCamera, ViewKind::kLight}) {
      SCOPED_TRACE(std::string(kmeans_generator_name(space, false)) + " " + view_name(kind));
      const DeviceView view = upload_view(device(), tiny(), kind);
      KmeansParams params;
      params.vsgl_count = kind == ViewKind::kCamera ? 128 : 64;
      const GpuResult gpu = run(view, space, params);
      check_against_reference(tiny().view(kind), space, params, view, gpu);
    }
  }
}

TEST_F(KmeansGeneratorTest, SeedsAreTheKernelCentresOfSpec5) {
  const DeviceView view = upload_view(device(), tiny(), ViewKind::kCamera);
  for (KmeansSpace space : {KmeansSpace::k2d, KmeansSpace::k3d}) {
    KmeansParams params;
    params.vsgl_count = 200;
    params.iterations = 0;
    const GpuResult gpu = run(view, space, params);
    const auto seeds = kmeans_seeds(tiny().gbuffer, view.source_position, space, params.vsgl_count, 0);
    if (test::division_is_correctly_rounded()) {
      ASSERT_EQ(gpu.centres, seeds);
    } else {  // the sampler's rescaling divides: allow its rounding, not another texel
      ASSERT_EQ(gpu.centres.size(), seeds.size());
      for (std::size_t k = 0; k < seeds.size(); ++k)
        for (int c = 0; c < 3; ++c)
          ASSERT_NEAR(gpu.centres[k][c], seeds[k][c], 1e-5f * std::max(1.0f, std::abs(seeds[k][c]))) << "seed " << k;
    }
    check_consistency(tiny().gbuffer, view, space, gpu);
  }
}

TEST_F(KmeansGeneratorTest, SegmentedSumEqualsTheSequentialSum) {
  for (KmeansSpace space : {KmeansSpace::k2d, KmeansSpace::k3d}) {
    const DeviceView view = upload_view(device(), tiny(), ViewKind::kLight);
    KmeansParams params;
    params.vsgl_count = 3;  // large clusters: many pieces each
    const GpuResult sequential = run(view, space, params);
    params.segmented_sum = true;
    const GpuResult segmented = run(view, space, params);
    ASSERT_EQ(segmented.assignment, sequential.assignment);
    check_consistency(tiny().rsm, view, space, segmented);
    for (uint32_t k = 0; k < params.vsgl_count; ++k) {
      const VsglRecord& a = segmented.vsgls[k];
      const VsglRecord& b = sequential.vsgls[k];
      EXPECT_EQ(a.center_pdf.w, b.center_pdf.w);
      for (int c = 0; c < 4; ++c) {
        EXPECT_NEAR(a.power_sharpness[c], b.power_sharpness[c], 1e-4f * std::abs(b.power_sharpness[c]) + 1e-9f);
        EXPECT_NEAR(a.position_variance[c], b.position_variance[c], 1e-4f * std::max(1.0f, std::abs(b.position_variance[c])));
        EXPECT_NEAR(a.axis_level[c], b.axis_level[c], 1e-4f);
        EXPECT_NEAR(a.center_pdf[c], b.center_pdf[c], 1e-5f * std::max(1.0f, std::abs(b.center_pdf[c])));
      }
    }
  }
}

TEST_F(KmeansGeneratorTest, OneClusterHoldsEveryClusteredTexel) {
  const DeviceView view = upload_view(device(), tiny(), ViewKind::kCamera);
  KmeansParams params;
  params.vsgl_count = 1;
  const GpuResult gpu = run(view, KmeansSpace::k3d, params);
  check_against_reference(tiny().gbuffer, KmeansSpace::k3d, params, view, gpu);
  std::size_t members = 0;
  for (const glm::vec4& f : gpu.features) members += f.w >= 0.0f;
  EXPECT_GT(members, 0u);
  EXPECT_EQ(gpu.sorted.ranges[0], glm::uvec2(0u, static_cast<uint32_t>(members)));
}

TEST_F(KmeansGeneratorTest, AsManyClustersAsSamplableTexelsLeavesEmptyClustersIntact) {
  for (KmeansSpace space : {KmeansSpace::k3d, KmeansSpace::k2d}) {
    SCOPED_TRACE(kmeans_generator_name(space, false));
    const DeviceView view = upload_view(device(), tiny(), ViewKind::kLight);
    KmeansParams params;
    params.vsgl_count = view.samplable_texels;
    params.iterations = 2;
    const GpuResult gpu = run(view, space, params);
    check_against_reference(tiny().rsm, space, params, view, gpu);
    std::size_t empty = 0;
    for (const glm::uvec2& r : gpu.sorted.ranges) empty += r.x == r.y;
    // Several seeds share a texel where the PDF is high: in 3D their centres coincide and all but
    // the lowest id stay empty.
    if (space == KmeansSpace::k3d) {
      EXPECT_GT(empty, 0u);
    }
  }
}

TEST_F(KmeansGeneratorTest, PdfConcentratedInOneCorner) {
  // Only the 40 valid texels nearest the bottom-left corner keep their PDF: every seed lands
  // there, and the far texels (still clustered: they have power) need wide grid searches.
  Capture capture = tiny();
  ViewImage& g = capture.gbuffer;
  std::vector<std::pair<float, std::size_t>> by_distance;
  for (uint32_t y = 0; y < g.height; ++y)
    for (uint32_t x = 0; x < g.width; ++x)
      if (g.at(kValid, x, y) != 0.0f && g.at(kPdf, x, y) > 0.0f)
        by_distance.emplace_back(glm::length(glm::vec2(static_cast<float>(x), static_cast<float>(g.height - 1 - y))),
                                 std::size_t{y} * g.width + x);
  ASSERT_GT(by_distance.size(), 40u);
  std::sort(by_distance.begin(), by_distance.end());
  for (std::size_t i = 40; i < by_distance.size(); ++i) g.planes[kPdf][by_distance[i].second] = 0.0f;
  const DeviceView view = upload_view(device(), capture, ViewKind::kCamera);
  ASSERT_EQ(view.samplable_texels, 40u);
  for (KmeansSpace space : {KmeansSpace::k2d, KmeansSpace::k3d}) {
    SCOPED_TRACE(kmeans_generator_name(space, false));
    KmeansParams params;
    params.vsgl_count = 8;
    const GpuResult gpu = run(view, space, params);
    check_against_reference(g, space, params, view, gpu);
  }
}

TEST_F(KmeansGeneratorTest, LargerImageNeedsMultiLevelScansAndTwoRadixPasses) {
  // 208 x 104 texels: the radix histograms (256 digits x 11 tiles) and the grid counts need two
  // scan levels, and N = 300 > 255 two radix passes.
  CaptureRecorder recorder(device());
  const Capture capture = recorder.record(make_scene("tiny"), RecordSizes{208, 104, 16}, 0, 1);
  const DeviceView view = upload_view(device(), capture, ViewKind::kCamera);
  KmeansParams params;
  params.vsgl_count = 300;
  params.iterations = 2;
  const GpuResult gpu = run(view, KmeansSpace::k2d, params);
  check_against_reference(capture.gbuffer, KmeansSpace::k2d, params, view, gpu);
}

TEST_F(KmeansGeneratorTest, OneCellGridGivesTheSameClusters) {
  // brute_force_grid = one cell holding every centre: the search is brute force on the GPU.
  const DeviceView view = upload_view(device(), tiny(), ViewKind::kCamera);
  KmeansParams params;
  params.vsgl_count = 100;
  const GpuResult grid = run(view, KmeansSpace::k3d, params);
  params.brute_force_grid = true;
  const GpuResult brute = run(view, KmeansSpace::k3d, params);
  EXPECT_EQ(grid.assignment, brute.assignment);
  EXPECT_EQ(grid.centres, brute.centres);
}

TEST_F(KmeansGeneratorTest, RejectsBadClusterCounts) {
  const DeviceView view = upload_view(device(), tiny(), ViewKind::kLight);
  KmeansParams p;
  p.vsgl_count = 0;
  EXPECT_THROW(KmeansGenerator(device(), view, KmeansSpace::k2d, p), InputError);
  p.vsgl_count = view.samplable_texels + 1;
  try {
    KmeansGenerator gen(device(), view, KmeansSpace::k3d, p);
    FAIL() << "N larger than the samplable texels was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("light_view"), std::string::npos) << e.what();
  }
  EXPECT_THROW(reference_kmeans(tiny().rsm, view.source_position, KmeansSpace::k3d, p), InputError);
}

}  // namespace
}  // namespace vsgl
