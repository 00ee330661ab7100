#include "harness/scene/model_scene.hpp"

#include <cctype>
#include <string>

#include "harness/core/path_text.hpp"
#include "harness/core/error.hpp"
#include "harness/core/printable_text.hpp"
#include "harness/scene/obj_scene.hpp"

namespace vsgl {

GltfImport import_model(const std::filesystem::path& file, const GltfCameraChoice& camera, const GltfLightChoice& light,
                        bool ground) {
  std::string ext = file.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".gltf" || ext == ".glb") return import_gltf(file, camera, light, ground);
  if (ext == ".obj") return import_obj(file, camera, light, ground);
  throw InputError("scene file " + printable_text(path_text(file), std::string_view::npos) +
                   ": unsupported extension '" + printable_text(ext, 80) +
                   "' (supported: .gltf and .glb for glTF 2.0, .obj for Wavefront OBJ + MTL)");
}

}  // namespace vsgl
