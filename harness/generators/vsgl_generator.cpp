#include "harness/generators/vsgl_generator.hpp"

#include "harness/vk/command_stream.hpp"
#include "harness/vk/device.hpp"

namespace vsgl {

void VsglGenerator::record_boundary(CommandStream& stream, const std::function<void(VkCommandBuffer)>& boundary) {
  boundary(stream.get());
}

void record_untimed(VsglGenerator& generator, CommandStream& stream) {
  generator.record(stream, [&](VkCommandBuffer) { stream.full_barrier(); });
}

void run_untimed(Device& device, VsglGenerator& generator) {
  device.submit_and_wait(
      [&](VkCommandBuffer cmd) {
        CommandStream stream(cmd);
        record_untimed(generator, stream);
      },
      generator.name());
}

}  // namespace vsgl
