#pragma once
// `vsgl-bench frame` as a library function (DESIGN.md §9.2): the paper's frame timed phase by phase
// on the device for each generator — the recorded RSM replayed into the buffer the generators read,
// the BRSM PDF built, the N light-view VSGLs generated, their imperfect shadow maps built, and the
// camera view shaded with them (visibility ism) — each phase between two Vulkan timestamps in one
// command buffer per (generator, frame), replayed by the timing runner (timing/timing_runner.hpp:
// warm-ups, interleaved rounds, the stop rule), so sample i of every phase and generator is round i
// and the frame of round i is the sum of its phases. Writes OUT/frame.json (validated against
// results/schema/frame.schema.json) and OUT/frame.md, atomically, after everything is measured.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "harness/formats/frame_model.hpp"
#include "harness/generators/generator_descriptor.hpp"
#include "harness/timing/timing_runner.hpp"
#include "harness/visibility/ism_settings.hpp"

namespace vsgl {

class Device;

struct FrameOptions {
  std::filesystem::path capture_dir;        // required: a capture with its visibility geometry
  std::filesystem::path out_dir;            // required
  std::vector<std::string> generators;      // required, registry names
  uint32_t light_vsgls = kPaperLightVsgls;  // N (the paper's 1024)
  GeneratorConfig generator;                // K, iterations, pyramid, mipmapping (vsgl_count set here)
  IsmSettings ism;                          // side 64 (the paper's) by default
  uint32_t stride = 1;                      // the shading's G-buffer stride; > 1 is not the paper's size
  TimingOptions timing;
  bool quick = false, validation = false, clocks_locked = false;  // recorded in the run header
  bool json_only = false;                                         // no frame.md
  std::optional<std::filesystem::path> schema;                    // none: the built-in copy
};

struct FrameOutcome {
  FrameModel model;
  std::string markdown;
  std::vector<std::filesystem::path> written;
};

// Throws InputError for a capture without visibility geometry (naming `record --visibility-points`)
// or with too few points, DeviceLimitError where the maps or a pass do not fit the device,
// DeviceError for a device without timestamps; nothing is written then.
FrameOutcome run_frame(Device& device, const FrameOptions& options,
                       const std::function<void(const TimingProgress&)>& progress = {});

}  // namespace vsgl
