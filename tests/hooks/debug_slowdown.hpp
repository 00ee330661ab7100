#pragma once
// TEST BUILD ONLY (tests/hooks/, never linked into the shipped programs): `tables --debug-slow
// GENERATOR` of the test build of vsgl-bench (DESIGN.md §10). Wraps a generator so that its last
// phase also runs a fixed amount of extra work (one dispatch of kernels/test_workload.comp
// recorded just before the generator's final phase boundary), so that `vsgl-bench compare` can be
// shown to flag exactly that generator as SLOWER. Through TablesOptions::wrap_generator and
// altered_generators, the run records it (run.altered_generators in the table JSON) and every
// report of it says so; never use it for numbers that mean anything.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "harness/generators/generator_registry.hpp"
#include "harness/generators/vsgl_generator.hpp"

namespace vsgl {

class Device;

struct DeviceInfo;

struct DebugSlowWork {
  uint32_t invocations = 1u << 16;  // threads of the extra dispatch
  uint32_t iterations = 64;         // hash steps per thread

  // A few ms on a CPU device (lavapipe: 64 steps), about 0.1 ms on a GPU (16384 steps): well
  // above the noise of the FIS generators' last phase on either, far below a time cap.
  static DebugSlowWork for_device(const DeviceInfo& info);
};

// The wrapped generator has the same name, phases and output; its recording holds one more
// dispatch (also in its dispatch count).
std::unique_ptr<VsglGenerator> with_debug_slowdown(Device& device, std::unique_ptr<VsglGenerator> inner,
                                                   DebugSlowWork work);

// A wrapper for TablesOptions::wrap_generator (with the same names as altered_generators): slows the generators named
// in `names` by DebugSlowWork::for_device() with its iterations times `factor`, and leaves the others as they are.
GeneratorWrapper debug_slowdown_of(std::vector<std::string> names, uint32_t factor = 1);

}  // namespace vsgl
