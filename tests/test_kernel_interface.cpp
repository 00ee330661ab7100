// The kernels and their host code share push constants and work-group sizes through
// kernels/include/interface/*.h; the headers' static_asserts check the C++ side. This test checks
// the GLSL side, in the embedded SPIR-V (no device needed): each kernel's push-constant block has
// the size of the header struct its host pushes, and its work-group size is specialization
// constants 0 (x) and 1 (y), which the host sets from the same header. A kernel that declares a
// block of its own, or a fixed local_size, fails here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "harness/vk/shader_registry.hpp"
#include "kernels/include/interface/brsm.h"
#include "kernels/include/interface/fis.h"
#include "kernels/include/interface/kmeans.h"
#include "kernels/include/interface/raster.h"
#include "kernels/include/interface/shading.h"
#include "kernels/include/interface/testing.h"

namespace vsgl {
namespace {

// What a module says about its interface: the push-constant block's size and the spec ids of
// the work-group size's x and y components (nullopt: a literal size).
struct ModuleInterface {
  std::optional<uint32_t> push_bytes;
  bool compute = false;
  std::optional<uint32_t> group_x_spec_id, group_y_spec_id;
};

// SPIR-V opcodes and enumerants used below (SPIR-V 1.5 specification, section 3).
enum : uint32_t {
  kOpEntryPoint = 15, kOpTypeInt = 21, kOpTypeFloat = 22, kOpTypeVector = 23, kOpTypeMatrix = 24,
  kOpTypeArray = 28, kOpTypeStruct = 30, kOpTypePointer = 32, kOpConstant = 43, kOpConstantComposite = 44,
  kOpSpecConstantComposite = 51,
  kOpVariable = 59, kOpDecorate = 71, kOpMemberDecorate = 72,
  kDecorationSpecId = 1, kDecorationArrayStride = 6, kDecorationMatrixStride = 7, kDecorationBuiltIn = 11,
  kDecorationOffset = 35, kBuiltInWorkgroupSize = 25, kStorageClassPushConstant = 9, kExecutionModelGLCompute = 5,
};

ModuleInterface read_interface(std::span<const uint32_t> words) {
  struct Inst {
    uint32_t op;
    std::vector<uint32_t> args;
  };
  std::map<uint32_t, Inst> defs;                                    // result id -> defining instruction
  std::map<uint32_t, std::map<uint32_t, uint32_t>> member_offsets;  // struct -> member -> offset
  std::map<uint32_t, std::map<uint32_t, uint32_t>> matrix_strides;  // struct -> member -> stride
  std::map<uint32_t, uint32_t> array_strides, spec_ids;
  std::optional<uint32_t> workgroup_size;
  std::vector<uint32_t> push_pointer_types;
  ModuleInterface out;
  for (std::size_t i = 5; i < words.size();) {
    const uint32_t count = words[i] >> 16, op = words[i] & 0xFFFFu;
    if (count == 0 || i + count > words.size()) throw std::runtime_error("malformed SPIR-V");
    const std::vector<uint32_t> a(words.begin() + static_cast<std::ptrdiff_t>(i) + 1,
                                  words.begin() + static_cast<std::ptrdiff_t>(i + count));
    i += count;
    switch (op) {
      case kOpEntryPoint: out.compute = out.compute || a.at(0) == kExecutionModelGLCompute; break;
      case kOpDecorate:
        if (a.at(1) == kDecorationSpecId) spec_ids[a.at(0)] = a.at(2);
        if (a.at(1) == kDecorationArrayStride) array_strides[a.at(0)] = a.at(2);
        if (a.at(1) == kDecorationBuiltIn && a.at(2) == kBuiltInWorkgroupSize) workgroup_size = a.at(0);
        break;
      case kOpMemberDecorate:
        if (a.at(2) == kDecorationOffset) member_offsets[a.at(0)][a.at(1)] = a.at(3);
        if (a.at(2) == kDecorationMatrixStride) matrix_strides[a.at(0)][a.at(1)] = a.at(3);
        break;
      case kOpTypeInt: case kOpTypeFloat: case kOpTypeVector: case kOpTypeMatrix: case kOpTypeArray:
      case kOpTypeStruct: case kOpTypePointer:
        defs[a.at(0)] = {op, {a.begin() + 1, a.end()}};
        if (op == kOpTypePointer && a.at(1) == kStorageClassPushConstant) push_pointer_types.push_back(a.at(0));
        break;
      case kOpConstant: case kOpConstantComposite: case kOpSpecConstantComposite:
        defs[a.at(1)] = {op, {a.begin() + 2, a.end()}};
        break;
      case kOpVariable:
        if (a.at(2) == kStorageClassPushConstant) {
          // The block's type: the pointee of the variable's pointer type.
          const uint32_t block = defs.at(a.at(0)).args.at(1);
          std::function<uint32_t(uint32_t, uint32_t)> size_of = [&](uint32_t type, uint32_t matrix_stride) -> uint32_t {
            const Inst& t = defs.at(type);
            switch (t.op) {
              case kOpTypeInt: case kOpTypeFloat: return t.args.at(0) / 8;
              case kOpTypeVector: return t.args.at(1) * size_of(t.args.at(0), 0);
              case kOpTypeMatrix: return t.args.at(1) * (matrix_stride ? matrix_stride : size_of(t.args.at(0), 0));
              case kOpTypeArray: return defs.at(t.args.at(1)).args.at(0) * array_strides.at(type);
              case kOpTypeStruct: {
                uint32_t end = 0;
                for (uint32_t m = 0; m < t.args.size(); ++m) {
                  const auto stride = matrix_strides[type].find(m);
                  const uint32_t member_stride = stride == matrix_strides[type].end() ? 0 : stride->second;
                  end = std::max(end, member_offsets[type].at(m) + size_of(t.args[m], member_stride));
                }
                return end;
              }
              default: throw std::runtime_error("unexpected type in a push-constant block");
            }
          };
          out.push_bytes = size_of(block, 0);
        }
        break;
      default: break;
    }
  }
  if (workgroup_size) {
    const Inst& composite = defs.at(*workgroup_size);
    if (composite.op == kOpSpecConstantComposite) {
      const auto spec = [&](uint32_t id) -> std::optional<uint32_t> {
        const auto it = spec_ids.find(id);
        return it == spec_ids.end() ? std::nullopt : std::optional<uint32_t>(it->second);
      };
      out.group_x_spec_id = spec(composite.args.at(0));
      out.group_y_spec_id = spec(composite.args.at(1));
    }
  }
  return out;
}

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
      {"brsm_pdf.comp", {sizeof(gpu::BrsmPush), 2}},
      {"scene.vert", {sizeof(gpu::RasterPush), 0}},
      {"capture.frag", {sizeof(gpu::RasterPush), 0}},
      {"test_division.comp", {sizeof(gpu::TestCountPush), 1}},
      {"test_vsgl_math.comp", {sizeof(gpu::TestCountPush), 1}},
      {"test_workload.comp", {sizeof(gpu::TestWorkloadPush), 1}},
  };
  return table;
}

