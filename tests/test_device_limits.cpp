// Device limits are checked before a pipeline is created, and a FIS mip strategy or pyramid path
// that does not fit falls back to one that does, naming the limit. The CPU tests take lavapipe's
// numbers apart from the limit they force; the GPU tests run a real second device on the test
// device with a forced limit, so the fallback is exercised end to end on any driver.
#include <gtest/gtest.h>

#include "gpu_test.hpp"
#include "tiny_capture.hpp"
#include "harness/core/error.hpp"
#include "harness/core/json_reader.hpp"
#include "harness/generators/device_view.hpp"
#include "harness/generators/fis/fis_generator.hpp"
#include "harness/generators/generator_descriptor.hpp"
#include "harness/math/vsgl_math.hpp"
#include "harness/vk/compute_pipeline.hpp"
#include "harness/vk/image.hpp"
#include "harness/vk/device_limits.hpp"
#include "harness/vk/spirv_reflection.hpp"
#include "harness/vk/shader_registry.hpp"
#include "kernels/include/interface/fis.h"

namespace vsgl {
namespace {

// A device with generous limits and every RGBA32F feature (what lavapipe reports, roughly).
DeviceInfo roomy_device() {
  DeviceInfo d;
  d.name = "forced-limits device";
  d.type = VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU;
  d.rgba32f_features = VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT |
                       VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT | VK_FORMAT_FEATURE_BLIT_SRC_BIT |
                       VK_FORMAT_FEATURE_BLIT_DST_BIT;
  DeviceLimits& l = d.limits;
  l.per_stage_storage_images = l.per_stage_sampled_images = l.per_stage_samplers = 1000;
  l.per_stage_storage_buffers = l.per_stage_uniform_buffers = l.per_stage_resources = 1000;
  l.set_storage_images = l.set_sampled_images = l.set_samplers = 1000;
  l.set_storage_buffers = l.set_uniform_buffers = 1000;
  l.bound_descriptor_sets = 8;
  l.push_constants_size = 128;
  l.compute_shared_memory = 32768;
  l.workgroup_size[0] = l.workgroup_size[1] = 1024;
  l.workgroup_size[2] = 64;
  l.workgroup_invocations = 1024;
  l.rgba32f_optimal_tiling = {true, true, true, true, true};
  return d;
}

// The driver's numbers become the one DeviceLimits every document writes (core/device_limits.hpp):
// the format features are read bit by bit, and the limits object reads back as it was written,
// but for the offset alignment, which no file holds.
TEST(DeviceLimits, TheDriversLimitsAreTheDocumentsLimitsAndReadBackAsWritten) {
  VkPhysicalDeviceProperties props{};
  props.limits.maxPerStageDescriptorStorageImages = 16;
  props.limits.maxComputeWorkGroupSize[2] = 64;
  props.limits.maxComputeWorkGroupCount[1] = 65535;
  props.limits.minStorageBufferOffsetAlignment = 256;
  const DeviceLimits l =
      read_device_limits(props, 1ull << 32, 32, VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT | VK_FORMAT_FEATURE_BLIT_DST_BIT);
  EXPECT_FALSE(l.rgba32f_optimal_tiling.sampled_image);
  EXPECT_TRUE(l.rgba32f_optimal_tiling.storage_image);
  EXPECT_FALSE(l.rgba32f_optimal_tiling.blit_src);
  EXPECT_TRUE(l.rgba32f_optimal_tiling.blit_dst);
  EXPECT_EQ(l.storage_buffer_offset_alignment, 256u);

  const nlohmann::ordered_json j = to_json(l);
  EXPECT_EQ(j["maxPerStageDescriptorStorageImages"], 16u);
  EXPECT_EQ(j["maxComputeWorkGroupSize"], nlohmann::ordered_json({0u, 0u, 64u}));
  EXPECT_EQ(j["rgba32f_optimal_tiling"]["blit_dst"], true);
  EXPECT_FALSE(j.contains("minStorageBufferOffsetAlignment"));
  const DeviceLimits back = device_limits_from_json(JsonReader("limits", JsonPathStyle::kPointer), j, "/limits");
  EXPECT_EQ(to_json(back), j);
  EXPECT_EQ(back.workgroup_count[1], 65535u);
  EXPECT_EQ(back.max_memory_allocation_size, 1ull << 32);
  EXPECT_EQ(back.storage_buffer_offset_alignment, 1u);

  nlohmann::ordered_json unknown = j;
  unknown["maxFramebufferWidth"] = 4096u;
  try {
    device_limits_from_json(JsonReader("limits", JsonPathStyle::kPointer), unknown, "/limits");
    FAIL() << "an unknown limit was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/limits/maxFramebufferWidth: is not a known limit"), std::string::npos)
        << e.what();
  }
}

