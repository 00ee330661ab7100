#pragma once
// The named scenes this build knows: the presets in the checkout's harness/scene/presets/ and the
// asset search path (--assets, VSGL_ASSETS, assets/ in the checkout, ../shared/scenes beside it;
// DESIGN.md §3.4).
#include <filesystem>
#include <vector>

#include "harness/scene/named_scene.hpp"

namespace vsgl {

SceneLibrary checkout_scene_library(const std::vector<std::filesystem::path>& assets);

}  // namespace vsgl
