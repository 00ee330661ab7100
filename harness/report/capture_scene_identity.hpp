#pragma once
// The identity of a capture's scene (formats/scene_identity.hpp) as its sidecar records it.
#include "harness/capture/capture.hpp"
#include "harness/formats/scene_identity.hpp"

namespace vsgl {

// A preset is the paper's scene, with a paper table (sponza, conference-room) or without one
// (sibenik, Fig. 5 only; DESIGN.md §3.4); a procedural scene that a paper table uses is its
// stand-in; a file given directly is the user's.
SceneIdentity capture_scene_identity(const CaptureMeta& meta);

}  // namespace vsgl
