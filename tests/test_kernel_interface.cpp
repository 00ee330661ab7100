// The kernels and their host code share push constants and work-group sizes through
// kernels/include/interface/*.h; the headers' static_asserts check the C++ side. This test checks
// the GLSL side, in the embedded SPIR-V as the harness reflects it (vk/spirv_reflection.hpp, the
// reader the pipelines' limit checks use; no device needed): each kernel's push-constant block has
// the size of the header struct its host pushes, and its work-group size is specialization
// constants 0 (x) and 1 (y), which the host sets from the same header. A kernel that declares a
// block of its own, or a fixed local_size, fails here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "harness/vk/shader_registry.hpp"
#include "harness/vk/spirv_reflection.hpp"
#include "kernels/include/interface/brsm.h"
#include "kernels/include/interface/fis.h"
#include "kernels/include/interface/ism.h"
#include "kernels/include/interface/kmeans.h"
#include "kernels/include/interface/raster.h"
#include "kernels/include/interface/shading.h"
#include "kernels/include/interface/testing.h"
#include "kernels/include/interface/visibility.h"

namespace vsgl {
namespace {

// The opcodes and enumerants the hand-made module below is written with (SPIR-V 1.5
// specification, section 3).
// clang-format off
enum : uint32_t {
  kOpEntryPoint = 15, kOpTypeInt = 21, kOpTypeVector = 23, kOpTypeStruct = 30, kOpTypePointer = 32,
  kOpConstant = 43, kOpConstantComposite = 44, kOpVariable = 59, kOpDecorate = 71, kOpMemberDecorate = 72,
  kDecorationBuiltIn = 11, kDecorationOffset = 35, kBuiltInWorkgroupSize = 25, kStorageClassPushConstant = 9,
  kExecutionModelGLCompute = 5,
};
// clang-format on

struct Expected {
  uint32_t push_bytes;
  int dims;  // 1: local_size_x_id = 0; 2: and local_size_y_id = 1; 0: not a compute kernel
};

// Every kernel, with the struct its host pushes.
const std::map<std::string, Expected>& kernels() {
  static const std::map<std::string, Expected> table = {
      {"fis_additional.comp", {sizeof(gpu::FisAdditionalPush), 2}},
      {"fis_additional_texture.comp", {sizeof(gpu::FisAdditionalPush), 2}},
      {"fis_mip_level.comp", {sizeof(gpu::FisMipPush), 2}},
      {"fis_mip_level_texture.comp", {sizeof(gpu::FisMipPush), 2}},
      {"fis_mip_single_pass.comp", {sizeof(gpu::FisMipPush), 2}},
      {"fis_mip_single_pass_tail.comp", {sizeof(gpu::FisMipPush), 2}},
      {"fis_filtered_sampling.comp", {sizeof(gpu::FisSamplingPush), 1}},
      {"fis_filtered_sampling_texture.comp", {sizeof(gpu::FisSamplingPush), 1}},
      {"kmeans_fill.comp", {sizeof(gpu::KmeansFillPush), 1}},
      {"kmeans_prepare.comp", {sizeof(gpu::KmeansPreparePush), 2}},
      {"kmeans_pdf_mip.comp", {sizeof(gpu::KmeansMipPush), 2}},
      {"kmeans_seed.comp", {sizeof(gpu::KmeansSeedPush), 1}},
      {"kmeans_grid_count.comp", {sizeof(gpu::KmeansGridPush), 1}},
      {"kmeans_grid_fill.comp", {sizeof(gpu::KmeansGridPush), 1}},
      {"kmeans_assign.comp", {sizeof(gpu::KmeansAssignPush), 1}},
      {"kmeans_scan_blocks.comp", {sizeof(gpu::KmeansScanPush), 1}},
      {"kmeans_scan_add.comp", {sizeof(gpu::KmeansScanPush), 1}},
      {"kmeans_radix_histogram.comp", {sizeof(gpu::KmeansRadixPush), 1}},
      {"kmeans_radix_scatter.comp", {sizeof(gpu::KmeansRadixPush), 1}},
      {"kmeans_ranges.comp", {sizeof(gpu::KmeansRangesPush), 1}},
      {"kmeans_update_pieces.comp", {sizeof(gpu::KmeansPiecesPush), 1}},
      {"kmeans_update_centres.comp", {sizeof(gpu::KmeansUpdatePush), 1}},
      {"kmeans_sum.comp", {sizeof(gpu::KmeansSumPush), 1}},
      {"kmeans_segsum_pieces.comp", {sizeof(gpu::KmeansSumPush), 1}},
      {"kmeans_segsum_clusters.comp", {sizeof(gpu::KmeansSumPush), 1}},
      {"shade_vsgls.comp", {sizeof(gpu::ShadePush), 2}},
      {"shade_vsgls_ism.comp", {sizeof(gpu::ShadeVisibilityPush), 2}},
      {"shade_vsgls_exact.comp", {sizeof(gpu::ShadeVisibilityPush), 2}},
      {"brsm_pdf.comp", {sizeof(gpu::BrsmPush), 2}},
      {"visibility_segments.comp", {sizeof(gpu::VisibilityPush), 1}},
      {"ism_splat.comp", {sizeof(gpu::IsmParams), 1}},
      {"ism_pull.comp", {sizeof(gpu::IsmPyramidPush), 1}},
      {"ism_push.comp", {sizeof(gpu::IsmPyramidPush), 1}},
      {"scene.vert", {sizeof(gpu::RasterPush), 0}},
      {"capture.frag", {sizeof(gpu::RasterPush), 0}},
      {"test_division.comp", {sizeof(gpu::TestCountPush), 1}},
      {"test_ism_lookup.comp", {sizeof(gpu::IsmQueryPush), 1}},
      {"test_vsgl_math.comp", {sizeof(gpu::TestCountPush), 1}},
      {"test_workload.comp", {sizeof(gpu::TestWorkloadPush), 1}},
  };
  return table;
}

TEST(KernelInterface, EveryKernelPushesItsHeaderStructAndTakesItsGroupSizeAsSpecConstants) {
  for (const auto& [name, expected] : kernels()) {
    SCOPED_TRACE(name);
    const KernelInterface m = reflect_kernel(find_shader(name));
    ASSERT_NE(m.push_constant_bytes, 0u) << "no push-constant block";
    EXPECT_EQ(m.push_constant_bytes, expected.push_bytes) << "the GLSL block differs from the header struct";
    EXPECT_EQ(m.compute, expected.dims > 0);
    if (expected.dims == 0) continue;
    EXPECT_EQ(m.workgroup_size_spec_ids[0], std::optional<uint32_t>(0u)) << "local_size_x must be local_size_x_id = 0";
    EXPECT_EQ(m.workgroup_size_spec_ids[1], expected.dims == 2 ? std::optional<uint32_t>(1u) : std::nullopt)
        << "local_size_y must be " << (expected.dims == 2 ? "local_size_y_id = 1" : "1");
  }
}

// A kernel missing from the table would go unchecked: every embedded module must be listed, and
// every listed name must be embedded (a renamed kernel leaves a stale row).
TEST(KernelInterface, EveryEmbeddedKernelIsListed) {
  const std::vector<std::string> embedded = shader_names();
  ASSERT_FALSE(embedded.empty()) << "no embedded SPIR-V";
  for (const std::string& name : embedded)
    EXPECT_TRUE(kernels().count(name)) << name << ": add it to the table of this test";
  for (const auto& [name, expected] : kernels())
    EXPECT_NE(std::find(embedded.begin(), embedded.end(), name), embedded.end()) << name << ": listed but not embedded";
}

// The reflection itself can fail: on a hand-made module with a literal work-group size (an
// OpConstantComposite decorated WorkgroupSize, as `local_size_x = 64` compiles to) and an
// 8-byte block, it reports no spec ids, the literal size and 8 bytes.
TEST(KernelInterface, ReflectionSeesALiteralGroupSizeAndTheBlockSize) {
  const std::vector<uint32_t> words = {
      0x07230203u, 0x00010500u, 0u, 9u, 0u,
      (4u << 16) | kOpEntryPoint, kExecutionModelGLCompute, 8u, 0u,
      (4u << 16) | kOpDecorate, 7u, kDecorationBuiltIn, kBuiltInWorkgroupSize,
      (5u << 16) | kOpMemberDecorate, 2u, 0u, kDecorationOffset, 0u,
      (5u << 16) | kOpMemberDecorate, 2u, 1u, kDecorationOffset, 4u,
      (4u << 16) | kOpTypeInt, 1u, 32u, 0u,
      (4u << 16) | kOpTypeStruct, 2u, 1u, 1u,
      (4u << 16) | kOpTypePointer, 3u, kStorageClassPushConstant, 2u,
      (4u << 16) | kOpTypeVector, 5u, 1u, 3u,
      (4u << 16) | kOpConstant, 1u, 6u, 64u,
      (6u << 16) | kOpConstantComposite, 5u, 7u, 6u, 6u, 6u,
      (4u << 16) | kOpVariable, 3u, 4u, kStorageClassPushConstant,
  };
  const KernelInterface m = reflect_kernel(words);
  EXPECT_EQ(m.push_constant_bytes, 8u);
  EXPECT_TRUE(m.compute);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_FALSE(m.workgroup_size_spec_ids[k].has_value()) << k;
    EXPECT_EQ(m.workgroup_size[k], 64u) << k;
  }
}

}  // namespace
}  // namespace vsgl
