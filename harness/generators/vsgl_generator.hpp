#pragma once
// What the harness sees of a generator: named phases recorded into one command buffer, with a
// boundary between them (a timestamp when timed, a full barrier otherwise), producing N VSGL
// records in the layout of kernels/include/vsgl_math.glsl.
#include <vulkan/vulkan.h>

#include <functional>
#include <string>
#include <vector>

namespace vsgl {

class Buffer;
class CommandStream;
class Device;

class VsglGenerator {
 public:
  virtual ~VsglGenerator() = default;
  virtual std::string name() const = 0;                // e.g. "fis_modified"
  virtual std::vector<std::string> phases() const = 0;  // in execution order
  // Records every phase. `boundary` is called before the first phase, between phases and after
  // the last (phases().size() + 1 times) and must order the work on each side of it.
  virtual void record(CommandStream& stream, const std::function<void(VkCommandBuffer)>& boundary) = 0;
  virtual const Buffer& vsgls() const = 0;
  virtual uint32_t vsgl_count() const = 0;
};

// The untimed run (correctness checks, verify, shading, the BRSM PDF): every phase recorded with
// a full barrier at each boundary, where a timed run writes a timestamp.
void record_untimed(VsglGenerator& generator, CommandStream& stream);
// The same, submitted on its own and waited for.
void run_untimed(Device& device, VsglGenerator& generator);

}  // namespace vsgl
