#pragma once
// The frame document of DESIGN.md §9.2 (results/schema/frame.schema.json) as one typed model:
// `frame` (quality/frame_run.cpp) fills it and writes it with to_json, renders its markdown with
// frame_markdown, and `dashboard` reads a file back with frame_model_from_json. Every field is
// required: the document has one writer and no older versions.
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/formats/run_header.hpp"
#include "harness/formats/timing_statistics.hpp"

namespace vsgl {

inline constexpr int kFrameSchemaVersion = 1;
inline constexpr const char* kFrameSchemaFile = "results/schema/frame.schema.json";

// The phases of a frame, in the order they run: rsm_replay, pdf, vsgl_generation, ism, shading.
const std::vector<std::string>& frame_phase_names();
// What a phase times, as the documents say it (one line each).
std::string frame_phase_description(const std::string& phase);

struct FramePhaseTiming {
  std::string phase;
  TimingStatistics stats;  // StatisticsLayout::kTable (no paper number: the paper gives none per phase)
};

struct FrameGeneratorTiming {
  std::string name;                      // the generator id (core/generator_ids.hpp)
  std::vector<FramePhaseTiming> phases;  // frame_phase_names(), in order
  TimingStatistics frame;                // per round: the sum of the phases of that round
  uint32_t dispatch_calls = 0;           // vkCmdDispatch calls in one frame's recording
};

struct FrameCaptureSummary {
  std::string scene;
  std::string dir;
  uint32_t gbuffer_width = 0, gbuffer_height = 0;
  uint32_t rsm_width = 0, rsm_height = 0;
  uint64_t visibility_points = 0;
};

struct FrameConfig {
  uint32_t light_vsgls = 0;       // N, the generators' light-view VSGLs (the paper: 1024)
  uint32_t pdf_camera_vsgls = 0;  // the BRSM PDF's camera-view VSGLs
  uint32_t ism_side = 0;          // texels per side of each map (the paper: 64)
  uint32_t ism_points_per_map = 0;
  uint32_t stride = 1;  // the shading's G-buffer stride (1: every pixel)
  uint32_t shaded_width = 0, shaded_height = 0;
  bool paper_sizes = false;  // N 1024, ISM 64^2, RSM 512^2, G-buffer 1920x1088, stride 1
  std::string sizes_note;    // what differs from the paper's sizes ("" when paper_sizes)
};

struct FrameTimingStop {
  uint64_t repetitions = 0;
  double timed_seconds = 0;
  std::string stop_reason;  // "noise_target" | "time_cap" | "max_repetitions"
  double worst_relative_iqr = 0;
};

struct FrameModel {
  int schema_version = kFrameSchemaVersion;
  DeviceRecord device;
  BuildRecord build;
  RunRecord run;
  FrameCaptureSummary capture;
  FrameConfig config;
  FrameTimingStop timing;
  std::vector<FrameGeneratorTiming> generators;  // in the order timed
};

// The document, keys in the order of the schema.
nlohmann::ordered_json to_json(const FrameModel& model);

// Reads a frame document; `what` names it in messages. Throws InputError naming the JSON pointer of
// whatever is missing or mistyped, a time that is not positive, a generator whose phases are not
// the five in order or whose frame samples are not the per-round sums of its phases, and series of
// different lengths (sample i of every series is round i).
FrameModel frame_model_from_json(const nlohmann::ordered_json& doc, const std::string& what);

// The markdown: the run header, what each phase times, then per generator each phase's median, its
// interquartile range and its share of the frame.
std::string frame_markdown(const FrameModel& model);

// A phase's share of its frame: the median over the rounds of phase / frame (so the shares of a
// generator need not sum to exactly 1).
double frame_phase_share(const FrameGeneratorTiming& generator, std::size_t phase);

}  // namespace vsgl
