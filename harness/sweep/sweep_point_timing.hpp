#pragma once
// One point of `vsgl-bench sweep` timed (DESIGN.md §10.1): its capture (on a pdf-sharpness axis
// with both views' PDFs raised to γ in memory, and their frequency measured), the tables' config
// and the interleaved timing of every generator on both views. What the device cannot hold ends
// only that case, or that point, with its reason: the device is unharmed and the sweep goes on.
#include <optional>
#include <vector>

#include "harness/formats/scene_identity.hpp"
#include "harness/sweep/measured_sweep.hpp"
#include "harness/sweep/sweep_capture_cache.hpp"
#include "harness/sweep/sweep_event.hpp"
#include "harness/sweep/sweep_point_setup.hpp"

namespace vsgl {

class Device;

struct SweepPointOutcome {
  std::optional<SweepPointResult> timed;         // none: the whole point is beyond the device
  std::vector<BeyondDevicePoint> beyond_device;  // the point, or the cases of it, the device cannot hold
  // The scene of the point's capture and the paper table whose input it is (0: none), when the
  // capture was had (MeasuredSweep::scene, paper_table).
  std::optional<SceneIdentity> scene;
  int paper_table = 0;
};

// Throws what the capture cache and the timing throw but DeviceLimitError, which it keeps.
SweepPointOutcome time_sweep_point(Device& device, SweepCaptureCache& captures, const SweepPointSetup& setup,
                                   const SweepLog& log);

}  // namespace vsgl
