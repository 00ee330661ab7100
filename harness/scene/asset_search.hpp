#pragma once
// Where a scene preset's model file is looked for (DESIGN.md §3.4), in order: every --assets DIR
// as given, then the directories of VSGL_ASSETS (separated by ':', on Windows ';': kPathListSeparator,
// in UTF-8), then assets/ in the current
// directory. Nothing depends on where the program was built, so a copied binary searches the same
// places. Models are data: they are read from there and never part of the repository.
#include <filesystem>
#include <string>
#include <vector>

namespace vsgl {

struct ScenePreset;

struct AssetDirectory {
  std::filesystem::path dir;
  std::string origin;  // why it is searched, for messages: "--assets", "VSGL_ASSETS", ...
};

struct AssetSearch {
  std::vector<AssetDirectory> dirs;  // in search order
};

// The search path from the command line's directories and the value of VSGL_ASSETS (UTF-8; nullptr
// or empty: none), then assets/ in the current directory.
AssetSearch make_asset_search(const std::vector<std::filesystem::path>& cli_dirs, const char* env_assets);

// A preset's model as found: the file to read, and its name relative to the asset directory it was
// found in (the preset's candidate, e.g. "sponza/Sponza.gltf"), which is what captures and tables
// record (DESIGN.md §3.4): where the asset directory lies is the machine's, not the scene's.
struct FoundModel {
  std::filesystem::path file;
  std::string name;
};

// The first of the preset's model candidates that exists as a regular file, over the directories in
// order. Throws InputError (exit 3, nothing written) when none does: it lists every place looked and
// says where to get the model.
FoundModel find_preset_model(const ScenePreset& preset, const AssetSearch& search);

}  // namespace vsgl
