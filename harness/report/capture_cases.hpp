#pragma once
// Every case of one capture (each generator on each view), ready to time: both views uploaded and
// every generator built and recorded at its view's N before any timing (DESIGN.md §9). `tables`
// and `sweep` time the cases interleaved (TimingRunner::run); vsgl-gbench replays them one at a
// time (TimingRunner::replay_once). One place builds them, so the two front ends time the same work.
#include <memory>
#include <string>
#include <vector>

#include "harness/generators/device_view.hpp"
#include "harness/generators/vsgl_generator.hpp"
#include "harness/report/tables_run.hpp"
#include "harness/timing/timing_runner.hpp"

namespace vsgl {

class Device;
struct Capture;

// A case (generator on a view) whose buffers the device cannot hold (a DeviceLimitError while it
// was built), left out of the timing.
struct CaseBeyondDevice {
  std::string generator, view, reason;
};

class CaptureCases {
 public:
  // Builds and records every generator of `options` on both views of `capture`, in the order
  // generators × (camera, light), with `options.wrap_generator` applied. Throws what upload_view,
  // make_generator and TimingRunner throw; with `beyond`, a case the device cannot hold is listed
  // there and left out (a DeviceLimitError still ends the call when no case is left).
  CaptureCases(Device& device, const TablesOptions& options, const Capture& capture,
               std::vector<CaseBeyondDevice>* beyond = nullptr);
  CaptureCases(const CaptureCases&) = delete;
  CaptureCases& operator=(const CaptureCases&) = delete;

  // The case list, in the runner's order: case i is cases()[i].
  const std::vector<TimingCase>& cases() const { return cases_; }
  TimingRunner& runner() { return runner_; }

 private:
  DeviceView camera_, light_;
  std::vector<std::unique_ptr<VsglGenerator>> generators_;
  std::vector<TimingCase> cases_;
  TimingRunner runner_;
};

}  // namespace vsgl
