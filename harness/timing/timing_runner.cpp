#include "harness/timing/timing_runner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "harness/vk/buffer.hpp"
#include "harness/vk/command_stream.hpp"
#include "harness/vk/device.hpp"
#include "harness/core/error.hpp"
#include "harness/core/statistics.hpp"
#include "harness/vk/timestamp_pool.hpp"
#include "harness/vk/vk_check.hpp"

namespace vsgl {

void require_timestamps(const DeviceInfo& info) {
  if (info.timestamp_valid_bits == 0)
    throw DeviceError("device '" + info.name + "' has timestampValidBits = 0 on its compute queue: it cannot be "
                      "timed, so no table is produced");
  if (!(info.timestamp_period_ns > 0.0f))
    throw DeviceError("device '" + info.name + "' reports timestampPeriod = 0: its timestamps cannot be converted "
                      "to time, so no table is produced");
}

TimingOptions TimingOptions::defaults_for(const DeviceInfo& info) {
  TimingOptions o;
  if (info.type == VK_PHYSICAL_DEVICE_TYPE_CPU) o.time_cap_s = 20.0;
  return o;
}

void TimingOptions::check() const {
  if (warmup < 2) throw UsageError("at least 2 warm-up runs are needed (the first pays shader compilation)");
  if (min_repetitions < 2) throw UsageError("at least 2 repetitions are needed (a standard deviation needs two)");
  if (max_repetitions < min_repetitions)
    throw UsageError("the maximum repetitions (" + std::to_string(max_repetitions) + ") are fewer than the minimum (" +
                     std::to_string(min_repetitions) + ")");
  if (!(noise_target > 0.0) || !std::isfinite(noise_target)) throw UsageError("the noise target must be a positive number");
  if (!(time_cap_s >= 0.0) || !std::isfinite(time_cap_s)) throw UsageError("the time cap must be a non-negative number");
  if (cold && cold_bytes == 0) throw UsageError("cold mode needs a buffer of at least one byte");
}

struct TimingRunner::Recorded {
  TimingCase what;
  std::vector<std::string> phases;
  std::unique_ptr<TimestampPool> pool;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  uint32_t dispatches = 0;
  std::vector<uint32_t> iteration_dispatches;
  Device* device = nullptr;
  ~Recorded() {
    if (cmd != VK_NULL_HANDLE) device->free_command_buffer(cmd);
  }
};

struct TimingRunner::ColdFlush {
  Buffer scratch;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  Device* device = nullptr;
  ~ColdFlush() {
    if (cmd != VK_NULL_HANDLE) device->free_command_buffer(cmd);
  }
};

TimingRunner::TimingRunner(Device& device, TimingOptions options) : device_(device), options_(options) {
  require_timestamps(device.info());
  options_.check();
  if (options_.cold) {
    cold_ = std::make_unique<ColdFlush>();
    cold_->device = &device;
    cold_->scratch = Buffer(device, options_.cold_bytes, MemoryUsage::kDeviceLocal, "timing.cold_flush");
    cold_->cmd = device.allocate_command_buffer("timing.cold_flush");
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    VK_CHECK(vkBeginCommandBuffer(cold_->cmd, &begin));
    vkCmdFillBuffer(cold_->cmd, cold_->scratch.get(), 0, VK_WHOLE_SIZE, 0x5eedf00du);
    CommandStream(cold_->cmd).full_barrier();
    VK_CHECK(vkEndCommandBuffer(cold_->cmd));
  }
}

TimingRunner::~TimingRunner() = default;

void TimingRunner::add(const TimingCase& c) {
  if (c.source == nullptr) throw std::logic_error("timing case without a generator");
  auto r = std::make_unique<Recorded>();
  r->what = c;
  r->phases = c.source->phases();
  r->device = &device_;
  const std::string label = c.generator + "." + c.view;
  r->pool = std::make_unique<TimestampPool>(device_, static_cast<uint32_t>(r->phases.size() + 1), label + ".timestamps");
  r->cmd = device_.allocate_command_buffer(label + ".timed");
  // No ONE_TIME_SUBMIT: the same recording is replayed for every sample (DESIGN.md §9).
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  VK_CHECK(vkBeginCommandBuffer(r->cmd, &begin));
  r->pool->reset(r->cmd);  // every replay resets its queries before writing them
  CommandStream stream(r->cmd);
  TimestampPool& pool = *r->pool;
  c.source->record(stream, [&pool](VkCommandBuffer cmd) { pool.write(cmd); });
  VK_CHECK(vkEndCommandBuffer(r->cmd));
  if (pool.written() != r->phases.size() + 1)
    throw std::logic_error("generator " + c.generator + " called its phase boundary " + std::to_string(pool.written()) +
                           " times for " + std::to_string(r->phases.size()) + " phases (expected phases + 1)");
  r->dispatches = stream.dispatch_count();
  r->iteration_dispatches = stream.iteration_dispatches();
  cases_.push_back(std::move(r));
}

uint32_t TimingRunner::dispatch_count(std::size_t case_index) const { return cases_.at(case_index)->dispatches; }

const std::vector<uint32_t>& TimingRunner::iteration_dispatches(std::size_t case_index) const {
  return cases_.at(case_index)->iteration_dispatches;
}

std::vector<double> TimingRunner::replay_once(std::size_t case_index) {
  Recorded& r = *cases_.at(case_index);
  if (cold_) device_.submit_and_wait(cold_->cmd);
  device_.submit_and_wait(r.cmd);
  const std::vector<uint64_t> ticks = r.pool->read_ticks();
  std::vector<double> ms(r.phases.size());
  for (std::size_t p = 0; p < r.phases.size(); ++p) {
    try {
      ms[p] = r.pool->interval_ns(ticks[p], ticks[p + 1]) * 1e-6;
    } catch (const DeviceError& e) {
      throw DeviceError(r.what.generator + " " + r.what.view + " phase '" + r.phases[p] + "': " + e.what());
    }
  }
  return ms;
}

TimingResult TimingRunner::run(const std::function<void(const TimingProgress&)>& progress) {
  if (cases_.empty()) throw std::logic_error("nothing to time");
  const std::size_t n = cases_.size();
  TimingResult result;
  for (const auto& r : cases_) {
    CaseTiming t;
    t.generator = r->what.generator;
    t.view = r->what.view;
    t.phases = r->phases;
    t.phase_ms.resize(r->phases.size());
    t.dispatch_count = r->dispatches;
    t.iteration_dispatches = r->iteration_dispatches;
    result.cases.push_back(std::move(t));
  }
  TimingProgress p;
  p.warmup_total = options_.warmup;
  p.min_rounds = options_.min_repetitions;
  p.cap_s = options_.time_cap_s;
  p.noise_target = options_.noise_target;
  for (uint32_t w = 0; w < options_.warmup; ++w) {
    for (std::size_t i = 0; i < n; ++i) replay_once(i);  // discarded
    p.warmup_done = w + 1;
    if (progress) progress(p);
  }

  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  const auto worst_noise = [&] {
    double worst = 0;
    for (const auto& c : result.cases) worst = std::max(worst, relative_iqr(summarize(c.total_ms)));
    return worst;
  };
  for (uint32_t round = 0;; ++round) {
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t i = (round + k) % n;  // rotating start: no case is always first
      const std::vector<double> ms = replay_once(i);
      CaseTiming& t = result.cases[i];
      double total = 0;
      for (std::size_t ph = 0; ph < ms.size(); ++ph) {
        t.phase_ms[ph].push_back(ms[ph]);
        total += ms[ph];  // = last - first timestamp: the intervals tile it exactly
      }
      t.total_ms.push_back(total);
    }
    result.repetitions = round + 1;
    p.rounds = result.repetitions;
    p.elapsed_s = elapsed();
    p.worst_noise = result.repetitions >= 2 ? worst_noise() : -1.0;
    if (progress) progress(p);
    if (result.repetitions < options_.min_repetitions) continue;
    if (p.worst_noise <= options_.noise_target) {
      result.stop_reason = "noise_target";
      break;
    }
    if (p.elapsed_s >= options_.time_cap_s) {
      result.stop_reason = "time_cap";
      break;
    }
    if (result.repetitions >= options_.max_repetitions) {
      result.stop_reason = "max_repetitions";
      break;
    }
  }
  result.timed_seconds = elapsed();
  result.worst_noise = worst_noise();
  return result;
}

}  // namespace vsgl
