#include "harness/report/checkout_scenes.hpp"

#include <cstdlib>

namespace vsgl {

SceneLibrary checkout_scene_library(const std::vector<std::filesystem::path>& assets) {
  const std::filesystem::path checkout(VSGL_SOURCE_DIR);
  return SceneLibrary{checkout / "harness" / "scene" / "presets",
                      make_asset_search(assets, std::getenv("VSGL_ASSETS"), checkout)};
}

}  // namespace vsgl
