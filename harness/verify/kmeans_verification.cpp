#include "harness/verify/kmeans_verification.hpp"

#include <algorithm>
#include <cmath>

#include "harness/vk/command_stream.hpp"
#include "harness/vk/device.hpp"
#include "harness/generators/device_view.hpp"
#include "harness/generators/kmeans/kmeans_generator.hpp"
#include "harness/reference/kmeans_reference.hpp"

namespace vsgl {
namespace {

std::string num(double v, int digits = 3) { return check_number(v, digits); }

struct DeviceClusters {
  std::vector<glm::vec4> centres;
  std::vector<uint32_t> assignment;
  KmeansSort sorted;
  std::vector<VsglRecord> vsgls;
};

DeviceClusters run_on_device(Device& device, const DeviceView& view, KmeansSpace space, const KmeansParams& params) {
  KmeansGenerator gen(device, view, space, params);
  run_untimed(device, gen);
  const std::size_t texels = view.square.level_texels(0);
  const uint32_t N = params.vsgl_count;
  DeviceClusters out;
  out.centres = download_vector<glm::vec4>(device, gen.centres(), N);
  out.assignment = download_vector<uint32_t>(device, gen.assignment(), texels);
  out.sorted.pairs = download_vector<glm::uvec2>(device, gen.sorted_pairs(), texels);
  out.sorted.ranges = download_vector<glm::uvec2>(device, gen.ranges(), N);
  out.vsgls = download_vector<VsglRecord>(device, gen.vsgls(), N);
  return out;
}

void verify_view(Device& device, const Capture& capture, ViewKind kind, const VerifyConfig& config, uint32_t stride,
                 std::vector<CheckResult>& out) {
  const DeviceView view = upload_view(device, capture, kind);
  const ViewImage& image = capture.view(kind);
  KmeansParams params;
  params.vsgl_count = std::min(kind == ViewKind::kCamera ? config.camera_vsgls : config.light_vsgls,
                               view.samplable_texels);
  for (KmeansSpace space : {KmeansSpace::k2d, KmeansSpace::k3d}) {
    const std::string gen = kmeans_generator_name(space, false);
    auto result = [&](const std::string& check) {
      CheckResult r;
      r.view = view.label;
      r.generator = gen;
      r.check = check;
      return r;
    };
    const DeviceClusters gpu = run_on_device(device, view, space, params);
    const std::vector<glm::vec4> features = kmeans_features(image, view.source_position, space);

    // Nearest centre, by brute force over every centre, on every stride-th texel.
    std::vector<glm::vec4> subset;
    std::vector<std::size_t> index;
    for (std::size_t t = 0; t < features.size(); t += stride) {
      subset.push_back(features[t]);
      index.push_back(t);
    }
    const std::vector<uint32_t> brute = brute_force_assignment(subset, gpu.centres);
    CheckResult assignment = result("assignment");
    for (std::size_t i = 0; i < subset.size(); ++i) assignment.measured += gpu.assignment[index[i]] != brute[i] ? 1 : 0;
    assignment.detail = "texels (of " + num(static_cast<double>(subset.size()), 9) +
                        " checked, every " + num(stride) + "th) not at their nearest centre (brute force, ties to the lower id)";
    out.push_back(assignment);

    // The stable sort is unique: it must equal std::stable_sort of the device's assignment.
    const KmeansSort expected = sort_by_cluster(gpu.assignment, params.vsgl_count);
    CheckResult sort = result("sort");
    for (std::size_t i = 0; i < expected.pairs.size(); ++i) sort.measured += gpu.sorted.pairs[i] != expected.pairs[i] ? 1 : 0;
    for (std::size_t k = 0; k < expected.ranges.size(); ++k) sort.measured += gpu.sorted.ranges[k] != expected.ranges[k] ? 1 : 0;
    sort.detail = "(cluster, texel) pairs and [begin, end) ranges differing from a stable sort of the assignment";
    out.push_back(sort);

    // Per-cluster power against double sums of the same texels, in units of a float-summation
    // bound (4 n 2^-24 of the cluster's power): the sequential sum may round once per texel.
    const std::vector<ClusterSums> sums = reference_cluster_sums(image, view.source_position, gpu.sorted);
    CheckResult cluster = result("cluster_sums");
    double total_power = 0, total_flux = 0;
    std::vector<uint32_t> sizes;
    uint32_t empty = 0;
    for (uint32_t k = 0; k < params.vsgl_count; ++k) {
      const double bound = 4.0 * (sums[k].texels + 1) * std::ldexp(1.0, -24);
      for (int c = 0; c < 3; ++c) {
        const double g = double{gpu.vsgls[k].power_sharpness[c]}, e = sums[k].m0[c];
        cluster.measured = std::max(cluster.measured, std::abs(g - e) / (bound * std::abs(e) + 1e-30));
        total_power += g;
        total_flux += e;
      }
      sizes.push_back(sums[k].texels);
      empty += sums[k].texels == 0 ? 1 : 0;
    }
    cluster.tolerance = 1;
    cluster.detail = "max per-cluster power error vs double sums, in units of 4 n 2^-24 of the cluster's power";
    out.push_back(cluster);

    CheckResult power = result("total_power");
    power.measured = total_flux > 0 ? std::abs(total_power - total_flux) / total_flux : 0;
    power.tolerance = 1e-5;
    power.detail = std::string("|sum of cluster power / ") + (kind == ViewKind::kCamera ? "reflectance" : "flux") +
                   " of the clustered texels - 1|";
    out.push_back(power);

    // Every clusterable texel is in exactly one cluster; the sizes are the cost of the paper's Sum.
    std::size_t clusterable = 0;
    for (const auto& f : features) clusterable += f.w >= 0.0f ? 1 : 0;
    std::size_t members = 0;
    for (uint32_t s : sizes) members += s;
    std::sort(sizes.begin(), sizes.end());
    CheckResult membership = result("clusters");
    membership.measured = static_cast<double>(std::max(members, clusterable) - std::min(members, clusterable));
    membership.detail = "clusterable texels not in exactly one cluster; sizes min/median/max " + num(sizes.front(), 9) +
                        "/" + num(sizes[sizes.size() / 2], 9) + "/" + num(sizes.back(), 9) + " texels, " +
                        num(empty, 9) + " empty of " + num(params.vsgl_count, 9);
    out.push_back(membership);
  }
}

}  // namespace

std::vector<CheckResult> verify_kmeans(Device& device, const Capture& capture, const VerifyConfig& config,
                                       uint32_t assignment_stride) {
  std::vector<CheckResult> out;
  for (ViewKind kind : {ViewKind::kCamera, ViewKind::kLight})
    verify_view(device, capture, kind, config, std::max(1u, assignment_stride), out);
  return out;
}

}  // namespace vsgl
