#pragma once
// The timing protocol of DESIGN.md §9. Each (generator, view) case is recorded ONCE into its own
// command buffer — query reset, then the generator's phases with a timestamp (full barrier +
// timestamp + full barrier, TimestampPool::write) at every phase boundary — and replayed.
// Inputs are uploaded before timing (the caller builds the views and generators first).
//
// Schedule and stop rule:
//  1. warm-up: every case is replayed `warmup` times (>= 2; the first pays shader compilation and
//     first-touch paging), round-robin, and the samples are discarded;
//  2. rounds: each round replays every case once, round-robin, the starting case rotating by one
//     each round, so drift (clocks, thermals, other load) hits all cases alike and no case is
//     always first;
//  3. after at least `min_repetitions` rounds, stop as soon as every case's total has a relative
//     noise IQR/median <= `noise_target`, or when the timed rounds have run `time_cap_s`
//     seconds of wall time, or after `max_repetitions` rounds — whichever comes first. The
//     reason is reported. The cap never cuts the minimum: `min_repetitions` rounds always run.
//  Pairing guarantee: every round appends exactly one sample to every case (a failure ends the
//  run), so sample i of any two cases — of any phase or total — comes from round i. Paired
//  statistics (the modified − Tok15 difference per round, DESIGN.md §9) rely on this.
// Defaults: warm-up 2, min 10, noise 0.02, cap 60 s on GPUs; 20 s on CPU devices (lavapipe), whose
// timings inform only correctness, not performance; max 1000 rounds (bounds the raw samples kept).
// Optional cold mode: before every timed replay a separate submission overwrites a large buffer
// (default 256 MiB) so that caches hold none of the inputs; off by default (the paper measured
// warm frames).
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "harness/generators/vsgl_generator.hpp"

namespace vsgl {

class Device;
struct DeviceInfo;

// Throws DeviceError when the device cannot be timed (timestampValidBits = 0 or
// timestampPeriod = 0 on its compute queue, DESIGN.md §9): no numbers at all rather than wrong ones.
void require_timestamps(const DeviceInfo& info);

struct TimingOptions {
  uint32_t warmup = 2;            // >= 2
  uint32_t min_repetitions = 10;  // >= 2 (statistics need two samples; DESIGN.md §9 asks for >= 10)
  uint32_t max_repetitions = 1000;
  double noise_target = 0.02;     // IQR / median of every case's total
  double time_cap_s = 60.0;       // wall time of the timed rounds
  bool cold = false;
  uint64_t cold_bytes = 256ull << 20;

  // The defaults for a device: the time cap is 20 s on a CPU device, else 60 s.
  static TimingOptions defaults_for(const DeviceInfo& info);
  // Throws UsageError for warm-up < 2, min_repetitions < 2, max < min, a noise target or cap
  // that is not a positive number.
  void check() const;
};

// One (generator, view) case: the generator to replay and what the report needs to name it.
struct TimingCase {
  std::string generator;  // name()
  std::string view;       // "camera_view" | "light_view"
  VsglGenerator* source = nullptr;  // not owned; outlives the runner
};

struct CaseTiming {
  std::string generator;
  std::string view;
  std::vector<std::string> phases;
  std::vector<std::vector<double>> phase_ms;  // [phase][round]: index i is round i in every case
  std::vector<double> total_ms;               // first to last timestamp, [round]
  uint32_t dispatch_count = 0;                // vkCmdDispatch calls recorded (CommandStream)
  std::vector<uint32_t> iteration_dispatches;  // of them, per iteration of a repeated block (k-means)
};

struct TimingResult {
  std::vector<CaseTiming> cases;  // in the order they were added
  uint32_t repetitions = 0;
  double timed_seconds = 0;       // wall time of the timed rounds
  std::string stop_reason;        // "noise_target" | "time_cap" | "max_repetitions"
  double worst_noise = 0;         // largest IQR/median of a case total at the stop
};

struct TimingProgress {
  uint32_t warmup_done = 0, warmup_total = 0;
  uint32_t rounds = 0, min_rounds = 0;
  double elapsed_s = 0, cap_s = 0;
  double worst_noise = -1;  // < 0 until it can be computed
  double noise_target = 0;
};

class TimingRunner {
 public:
  // Throws DeviceError (require_timestamps) for a device without timestamps.
  TimingRunner(Device& device, TimingOptions options);
  ~TimingRunner();
  TimingRunner(const TimingRunner&) = delete;
  TimingRunner& operator=(const TimingRunner&) = delete;

  // Records the case's command buffer now (once).
  void add(const TimingCase& c);
  // Dispatches the case's recording contains (known right after add()).
  uint32_t dispatch_count(std::size_t case_index) const;
  // Of them, those of each iteration of a repeated block (CommandStream::begin_iteration).
  const std::vector<uint32_t>& iteration_dispatches(std::size_t case_index) const;

  // Warm-up, then rounds until the stop rule says so. `progress` (may be empty) is called after
  // every replay round. Throws DeviceError for a zero or negative interval (TimestampPool).
  TimingResult run(const std::function<void(const TimingProgress&)>& progress = {});

  // Replays case `case_index` once and returns its phase intervals in ms (for vsgl-gbench).
  std::vector<double> replay_once(std::size_t case_index);

 private:
  struct Recorded;
  Device& device_;
  TimingOptions options_;
  std::vector<std::unique_ptr<Recorded>> cases_;
  struct ColdFlush;
  std::unique_ptr<ColdFlush> cold_;
};

}  // namespace vsgl