TEST(DeviceLimits, SinglePassNeedsAtMostEightStorageImagesPerDispatch) {
  uint32_t most = 0;
  for (const auto& desc : fis_pipelines(PyramidPath::kTexture, MipStrategy::kSinglePass))
    most = std::max(most, pipeline_needs(desc).storage_images);
  EXPECT_EQ(most, 8u);  // the tail: levels 7..14
  const auto tiles = pipeline_needs({"fis_mip_single_pass.comp",
                                     1,
                                     sizeof(gpu::FisMipPush),
                                     {{0, 16}, {1, 16}},
                                     {{VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1}, {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 6}}});
  EXPECT_EQ(tiles.storage_images, 7u);
  EXPECT_EQ(tiles.workgroup_size[0] * tiles.workgroup_size[1], 256u);
  EXPECT_GT(tiles.shared_memory_bytes, 0u);
}

TEST(DeviceLimits, SwiftShadersSixteenStorageImagesRunEveryStrategyAsAsked) {
  DeviceInfo d = roomy_device();
  d.limits.per_stage_storage_images = d.limits.set_storage_images = 16;
  for (MipStrategy m : {MipStrategy::kSinglePass, MipStrategy::kBlit, MipStrategy::kPerLevel}) {
    std::string reason;
    EXPECT_EQ(effective_mip_strategy(d, m, &reason), m) << reason;
    EXPECT_TRUE(reason.empty()) << reason;
  }
}

TEST(DeviceLimits, TooFewStorageImagesMakeTheSinglePassFallBackNamingTheLimit) {
  DeviceInfo d = roomy_device();
  d.limits.per_stage_storage_images = 4;  // the spec's guaranteed minimum
  const std::string why = fis_unfit_reason(d, PyramidPath::kTexture, MipStrategy::kSinglePass);
  EXPECT_NE(why.find("maxPerStageDescriptorStorageImages"), std::string::npos) << why;
  EXPECT_NE(why.find("needs 7 where the device allows 4"), std::string::npos) << why;
  std::string reason;
  EXPECT_EQ(effective_mip_strategy(d, MipStrategy::kSinglePass, &reason), MipStrategy::kBlit);
  EXPECT_NE(reason.find("maxPerStageDescriptorStorageImages"), std::string::npos) << reason;
  EXPECT_NE(reason.find("blit is used instead"), std::string::npos) << reason;
  // Without RGBA32F blits, per-level (2 storage images) is next.
  d.rgba32f_features &= ~VkFormatFeatureFlags{VK_FORMAT_FEATURE_BLIT_DST_BIT};
  EXPECT_EQ(effective_mip_strategy(d, MipStrategy::kSinglePass, &reason), MipStrategy::kPerLevel);
  GeneratorConfig config;
  config.pyramid = PyramidPath::kTexture;
  config.mipmapping = MipStrategy::kSinglePass;
  EXPECT_EQ(resolve_fis_config(d, config).mipmapping, MipStrategy::kPerLevel);
}

TEST(DeviceLimits, NoStrategyFitsSoTheTexturePathFallsBackToTheBuffer) {
  DeviceInfo d = roomy_device();
  d.limits.per_stage_storage_images = 1;  // per-level needs 2, single-pass 7
  d.rgba32f_features &= ~VkFormatFeatureFlags{VK_FORMAT_FEATURE_BLIT_SRC_BIT};
  d.limits.rgba32f_optimal_tiling.blit_src = false;
  EXPECT_THROW(effective_mip_strategy(d, std::nullopt), DeviceError);
  std::string reason;
  EXPECT_EQ(effective_pyramid_path(d, PyramidPath::kTexture, &reason), PyramidPath::kBuffer);
  EXPECT_NE(reason.find("maxPerStageDescriptorStorageImages"), std::string::npos) << reason;
}

TEST(DeviceLimits, NothingFitsIsADeviceErrorNamingLimitValueAndNeed) {
  DeviceInfo d = roomy_device();
  d.limits.per_stage_storage_buffers = 1;  // the buffer path binds 5: the view's 4 layers and the pyramid
  d.limits.per_stage_storage_images = 0;
  try {
    (void)effective_pyramid_path(d, PyramidPath::kTexture);
    FAIL() << "no DeviceError";
  } catch (const DeviceError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("maxPerStageDescriptorStorageBuffers"), std::string::npos) << m;
    EXPECT_NE(m.find("needs 5 where the device allows 1"), std::string::npos) << m;
  }
}

TEST(DeviceLimits, EveryLimitKindIsChecked) {
  const DeviceInfo d = roomy_device();
  PipelineNeeds n;
  n.name = "k";
  EXPECT_TRUE(shortfalls(d.limits, n).empty());
  n.push_constant_bytes = 129;
  n.shared_memory_bytes = 32769;
  n.workgroup_size[0] = 2048;
  n.sampled_images = 1001;
  const auto s = shortfalls(d.limits, n);
  std::string all;
  for (const auto& x : s) all += x.limit + " ";
  for (const char* limit : {"maxPushConstantsSize", "maxComputeSharedMemorySize", "maxComputeWorkGroupSize[0]",
                            "maxComputeWorkGroupInvocations", "maxPerStageDescriptorSampledImages",
                            "maxDescriptorSetSampledImages", "maxPerStageResources"})
    EXPECT_NE(all.find(limit), std::string::npos) << limit << " not in: " << all;
}