TEST(KernelInterface, EveryKernelPushesItsHeaderStructAndTakesItsGroupSizeAsSpecConstants) {
  for (const auto& [name, expected] : kernels()) {
    SCOPED_TRACE(name);
    const ModuleInterface m = read_interface(find_shader(name));
    ASSERT_TRUE(m.push_bytes.has_value()) << "no push-constant block";
    EXPECT_EQ(*m.push_bytes, expected.push_bytes) << "the GLSL block differs from the header struct";
    EXPECT_EQ(m.compute, expected.dims > 0);
    if (expected.dims == 0) continue;
    EXPECT_EQ(m.group_x_spec_id, std::optional<uint32_t>(0u)) << "local_size_x must be local_size_x_id = 0";
    EXPECT_EQ(m.group_y_spec_id, expected.dims == 2 ? std::optional<uint32_t>(1u) : std::nullopt)
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

// The reader itself can fail: on a hand-made module with a literal work-group size (an
// OpConstantComposite decorated WorkgroupSize, as `local_size_x = 64` compiles to) and an
// 8-byte block, it reports no spec ids and 8 bytes.
TEST(KernelInterface, ReaderSeesALiteralGroupSizeAndTheBlockSize) {
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
  const ModuleInterface m = read_interface(words);
  EXPECT_EQ(m.push_bytes, std::optional<uint32_t>(8u));
  EXPECT_TRUE(m.compute);
  EXPECT_FALSE(m.group_x_spec_id.has_value());
  EXPECT_FALSE(m.group_y_spec_id.has_value());
}

}  // namespace
}  // namespace vsgl
