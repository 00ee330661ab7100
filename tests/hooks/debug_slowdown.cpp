#include "debug_slowdown.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "harness/vk/buffer.hpp"
#include "harness/vk/command_stream.hpp"
#include "harness/vk/compute_pipeline.hpp"
#include "harness/vk/device.hpp"
#include "harness/vk/device_info.hpp"
#include "kernels/include/interface/testing.h"

namespace vsgl {
namespace {

class DebugSlowGenerator final : public VsglGenerator {
 public:
  DebugSlowGenerator(Device& device, std::unique_ptr<VsglGenerator> inner, DebugSlowWork work)
      : inner_(std::move(inner)),
        work_(work),
        out_(device, static_cast<VkDeviceSize>(work.invocations) * sizeof(uint32_t), MemoryUsage::kDeviceLocal,
             inner_->name() + ".debug_slow.out"),
        pipeline_(device,
                  {"test_workload.comp", 1, sizeof(gpu::TestWorkloadPush), work_group_size_1d(gpu::kTestGroupSize)}),
        set_(device, pipeline_, {out_}, inner_->name() + ".debug_slow.set") {}

  std::string name() const override { return inner_->name(); }
  std::vector<std::string> phases() const override { return inner_->phases(); }
  const Buffer& vsgls() const override { return inner_->vsgls(); }
  uint32_t vsgl_count() const override { return inner_->vsgl_count(); }

  void record(CommandStream& stream, const std::function<void(VkCommandBuffer)>& boundary) override {
    const std::size_t last = inner_->phases().size();  // index of the boundary after the last phase
    std::size_t calls = 0;
    inner_->record(stream, [&](VkCommandBuffer cmd) {
      if (calls++ == last) {  // inside the last phase, after the generator's own work
        stream.full_barrier();
        stream.dispatch(pipeline_, set_, gpu::TestWorkloadPush{work_.invocations, work_.iterations},
                        div_up(work_.invocations, gpu::kTestGroupSize));
      }
      boundary(cmd);
    });
    if (calls != last + 1)
      throw std::logic_error(inner_->name() + ": unexpected phase boundary count under --debug-slow");
  }

 private:
  std::unique_ptr<VsglGenerator> inner_;
  DebugSlowWork work_;
  Buffer out_;
  ComputePipeline pipeline_;
  BindingSet set_;
};

}  // namespace

DebugSlowWork DebugSlowWork::for_device(const DeviceInfo& info) {
  DebugSlowWork w;
  w.iterations = info.type == VK_PHYSICAL_DEVICE_TYPE_CPU ? 64u : 16384u;
  return w;
}

std::unique_ptr<VsglGenerator> with_debug_slowdown(Device& device, std::unique_ptr<VsglGenerator> inner,
                                                   DebugSlowWork work) {
  if (!inner) throw std::logic_error("with_debug_slowdown without a generator");
  return std::make_unique<DebugSlowGenerator>(device, std::move(inner), work);
}

GeneratorWrapper debug_slowdown_of(std::vector<std::string> names, uint32_t factor) {
  return [names = std::move(names), factor](Device& device, std::unique_ptr<VsglGenerator> generator) {
    if (std::find(names.begin(), names.end(), generator->name()) == names.end()) return generator;
    DebugSlowWork work = DebugSlowWork::for_device(device.info());
    work.iterations *= std::max(1u, factor);
    return with_debug_slowdown(device, std::move(generator), work);
  };
}

}  // namespace vsgl
