// libFuzzer target: the capture loader (harness/capture/capture_files.cpp load_capture: the JSON
// sidecar, both OpenEXR files through harness/capture/exr_io.cpp, the size / channel / value / hash
// checks), and the visibility geometry of a capture that loads (visibility_geometry.cpp). The
// input is gbuffer.exr SEP rsm.exr SEP capture.json SEP visibility_geometry.bin
// (fuzz_input_files.hpp); a missing part is a missing file. Bad input must end in InputError; anything else (another
// exception, a crash, a sanitizer report, a leak) is a bug.
#include <OpenEXR/ImfThreading.h>

#include <cstdint>
#include <string_view>

#include "fuzz_input_files.hpp"
#include "harness/capture/capture.hpp"
#include "harness/capture/capture_files.hpp"
#include "harness/capture/visibility_geometry.hpp"
#include "harness/core/error.hpp"

namespace {

const vsgl::fuzz::ScratchDir& scratch() {
  static const vsgl::fuzz::ScratchDir dir;
  return dir;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  // One OpenEXR worker thread (the loader asks for all cores only when the pool is empty):
  // keeps runs reproducible and the fuzzer's own process lean.
  Imf::setGlobalThreadCount(1);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const auto parts = vsgl::fuzz::split_parts(input, 4);
  const char* names[] = {"gbuffer.exr", "rsm.exr", "capture.json", vsgl::kVisibilityGeometryFile};
  for (std::size_t i = 0; i < 4; ++i) {
    if (i < parts.size()) scratch().write(names[i], parts[i]);
    else scratch().remove(names[i]);
  }
  try {
    const vsgl::Capture capture = vsgl::load_capture(scratch().path());
    // A capture that loads is whole: both views hold every plane at the recorded size.
    for (const vsgl::ViewImage* view : {&capture.gbuffer, &capture.rsm})
      for (const auto& plane : view->planes)
        if (plane.size() != view->texels()) __builtin_trap();
    // Its geometry, where the sidecar names one: whole triangles, unit normals.
    if (capture.meta.visibility_geometry) {
      const vsgl::VisibilityGeometry g = vsgl::load_visibility_geometry(scratch().path(), capture.meta);
      if (g.triangle_vertices.size() != 3 * capture.meta.visibility_geometry->triangles) __builtin_trap();
    }
  } catch (const vsgl::InputError&) {
  }
  return 0;
}
