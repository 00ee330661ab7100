#pragma once
// The identity of a capture's scene (formats/scene_identity.hpp) as its sidecar records it.
#include "harness/capture/capture.hpp"
#include "harness/formats/scene_identity.hpp"

namespace vsgl {

// A preset with a paper table is the paper's scene; a procedural scene that a paper table uses
// is its stand-in; a file given directly (or through a preset of no paper table) is the user's.
SceneIdentity capture_scene_identity(const CaptureMeta& meta);

}  // namespace vsgl
