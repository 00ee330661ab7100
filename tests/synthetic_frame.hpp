#pragma once
// A frame document's model (harness/formats/frame_model.hpp) made without a device, for the tests
// of the model and of the dashboard.
#include <vector>

#include "harness/formats/frame_model.hpp"
#include "synthetic_header.hpp"

namespace vsgl::test {

// Two generators, five rounds; phase p of round i takes (p + 1) * 0.1 + i * 0.01 ms (+ g).
inline FrameModel synthetic_frame() {
  FrameModel m;
  m.device = synthetic_device();
  m.build = synthetic_build();
  m.run = synthetic_run();
  m.capture = {"tiny", "captures/tiny", 96, 64, 32, 32, 4096};
  m.config = {32, 32, 16, 512, 1, 96, 64, false, "N 32, not 1024; ISM 16^2, not 64^2"};
  const uint32_t rounds = 5;
  m.timing = {rounds, 0.5, "max_repetitions", 0.1};
  for (int g = 0; g < 2; ++g) {
    FrameGeneratorTiming t;
    t.name = g == 0 ? "fis_tok15" : "kmeans";
    std::vector<double> frame(rounds, 0.0);
    for (std::size_t p = 0; p < frame_phase_names().size(); ++p) {
      std::vector<double> s;
      for (uint32_t i = 0; i < rounds; ++i) {
        s.push_back(static_cast<double>(p + 1) * 0.1 + i * 0.01 + g);
        frame[i] += s.back();
      }
      t.phases.push_back({frame_phase_names()[p], timing_statistics(s)});
    }
    t.frame = timing_statistics(frame);
    t.dispatch_calls = 40 + static_cast<uint32_t>(g);
    m.generators.push_back(std::move(t));
  }
  return m;
}

}  // namespace vsgl::test
