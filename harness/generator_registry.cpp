#include "harness/generator_registry.hpp"

#include <algorithm>

#include "harness/error.hpp"
#include "harness/fis_generator.hpp"
#include "harness/kmeans_generator.hpp"

namespace vsgl {
namespace {

struct KmeansName {
  const char* name;
  KmeansSpace space;
  bool segmented_sum;
};
constexpr KmeansName kKmeans[] = {
    {"kmeans_2d", KmeansSpace::k2d, false},
    {"kmeans_3d", KmeansSpace::k3d, false},
    {"kmeans_2d_segsum", KmeansSpace::k2d, true},
    {"kmeans_3d_segsum", KmeansSpace::k3d, true},
};

const KmeansName* find_kmeans(const std::string& name) {
  for (const auto& k : kKmeans)
    if (name == k.name) return &k;
  return nullptr;
}

[[noreturn]] void unknown(const std::string& name) {
  std::string known;
  for (const auto& n : generator_names()) known += (known.empty() ? "" : ", ") + n;
  throw InputError("unknown generator '" + name + "' (known: " + known + ")");
}

}  // namespace

std::vector<std::string> generator_names() {
  return {"fis_tok15", "fis_modified", "kmeans_2d", "kmeans_3d", "kmeans_2d_segsum", "kmeans_3d_segsum"};
}

bool generator_in_paper(const std::string& name) {
  return name == "fis_tok15" || name == "fis_modified" || name == "kmeans_2d" || name == "kmeans_3d";
}

std::unique_ptr<VsglGenerator> make_generator(const std::string& name, Device& device, const DeviceView& view,
                                              const GeneratorConfig& config) {
  if (name == "fis_tok15" || name == "fis_modified") {
    FisParams p;
    p.vsgl_count = config.vsgl_count;
    p.K = config.K;
    p.bisection_iterations = config.bisection_iterations;
    p.offset_bits = config.offset_bits;
    return std::make_unique<FisGenerator>(device, view, name == "fis_tok15" ? FisVariant::kTok15 : FisVariant::kModified,
                                          p);
  }
  // ---- k-means generators (SPEC §6.2; harness/kmeans_generator.hpp) ----
  if (const KmeansName* k = find_kmeans(name)) {
    KmeansParams p;
    p.vsgl_count = config.vsgl_count;
    p.iterations = config.kmeans_iterations;
    p.segmented_sum = k->segmented_sum;
    p.offset_bits = config.offset_bits;
    return std::make_unique<KmeansGenerator>(device, view, k->space, p);
  }
  unknown(name);
}

GeneratorSources generator_sources(const std::string& name) {
  if (name == "fis_tok15" || name == "fis_modified")
    return {{"harness/fis_generator.hpp", "harness/fis_generator.cpp"},
            {"kernels/fis_additional.comp", "kernels/fis_mip_level.comp", "kernels/fis_filtered_sampling.comp"}};
  if (const KmeansName* k = find_kmeans(name)) {
    // The kernels KmeansGenerator builds pipelines from; the sum pass is kmeans_sum.comp
    // (sequential, the paper's) or the two segmented-reduction kernels.
    GeneratorSources s{{"harness/kmeans_generator.hpp", "harness/kmeans_generator.cpp"},
                       {"kernels/kmeans_fill.comp", "kernels/kmeans_prepare.comp", "kernels/kmeans_pdf_mip.comp",
                        "kernels/kmeans_seed.comp", "kernels/kmeans_grid_count.comp", "kernels/kmeans_grid_fill.comp",
                        "kernels/kmeans_assign.comp", "kernels/kmeans_scan_blocks.comp", "kernels/kmeans_scan_add.comp",
                        "kernels/kmeans_radix_histogram.comp", "kernels/kmeans_radix_scatter.comp",
                        "kernels/kmeans_ranges.comp", "kernels/kmeans_update_pieces.comp",
                        "kernels/kmeans_update_centres.comp"}};
    if (k->segmented_sum) {
      s.kernels.push_back("kernels/kmeans_segsum_pieces.comp");
      s.kernels.push_back("kernels/kmeans_segsum_clusters.comp");
    } else {
      s.kernels.push_back("kernels/kmeans_sum.comp");
    }
    return s;
  }
  unknown(name);
}

}  // namespace vsgl
