#pragma once
// A capture: one frame of one scene, recorded by the rasterizer (DESIGN.md §3). Two views share one
// layout of 15 float32 planes; only the names of the reflectance channels differ (albedo for the
// camera's G-buffer, flux for the light's RSM).
#include <array>
#include <cstdint>
#include <span>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "harness/capture/visibility_geometry.hpp"
#include "harness/math/fis_params.hpp"
#include "harness/math/vsgl_math.hpp"
#include "kernels/include/interface/shading.h"

namespace vsgl {

enum class ViewKind { kCamera, kLight };

enum Channel : int {
  kPX, kPY, kPZ, kValid,   // world position, valid flag (1 where geometry was hit, else 0)
  kNX, kNY, kNZ,           // unit normal
  kDR, kDG, kDB,           // diffuse albedo (camera) | diffuse flux (light)
  kSR, kSG, kSB,           // specular albedo (camera) | specular flux (light)
  kRoughness,              // GGX alpha
  kPdf,                    // camera PDF (reflectance luminance) | BRSM PDF
  kChannelCount
};

// EXR channel names, in Channel order, for a view.
std::span<const char* const> channel_names(ViewKind kind);
const char* view_file_name(ViewKind kind);  // "gbuffer.exr" | "rsm.exr"
const char* view_label(ViewKind kind);      // "gbuffer" | "rsm"

struct ViewImage {
  ViewKind kind = ViewKind::kCamera;
  uint32_t width = 0;
  uint32_t height = 0;
  // The RSM's BRSM PDF is computed after recording (DESIGN.md §8); until then the capture has none
  // and the PDF plane is absent from the file (and all zero in memory).
  bool has_pdf = true;
  // Planar, row-major, row 0 = top of the image, texel (x, y) at index y * width + x.
  std::array<std::vector<float>, kChannelCount> planes;

  void resize(ViewKind k, uint32_t w, uint32_t h);
  std::size_t texels() const { return std::size_t{width} * height; }
  float& at(Channel c, uint32_t x, uint32_t y) { return planes[c][std::size_t{y} * width + x]; }
  float at(Channel c, uint32_t x, uint32_t y) const { return planes[c][std::size_t{y} * width + x]; }
};

struct CameraDesc {
  glm::vec3 position{0.0f};
  glm::vec3 target{0.0f, 0.0f, -1.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fov_y_deg = 60.0f;
  float near_plane = 0.05f;
  float far_plane = 100.0f;
};

struct SpotLightDesc {
  glm::vec3 position{0.0f};
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // unit spot axis
  glm::vec3 up{0.0f, 0.0f, -1.0f};         // orientation of the RSM image
  float cone_half_angle_deg = 45.0f;       // flux is zero outside the cone; the RSM's fov is twice this
  glm::vec3 intensity{10.0f};              // W/sr (rgb)
  float near_plane = 0.05f;
  float far_plane = 100.0f;
};

// Where the scene of a capture came from when it is a user's file rather than a procedural scene
// (sidecar key "source"; absent for the procedural scenes).
struct SceneSource {
  std::string format;        // "gltf" (.gltf, .glb) or "obj" (.obj + .mtl)
  // The model file relative to the directory it was found in (escaped; DESIGN.md §3.4): a preset's
  // candidate under its asset directory ("sponza/Sponza.gltf"), a file given directly by its name.
  std::string file;
  std::string content_hash;  // "fnv1a64:<16 hex>" over the file, its buffers and its decoded images
  uint32_t triangles = 0;
  std::string camera;        // which camera was used, in words
  std::string light;         // which light was used, in words
  // A named scene preset (harness/scene/presets/NAME.json) the file was recorded through; empty
  // for a file given directly (record --model / --gltf).
  std::string preset;
  uint32_t paper_table = 0;  // the paper table the preset reproduces (1, 2), 0 for none
};

// The importance this version makes the BRSM PDF by (DESIGN.md §8): Tok15 Eq. 3 with K = 2 lobes,
// the exact cosines and §3.3's bias reduction at alpha = gpu::kBiasReductionAlpha. A capture whose
// PDF was made by another is refused when loaded (its PDF would not be this version's).
inline constexpr std::string_view kBrsmImportanceModel = kShadingModel;

struct CaptureMeta {
  std::string scene;
  std::optional<SceneSource> source;  // a user's file; none for the procedural scenes
  uint32_t frame = 0;
  uint32_t frames = 1;
  CameraDesc camera;
  SpotLightDesc light;
  glm::mat4 camera_view{1.0f}, camera_projection{1.0f};  // Vulkan clip space (y down, z in [0,1])
  glm::mat4 light_view{1.0f}, light_projection{1.0f};
  std::string device;        // where it was recorded
  std::string tool_version;  // vsgl-bench version that wrote it
  double brsm_build_ms = 0;  // time to build the BRSM PDF (0 when none)
  // The FIS pyramid path the BRSM PDF was built on (DESIGN.md §8): the buffer path (bit-identical on
  // every device), or the texture path where the device cannot bind the buffer pyramid. None: no
  // PDF, or a capture written before the key was recorded.
  std::optional<PyramidPath> brsm_pyramid;
  // The importance the BRSM PDF was made by (sidecar `brsm_importance`): its model and Tok15 §3.3's
  // alpha. Empty: no PDF, or a capture written before the key (an older importance).
  std::string brsm_importance;
  double brsm_bias_alpha = 0;
  // Filled by write_capture / checked by load_capture: "fnv1a64:<16 hex>" per channel name.
  std::array<std::string, kChannelCount> gbuffer_hashes;
  std::array<std::string, kChannelCount> rsm_hashes;
  // The scene's triangles and point sampling for visibility (visibility_geometry.hpp, DESIGN.md
  // §8a); none in a capture recorded without them or before they were recorded.
  std::optional<VisibilityGeometryRecord> visibility_geometry;
};

struct Capture {
  CaptureMeta meta;
  ViewImage gbuffer;  // camera view
  ViewImage rsm;      // light view
  // Written by write_capture when present; load_capture leaves it empty (load_visibility_geometry
  // reads it for the commands that shade with visibility).
  std::optional<VisibilityGeometry> visibility_geometry;
  const ViewImage& view(ViewKind k) const { return k == ViewKind::kCamera ? gbuffer : rsm; }
};

// 64-bit FNV-1a of a plane's bytes, as "fnv1a64:%016x". Identifies inputs exactly.
std::string plane_hash(const std::vector<float>& plane);
// The same hash over any bytes (the visibility geometry file, visibility_geometry.hpp).
std::string bytes_hash(std::string_view bytes);

// Channels stored in a file: all of them, less the PDF when the view has none.
inline int stored_channel_count(bool has_pdf) { return has_pdf ? kChannelCount : kPdf; }

}  // namespace vsgl
