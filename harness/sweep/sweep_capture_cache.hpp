#pragma once
// The capture each point of `vsgl-bench sweep` times (DESIGN.md §10.1): the one given (--capture),
// loaded with every hash checked, or the scene's (--scene) recorded at the point's sizes into
// "<captures_dir>/<scene>-g<W>x<H>-r<R>", or reused from there when it is still the scene's.
// Consecutive points of one size share the capture held.
#include <filesystem>
#include <optional>
#include <string>

#include "harness/scene/capture_provisioning.hpp"
#include "harness/scene/named_scene.hpp"
#include "harness/sweep/sweep_event.hpp"
#include "harness/sweep/sweep_options.hpp"

namespace vsgl {

class Device;

// The capture directory of a scene at some sizes under the cache root: "<scene>-g<W>x<H>-r<R>".
std::filesystem::path sweep_capture_dir(const std::filesystem::path& root, const std::string& scene,
                                        const RecordSizes& sizes);

class SweepCaptureCache {
 public:
  // Loads the named scene now (InputError for a bad one), so it fails before any measurement.
  SweepCaptureCache(Device& device, const SweepOptions& options);

  // The capture at `sizes` (the given capture's own sizes for --capture); says, for `point`, when
  // it recorded or re-recorded one. Throws what loading or recording throws (DeviceLimitError for
  // sizes the device cannot hold), and holds nothing then.
  const Capture& at(const RecordSizes& sizes, std::size_t point, const SweepLog& log);

  // Where the capture at `sizes` is: the given directory or the cache's.
  std::string dir(const RecordSizes& sizes) const;

 private:
  Device& device_;
  const SweepOptions& options_;
  std::optional<NamedScene> scene_;
  std::optional<RecordSizes> held_sizes_;  // of `held_`; none: nothing held
  ProvidedCapture held_;
};

}  // namespace vsgl
