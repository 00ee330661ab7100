// check_reference_capture (harness/quality/reference_capture.hpp): a reference capture lends its RSM
// only when it shows the capture's frame (scene, model, camera, light, the very G-buffer) with an
// RSM at least as large that has a BRSM PDF; anything else is refused, naming what differs.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "harness/capture/capture.hpp"
#include "harness/core/error.hpp"
#include "harness/quality/reference_capture.hpp"

namespace vsgl {
namespace {

Capture reference_capture_of_side(uint32_t rsm_side) {
  Capture c;
  c.meta.scene = "atrium";
  c.meta.source = SceneSource{"gltf", "atrium/atrium.gltf", "fnv1a64:0123456789abcdef"};
  c.gbuffer.resize(ViewKind::kCamera, 8, 4);
  c.rsm.resize(ViewKind::kLight, rsm_side, rsm_side);
  for (int ch = 0; ch < kChannelCount; ++ch) c.meta.gbuffer_hashes[ch] = "fnv1a64:" + std::to_string(ch);
  return c;
}

// The message of check_reference_capture's refusal, or "" when it accepts.
std::string refusal(const Capture& capture, const Capture& reference) {
  try {
    check_reference_capture(capture, reference, "ref");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ReferenceCapture, TheSameFrameWithALargerOrEqualRsmIsTaken) {
  const Capture capture = reference_capture_of_side(4);
  EXPECT_EQ(refusal(capture, reference_capture_of_side(16)), "");
  EXPECT_EQ(refusal(capture, reference_capture_of_side(4)), "");
}

TEST(ReferenceCapture, AnotherFrameIsRefusedNamingTheDifference) {
  const Capture capture = reference_capture_of_side(4);
  const std::vector<std::pair<std::function<void(Capture&)>, std::string>> cases = {
      {[](Capture& r) { r.meta.scene = "conference"; }, "shows scene 'conference'"},
      {[](Capture& r) { r.meta.source->content_hash = "fnv1a64:ffffffffffffffff"; }, "another model file"},
      {[](Capture& r) { r.meta.source.reset(); }, "another model file"},
      {[](Capture& r) { r.meta.camera.fov_y_deg = 50.0f; }, "another camera"},
      {[](Capture& r) { r.meta.camera_view[3][0] = 1.0f; }, "another camera"},
      {[](Capture& r) { r.meta.light.intensity.g = 3.0f; }, "another light"},
      {[](Capture& r) { r.meta.light_projection[0][0] = 2.0f; }, "another light"},
      {[](Capture& r) { r.gbuffer.resize(ViewKind::kCamera, 16, 8); }, "16x8 G-buffer, the capture 8x4"},
      {[](Capture& r) { r.meta.gbuffer_hashes[kNY] = "fnv1a64:other"; }, "in channel 'N.Y'"},
      {[](Capture& r) { r.rsm.resize(ViewKind::kLight, 2, 8); }, "2x8 RSM, smaller than the capture's 4x4"},
      {[](Capture& r) { r.rsm.has_pdf = false; }, "no BRSM PDF"},
  };
  for (const auto& [change, says] : cases) {
    Capture reference = reference_capture_of_side(16);
    change(reference);
    const std::string message = refusal(capture, reference);
    EXPECT_NE(message.find(says), std::string::npos) << "expected '" << says << "' in: " << message;
    EXPECT_NE(message.find("the reference capture ref"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace vsgl
