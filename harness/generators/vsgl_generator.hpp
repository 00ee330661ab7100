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
  virtual std::string name() const = 0;                 // its id (core/generator_ids.hpp)
  virtual std::vector<std::string> phases() const = 0;  // in execution order
  // Records every phase. `boundary` is called before the first phase, between phases and after
  // the last (phases().size() + 1 times) and must order the work on each side of it.
  virtual void record(CommandStream& stream, const std::function<void(VkCommandBuffer)>& boundary) = 0;
  virtual const Buffer& vsgls() const = 0;
  virtual uint32_t vsgl_count() const = 0;

 protected:
  // A phase as its generator names it (a row of the paper's tables) and the member function of
  // the generator that records it.
  template <class G>
  struct Phase {
    const char* name;
    void (G::*record)(CommandStream&);
  };

  template <class G>
  static std::vector<std::string> phase_names(const std::vector<Phase<G>>& phases) {
    std::vector<std::string> names;
    for (const Phase<G>& p : phases) names.emplace_back(p.name);
    return names;
  }

  // The skeleton every phased generator's record() shares: `boundary` before the first phase,
  // between each two and after the last, the phases recorded in their order.
  template <class G>
  static void record_phases(G& generator, CommandStream& stream, const std::function<void(VkCommandBuffer)>& boundary,
                            const std::vector<Phase<G>>& phases) {
    record_boundary(stream, boundary);
    for (const Phase<G>& p : phases) {
      (generator.*p.record)(stream);
      record_boundary(stream, boundary);
    }
  }

 private:
  static void record_boundary(CommandStream& stream, const std::function<void(VkCommandBuffer)>& boundary);
};

// The untimed run (correctness checks, verify, shading, the BRSM PDF): every phase recorded with
// a full barrier at each boundary, where a timed run writes a timestamp.
void record_untimed(VsglGenerator& generator, CommandStream& stream);
// The same, submitted on its own and waited for.
void run_untimed(Device& device, VsglGenerator& generator);

}  // namespace vsgl
