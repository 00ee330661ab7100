#include "harness/scene/asset_search.hpp"

#include <string_view>

#include "harness/core/path_text.hpp"
#include "harness/core/error.hpp"
#include "harness/core/platform_path.hpp"
#include "harness/core/printable_text.hpp"
#include "harness/scene/scene_preset.hpp"

namespace vsgl {

AssetSearch make_asset_search(const std::vector<std::filesystem::path>& cli_dirs, const char* env_assets) {
  AssetSearch out;
  for (const auto& d : cli_dirs) out.dirs.push_back({d, "--assets"});
  std::string_view env = env_assets == nullptr ? std::string_view() : std::string_view(env_assets);
  while (!env.empty()) {
    const std::size_t separator = env.find(kPathListSeparator);
    const std::string_view part = env.substr(0, separator);
    if (!part.empty()) out.dirs.push_back({path_from_utf8(part), "VSGL_ASSETS"});
    env = separator == std::string_view::npos ? std::string_view() : env.substr(separator + 1);
  }
  out.dirs.push_back({"assets", "assets/ in the current directory"});
  return out;
}

FoundModel find_preset_model(const ScenePreset& preset, const AssetSearch& search) {
  std::string looked;
  for (const AssetDirectory& d : search.dirs)
    for (const std::string& candidate : preset.model) {
      const std::filesystem::path file = d.dir / candidate;
      std::error_code ec;
      if (std::filesystem::is_regular_file(file, ec)) return FoundModel{file, candidate};
      looked += "\n  " + printable_text(path_text(file), std::string_view::npos) + "  (" + d.origin + ")";
    }
  throw InputError("scene " + quoted_text(preset.name) + ": its model was not found; looked for" + looked +
                   "\nget it: " + preset.where_to_get +
                   "\nand put it in one of those places, or pass --assets DIR (or set VSGL_ASSETS) to where it is");
}

}  // namespace vsgl