TEST(DeviceLimits, ReflectionSeesACombinedSamplerAndSpecializedGroupSize) {
  const auto k = reflect_kernel(find_shader("fis_filtered_sampling_texture.comp"), {{0, 64}});
  bool sampler = false;
  for (const auto& d : k.descriptors) sampler = sampler || d.type == VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  EXPECT_TRUE(sampler);
  EXPECT_EQ(k.workgroup_size[0], 64u);
  EXPECT_EQ(k.push_constant_bytes, sizeof(gpu::FisSamplingPush));
}

class DeviceLimitsTest : public test::GpuTest {};

// The test device itself, with maxPerStageDescriptorStorageImages forced to 4: the pipeline
// check refuses the single pass before creating it, and the generator falls back to a strategy
// that fits and still matches the CPU reference's VSGL count.
TEST_F(DeviceLimitsTest, ForcedLimitRefusesThePipelineAndTheGeneratorFallsBack) {
  DeviceInfo forced = device().info();
  forced.limits.per_stage_storage_images = 4;
  Device limited(test::shared_context().instance(), forced);
  try {
    ComputePipeline p(limited, fis_pipelines(PyramidPath::kTexture, MipStrategy::kSinglePass)[1]);
    FAIL() << "the single pass's pipeline was created over the limit";
  } catch (const DeviceError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("maxPerStageDescriptorStorageImages"), std::string::npos) << m;
    EXPECT_NE(m.find("allows 4"), std::string::npos) << m;
  }
  const Capture capture = test::record_tiny_with_flux_pdf(device());
  const DeviceView view = upload_view(limited, capture, ViewKind::kCamera);
  FisParams params;
  params.vsgl_count = 64;
  params.pyramid = PyramidPath::kTexture;
  params.mipmapping = MipStrategy::kSinglePass;
  FisGenerator gen(limited, view, FisVariant::kModified, params);
  EXPECT_NE(gen.mip_strategy(), MipStrategy::kSinglePass);
  run_untimed(limited, gen);
  const auto got = download_vector<VsglRecord>(limited, gen.vsgls(), params.vsgl_count);
  float power = 0.0f;
  for (const auto& v : got) power += v.power_sharpness.x;
  EXPECT_GT(power, 0.0f);
}

// Buffers and images are checked against maxMemoryAllocationSize, maxStorageBufferRange,
// maxImageDimension2D and maxImageArrayLayers before they are created or bound.
TEST_F(DeviceLimitsTest, ForcedSizeLimitsRefuseBuffersImagesAndBindings) {
  DeviceInfo forced = device().info();
  forced.limits.max_memory_allocation_size = 1024;
  forced.limits.storage_buffer_range = 256;
  forced.limits.image_dimension_2d = 64;
  forced.limits.image_array_layers = 2;
  Device limited(test::shared_context().instance(), forced);
  const auto expect_device_error = [](const auto& make, const char* limit) {
    try {
      make();
      ADD_FAILURE() << "no DeviceError for " << limit;
    } catch (const DeviceError& e) {
      EXPECT_NE(std::string(e.what()).find(limit), std::string::npos) << e.what();
    }
  };
  expect_device_error([&] { Buffer b(limited, 2048, MemoryUsage::kDeviceLocal, "test.too_big"); },
                      "maxMemoryAllocationSize");
  expect_device_error(
      [&] {
        MipImage i(limited, 128, 1, 1, VK_FORMAT_R32G32B32A32_SFLOAT, VK_IMAGE_USAGE_STORAGE_BIT, "test.too_wide");
      },
      "maxImageDimension2D");
  expect_device_error(
      [&] { MipImage i(limited, 32, 1, 3, VK_FORMAT_R32G32B32A32_SFLOAT, VK_IMAGE_USAGE_STORAGE_BIT, "test.layers"); },
      "maxImageArrayLayers");
  Buffer in(limited, 512, MemoryUsage::kDeviceLocal, "test.range.in");
  Buffer out(limited, 512, MemoryUsage::kDeviceLocal, "test.range.out");
  ComputePipeline pipeline(
      limited, {"test_division.comp", 2, sizeof(gpu::TestCountPush), work_group_size_1d(gpu::kTestGroupSize)});
  expect_device_error([&] { BindingSet set(limited, pipeline, {in, out}, "test.range.set"); }, "maxStorageBufferRange");
  BindingSet fits(limited, pipeline, {BufferBinding(in, 0, 256), BufferBinding(out, 0, 256)}, "test.range.fits");
}

}  // namespace
}  // namespace vsgl
