#pragma once
// The tiny scene recorded small for generator tests, with a stand-in light-view PDF (each RSM
// texel's flux) so that tests of a generator do not also depend on the BRSM PDF's build.
#include "harness/scene/capture_recorder.hpp"
#include "harness/scene/scene.hpp"

namespace vsgl::test {

inline Capture record_tiny_with_flux_pdf(Device& device) {
  CaptureRecorder recorder(device);
  Capture c = recorder.record(make_scene("tiny"), RecordSizes{96, 64, 64}, 0, 1);
  ViewImage& rsm = c.rsm;
  for (std::size_t i = 0; i < rsm.texels(); ++i)
    rsm.planes[kPdf][i] = rsm.planes[kDR][i] + rsm.planes[kDG][i] + rsm.planes[kDB][i];
  rsm.has_pdf = true;
  return c;
}

}  // namespace vsgl::test
