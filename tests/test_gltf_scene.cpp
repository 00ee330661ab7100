// glTF 2.0 import (DESIGN.md §3): Khronos sample files nobody here wrote (Debian's assimp-testmodels),
// each broken one with its expected outcome, and a closed room written by the test itself whose
// G-buffer and RSM are checked exactly: positions on the surfaces, unit normals facing the
// camera, the floor's checker texture in the diffuse channel, flux inside the spot cone only.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "input_error.hpp"
#include "cli_runner.hpp"
#include "gpu_test.hpp"
#include "harness/capture/capture_files.hpp"
#include "harness/capture/view_matrices.hpp"
#include "harness/core/error.hpp"
#include "harness/quality/png_image.hpp"
#include "harness/scene/capture_recorder.hpp"
#include "harness/scene/gltf_scene.hpp"
#include "harness/scene/scene_geometry.hpp"
#include "harness/scene/scene_textures.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

namespace fs = std::filesystem;
const fs::path kGltfModels = "/usr/share/assimp/models/glTF2";

using test::input_error;

void write_bytes(const fs::path& path, const std::vector<unsigned char>& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

// ---- The room the test writes -------------------------------------------------------------------

constexpr uint8_t kRed[3] = {230, 40, 40};
constexpr uint8_t kBlue[3] = {40, 40, 230};
constexpr double kOuterCone = 0.5;  // radians

// A glTF column-major node matrix that looks from `eye` along `forward` (-Z local), +Y local up.
std::vector<double> look_matrix(glm::dvec3 eye, glm::dvec3 forward, glm::dvec3 up_hint) {
  const glm::dvec3 f = glm::normalize(forward), r = glm::normalize(glm::cross(f, up_hint)), u = glm::cross(r, f);
  return {r.x, r.y, r.z, 0, u.x, u.y, u.z, 0, -f.x, -f.y, -f.z, 0, eye.x, eye.y, eye.z, 1};
}

struct RoomOptions {
  bool indices_out_of_range = false;
  std::string mesh_name = "room";
  bool missing_texture = false;
  bool spot_light = true;
  // A greyscale height map (bump.png) on the floor material, as converted OBJ files carry it:
  // kInExtras names it only in the material's extras (the MTL's map_bump) with a texture that no
  // material slot uses; kAsNormalTexture also makes it the floor's normalTexture.
  enum class HeightMap { kNone, kInExtras, kAsNormalTexture } height_map = HeightMap::kNone;
};

// A closed 4 x 3 x 4 m room seen from inside: the floor (y = 0) carries a 16x16 checker texture of
// 8-texel squares with texture coordinates (x + 2) / 2, (z + 2) / 2, so its squares are 1 m; walls
// and ceiling are grey. A perspective camera and a KHR_lights_punctual spot under the ceiling.
fs::path write_gltf_room(const fs::path& dir, const RoomOptions& opt = {}) {
  struct Face {
    glm::vec3 centre, eu, ev;  // cross(eu, ev) points into the room
  };
  const Face faces[6] = {
      {{0, 0, 0}, {0, 0, 4}, {4, 0, 0}},     // floor, normal +y
      {{0, 3, 0}, {4, 0, 0}, {0, 0, 4}},     // ceiling, -y
      {{-2, 1.5f, 0}, {0, 3, 0}, {0, 0, 4}},  // -x wall, +x
      {{2, 1.5f, 0}, {0, 0, 4}, {0, 3, 0}},   // +x wall, -x
      {{0, 1.5f, -2}, {4, 0, 0}, {0, 3, 0}},  // -z wall, +z
      {{0, 1.5f, 2}, {0, 3, 0}, {4, 0, 0}},   // +z wall, -z
  };
  std::vector<float> pos, nrm, uv;
  std::vector<uint16_t> idx;
  for (const Face& f : faces) {
    const glm::vec3 n = glm::normalize(glm::cross(f.eu, f.ev));
    const auto base = static_cast<uint16_t>(pos.size() / 3);
    const glm::vec2 st[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (const glm::vec2& s : st) {
      const glm::vec3 p = f.centre + (s.x - 0.5f) * f.eu + (s.y - 0.5f) * f.ev;
      pos.insert(pos.end(), {p.x, p.y, p.z});
      nrm.insert(nrm.end(), {n.x, n.y, n.z});
      uv.insert(uv.end(), {(p.x + 2.0f) / 2.0f, (p.z + 2.0f) / 2.0f});
    }
    idx.insert(idx.end(), {base, static_cast<uint16_t>(base + 1), static_cast<uint16_t>(base + 2), base,
                           static_cast<uint16_t>(base + 2), static_cast<uint16_t>(base + 3)});
  }
  if (opt.indices_out_of_range) idx[7] = 99;
  std::vector<unsigned char> bin;
  const auto append = [&](const void* data, std::size_t bytes) {
    const auto offset = bin.size();
    bin.resize(offset + bytes);
    std::memcpy(bin.data() + offset, data, bytes);
    while (bin.size() % 4) bin.push_back(0);
    return offset;
  };
  const std::size_t pos_at = append(pos.data(), pos.size() * 4), nrm_at = append(nrm.data(), nrm.size() * 4),
                    uv_at = append(uv.data(), uv.size() * 4), idx_at = append(idx.data(), idx.size() * 2);
  write_bytes(dir / "room.bin", bin);
  Rgb8Image checker{16, 16, {}};
  for (uint32_t y = 0; y < 16; ++y)
    for (uint32_t x = 0; x < 16; ++x) {
      const uint8_t* c = ((x / 8 + y / 8) % 2 == 0) ? kRed : kBlue;
      checker.rgb.insert(checker.rgb.end(), c, c + 3);
    }
  if (!opt.missing_texture) write_png_atomic(dir / "checker.png", checker);

  using json = nlohmann::ordered_json;
  const auto n_vertices = pos.size() / 3;
  json doc = {
      {"asset", {{"version", "2.0"}, {"generator", "vsgl tests"}}},
      {"extensionsUsed", json::array({"KHR_lights_punctual"})},
      {"scene", 0},
      {"scenes", json::array({{{"nodes", json::array({0, 1, 2})}}})},
      {"buffers", json::array({{{"uri", "room.bin"}, {"byteLength", bin.size()}}})},
      {"bufferViews", json::array({{{"buffer", 0}, {"byteOffset", pos_at}, {"byteLength", pos.size() * 4}},
                                   {{"buffer", 0}, {"byteOffset", nrm_at}, {"byteLength", nrm.size() * 4}},
                                   {{"buffer", 0}, {"byteOffset", uv_at}, {"byteLength", uv.size() * 4}},
                                   {{"buffer", 0}, {"byteOffset", idx_at}, {"byteLength", idx.size() * 2}}})},
      {"accessors", json::array({{{"bufferView", 0}, {"componentType", 5126}, {"count", n_vertices}, {"type", "VEC3"},
                                  {"min", {-2, 0, -2}}, {"max", {2, 3, 2}}},
                                 {{"bufferView", 1}, {"componentType", 5126}, {"count", n_vertices}, {"type", "VEC3"}},
                                 {{"bufferView", 2}, {"componentType", 5126}, {"count", n_vertices}, {"type", "VEC2"}},
                                 {{"bufferView", 3}, {"byteOffset", 0}, {"componentType", 5123}, {"count", 6},
                                  {"type", "SCALAR"}},
                                 {{"bufferView", 3}, {"byteOffset", 12}, {"componentType", 5123}, {"count", 30},
                                  {"type", "SCALAR"}}})},
      {"images", json::array({{{"uri", "checker.png"}}})},
      {"samplers", json::array({{{"wrapS", 10497}, {"wrapT", 10497}}})},
      {"textures", json::array({{{"source", 0}, {"sampler", 0}}})},
      {"materials", json::array({{{"name", "checker floor"},
                                  {"pbrMetallicRoughness",
                                   {{"baseColorTexture", {{"index", 0}}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.8}}}},
                                 {{"name", "grey"},
                                  {"pbrMetallicRoughness",
                                   {{"baseColorFactor", {0.6, 0.6, 0.6, 1.0}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.5}}}}})},
      {"meshes", json::array({{{"name", opt.mesh_name},
                               {"primitives", json::array({{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}}},
                                                            {"indices", 3}, {"material", 0}},
                                                           {{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}}},
                                                            {"indices", 4}, {"material", 1}}})}}})},
      {"cameras", json::array({{{"name", "view"}, {"type", "perspective"},
                                {"perspective", {{"yfov", 1.0}, {"znear", 0.05}, {"zfar", 20.0}}}}})},
      {"nodes", json::array({{{"name", "room"}, {"mesh", 0}},
                             {{"name", "camera"}, {"camera", 0},
                              {"matrix", look_matrix({0.0, 2.4, 1.8}, {0.0, -2.4, -2.2}, {0, 1, 0})}},
                             {{"name", "spot"},
                              {"matrix", look_matrix({0.3, 2.9, -0.2}, {0.0, -1.0, 0.0}, {0, 0, -1})}}})},
  };
  doc["extensions"]["KHR_lights_punctual"]["lights"] = json::array(
      {{{"name", "spot"}, {"type", opt.spot_light ? "spot" : "point"}, {"intensity", 20.0}, {"color", {1.0, 1.0, 1.0}},
        {"spot", {{"innerConeAngle", 0.3}, {"outerConeAngle", kOuterCone}}}}});
  if (!opt.spot_light) doc["extensions"]["KHR_lights_punctual"]["lights"][0].erase("spot");
  doc["nodes"][2]["extensions"]["KHR_lights_punctual"]["light"] = 0;
  if (opt.height_map != RoomOptions::HeightMap::kNone) {
    Rgb8Image bump{8, 8, {}};
    for (uint32_t i = 0; i < 64; ++i) {
      const auto h = static_cast<uint8_t>(i % 8 < 4 ? 40 : 220);
      bump.rgb.insert(bump.rgb.end(), {h, h, h});
    }
    write_png_atomic(dir / "bump.png", bump);
    doc["images"].push_back({{"uri", "bump.png"}});
    doc["textures"].push_back({{"source", 1}, {"sampler", 0}});
    doc["materials"][0]["extras"]["mtl"] = {{"map_bump", "bump.png"}, {"bump", "bump.png"}};
    if (opt.height_map == RoomOptions::HeightMap::kAsNormalTexture)
      doc["materials"][0]["normalTexture"] = {{"index", 1}};
  }
  const fs::path file = dir / "room.gltf";
  std::ofstream(file) << doc.dump(1);
  return file;
}

glm::vec3 linear_rgb(const uint8_t (&c)[3]) {
  return {srgb_to_linear(c[0] / 255.0f), srgb_to_linear(c[1] / 255.0f), srgb_to_linear(c[2] / 255.0f)};
}

// ---- Import (no device) --------------------------------------------------------------------------

TEST(GltfImport, TexturedBoxIsTheSameInEveryContainer) {
  const GltfImport glb = import_gltf(kGltfModels / "BoxTextured-glTF-Binary/BoxTextured.glb");
  const GltfImport embedded = import_gltf(kGltfModels / "BoxTextured-glTF-Embedded/BoxTextured.gltf");
  const GltfImport external = import_gltf(kGltfModels / "BoxTextured-glTF/BoxTextured.gltf");
  for (const GltfImport* g : {&glb, &embedded, &external}) {
    EXPECT_EQ(g->triangles, 12u);
    EXPECT_EQ(g->scene.name, "BoxTextured");
    ASSERT_EQ(g->scene.textures.size(), 1u) << "the base colour map (CesiumLogoFlat.png)";
    EXPECT_TRUE(g->scene.textures[0].srgb);
    EXPECT_GT(g->scene.textures[0].width, 64u);
    ASSERT_FALSE(g->scene.materials.empty());
    EXPECT_EQ(g->scene.materials[0].base_color_texture, 0);
    EXPECT_EQ(g->scene.materials[0].metallic_factor, 0.0f);
    EXPECT_NE(g->camera_source.find("automatic framing"), std::string::npos) << "the box has no camera";
    EXPECT_NE(g->light_source.find("automatic spot"), std::string::npos);
    EXPECT_EQ(g->content_hash.rfind("fnv1a64:", 0), 0u);
  }
  ASSERT_EQ(glb.scene.mesh.vertices.size(), embedded.scene.mesh.vertices.size());
  for (std::size_t i = 0; i < glb.scene.mesh.vertices.size(); ++i) {
    EXPECT_EQ(glb.scene.mesh.vertices[i].position, embedded.scene.mesh.vertices[i].position);
    EXPECT_EQ(glb.scene.mesh.vertices[i].uv, external.scene.mesh.vertices[i].uv);
  }
  EXPECT_EQ(glb.scene.textures[0].rgba8, embedded.scene.textures[0].rgba8);
  EXPECT_NE(glb.content_hash, embedded.content_hash) << "different files, different hashes";
}

TEST(GltfImport, EngineWithManyNodesKeepsItsTransformsAndCamera) {
  const GltfImport engine = import_gltf(kGltfModels / "2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
  EXPECT_EQ(engine.triangles, 121496u);  // every TRIANGLES primitive of the default scene's 82 nodes
  EXPECT_EQ(engine.scene.materials.size(), 34u);
  EXPECT_NE(engine.camera_source.find("the file's camera 0"), std::string::npos) << engine.camera_source;
  // The camera sits at the file's node translation, looking towards the model.
  EXPECT_NEAR(engine.scene.camera.position.x, 1005.987f, 1e-2f);
  const glm::vec3 centre = 0.5f * (engine.bounds_lo + engine.bounds_hi);
  const glm::vec3 forward = glm::normalize(engine.scene.camera.target - engine.scene.camera.position);
  EXPECT_GT(glm::dot(forward, glm::normalize(centre - engine.scene.camera.position)), 0.9f);
  for (const SceneVertex& v : engine.scene.mesh.vertices) {
    ASSERT_TRUE(std::isfinite(v.position.x) && std::isfinite(v.position.y) && std::isfinite(v.position.z));
    ASSERT_NEAR(glm::length(v.normal), 1.0f, 1e-4f);
  }
  // The camera's far plane is cut to the model (the file's 1e6 would waste the depth precision).
  EXPECT_LT(engine.scene.camera.far_plane, 1e4f);
}

TEST(GltfImport, BrokenSampleFilesGiveTheirExpectedOutcome) {
  // Every index of one triangle points past the 24 vertices.
  const std::string range = input_error([] { import_gltf(kGltfModels / "IndexOutOfRange/IndexOutOfRange.gltf"); });
  EXPECT_NE(range.find("IndexOutOfRange.gltf"), std::string::npos) << range;
  EXPECT_NE(range.find("out of range"), std::string::npos) << range;
  EXPECT_NE(
      input_error([] { import_gltf(kGltfModels / "IndexOutOfRange/AllIndicesOutOfRange.gltf"); }).find("out of range"),
      std::string::npos);
  // The .bin the file names is not there.
  const std::string missing = input_error([] { import_gltf(kGltfModels / "MissingBin/BoxTextured.gltf"); });
  EXPECT_NE(missing.find("MissingBin/BoxTextured.gltf"), std::string::npos) << missing;
  EXPECT_NE(missing.find("BoxTextured0.bin"), std::string::npos) << missing;
  // Positions of +-infinity.
  const std::string inf =
      input_error([] { import_gltf(kGltfModels / "BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb"); });
  EXPECT_NE(inf.find("not finite"), std::string::npos) << inf;
  EXPECT_NE(inf.find("POSITION"), std::string::npos) << inf;
  // 35 vertices or 35 indices of TRIANGLES: not a whole number of triangles.
  const std::string arrays = input_error([] { import_gltf(kGltfModels / "IncorrectVertexArrays/Cube.gltf"); });
  EXPECT_NE(arrays.find("35"), std::string::npos) << arrays;
  EXPECT_NE(arrays.find("whole number of triangles"), std::string::npos) << arrays;
  // glTF 1.0, as JSON and as a version-1 binary container.
  for (const char* f : {"BoxTextured-glTF/BoxTextured.gltf", "BoxTextured-glTF-Binary/BoxTextured.glb"}) {
    const std::string v1 = input_error([&] { import_gltf(kGltfModels.parent_path() / "glTF" / f); });
    EXPECT_NE(v1.find("glTF 1.0"), std::string::npos) << v1;
    EXPECT_NE(v1.find("only glTF 2.0"), std::string::npos) << v1;
  }
}

// Found by fuzz_gltf: an embedded image whose bufferView runs past its buffer. tinygltf 2.7 does
// not check the range and its decoder read past the heap block (AddressSanitizer); now it is a
// clear error. The file is the fuzzer's crash input, kept in the corpus.
TEST(GltfImport, ImageViewPastItsBufferIsAnErrorNotAnOverread) {
  const fs::path source = fs::path(VSGL_SOURCE_DIR) / "tests/fuzz/corpus/fuzz_gltf/regression-image-view-past-buffer.glb";
  const std::string message = input_error([&] { import_gltf(source); });
  EXPECT_NE(message.find("runs past the end of buffer"), std::string::npos) << message;
  // Messages spell a path with '/' on every host (core/path_text.hpp).
  EXPECT_NE(message.find(source.generic_string()), std::string::npos) << message;
  // However deep the file lies, the message names it whole (a checkout's path once cut it short).
  const test::TempDir deep_temp("gltf_deep");
  const fs::path deep = deep_temp / std::string(120, 'd') / std::string(120, 'e') / "view-past-buffer.glb";
  fs::create_directories(deep.parent_path());
  fs::copy_file(source, deep);
  const std::string deep_message = input_error([&] { import_gltf(deep); });
  EXPECT_NE(deep_message.find(deep.generic_string() + ":"), std::string::npos) << deep_message;
}

// Found by fuzz_gltf: an attribute naming an accessor that does not exist was read out of bounds.
TEST(GltfImport, AttributeWithAMissingAccessorIsAnError) {
  const std::filesystem::path file = std::filesystem::path(VSGL_SOURCE_DIR) /
                                     "tests/fuzz/corpus/fuzz_gltf/regression-attribute-accessor-out-of-range.glb";
  const std::string message = input_error([&] { import_gltf(file); });
  EXPECT_NE(message.find("does not exist"), std::string::npos) << message;
}

TEST(GltfImport, BadNormalsAreRepairedAndSaidSo) {
  // BoxBadNormals: zero normals and normals of length 0.1; the box itself is fine.
  const GltfImport box = import_gltf(kGltfModels / "BoxBadNormals-glTF-Binary/BoxBadNormals.glb");
  EXPECT_EQ(box.triangles, 12u);
  bool replaced = false, normalized = false;
  for (const std::string& n : box.notes) {
    replaced = replaced || n.find("replaced by the surface's normal") != std::string::npos;
    normalized = normalized || n.find("normalized") != std::string::npos;
  }
  EXPECT_TRUE(replaced);
  EXPECT_TRUE(normalized);
  for (const SceneVertex& v : box.scene.mesh.vertices) EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-5f);
  // A replaced normal is the face's: it is perpendicular to the triangle's edges.
  const SceneMesh& m = box.scene.mesh;
  for (std::size_t t = 0; t < m.indices.size(); t += 3) {
    const glm::vec3 fn = triangle_normal(m, static_cast<uint32_t>(t / 3));
    for (int k = 0; k < 3; ++k) EXPECT_GT(glm::dot(fn, m.vertices[m.indices[t + static_cast<std::size_t>(k)]].normal), 0.5f);
  }
}

// Only normalTexture is a normal map: a height map that a converted OBJ names in the material's
// extras (the Sibenik cathedral's map_bump, docs/scenes.md) leaves the file's normals as they are.
TEST(GltfImport, OnlyNormalTextureIsANormalMap) {
  const test::TempDir dir_temp("gltf_height_map");
  const fs::path& dir = dir_temp.path();
  const GltfImport plain = import_gltf(write_gltf_room(dir));
  RoomOptions in_extras;
  in_extras.height_map = RoomOptions::HeightMap::kInExtras;
  const GltfImport extras = import_gltf(write_gltf_room(dir, in_extras));
  ASSERT_EQ(extras.scene.materials.size(), 2u);
  EXPECT_EQ(extras.scene.materials[0].normal_texture, -1);
  EXPECT_EQ(extras.scene.textures.size(), 1u) << "the checker only: nothing reads the height map";
  ASSERT_EQ(extras.scene.mesh.vertices.size(), plain.scene.mesh.vertices.size());
  for (std::size_t i = 0; i < plain.scene.mesh.vertices.size(); ++i) {
    EXPECT_EQ(extras.scene.mesh.vertices[i].normal, plain.scene.mesh.vertices[i].normal);
    EXPECT_EQ(extras.scene.mesh.vertices[i].tangent, plain.scene.mesh.vertices[i].tangent);
  }
  // The same map given as normalTexture is read as one (linear, with tangents for the floor).
  RoomOptions as_normal;
  as_normal.height_map = RoomOptions::HeightMap::kAsNormalTexture;
  const GltfImport normal = import_gltf(write_gltf_room(dir, as_normal));
  ASSERT_GE(normal.scene.materials[0].normal_texture, 0);
  EXPECT_FALSE(normal.scene.textures[static_cast<std::size_t>(normal.scene.materials[0].normal_texture)].srgb);
}

TEST(GltfImport, FilesTheTestBreaksNameTheProblem) {
  const test::TempDir dir_temp("gltf_broken");
  const fs::path& dir = dir_temp.path();
  // A mesh name with bytes that are not printable ASCII, and an index out of range: the name is
  // escaped in the message.
  RoomOptions bad;
  bad.indices_out_of_range = true;
  bad.mesh_name = "r\xC3\xBCm\n";
  const std::string range = input_error([&] { import_gltf(write_gltf_room(dir, bad)); });
  EXPECT_NE(range.find("'r\\xc3\\xbcm\\x0a'"), std::string::npos) << range;
  EXPECT_NE(range.find("99"), std::string::npos) << range;
  // The texture's PNG is not there.
  RoomOptions no_png;
  no_png.missing_texture = true;
  fs::remove(dir / "checker.png");
  const std::string tex = input_error([&] { import_gltf(write_gltf_room(dir, no_png)); });
  EXPECT_NE(tex.find("checker"), std::string::npos) << tex;
  // A file that is not glTF, and one that is missing.
  std::ofstream(dir / "junk.gltf") << "not json";
  EXPECT_NE(input_error([&] { import_gltf(dir / "junk.gltf"); }).find("not valid JSON"), std::string::npos);
  EXPECT_NE(input_error([&] { import_gltf(dir / "absent.glb"); }).find("cannot be opened"), std::string::npos);
  // Only lines: no triangles.
  nlohmann::ordered_json lines =
      nlohmann::ordered_json::parse(R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],
    "nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":{"POSITION":0},"mode":1}]}],
    "accessors":[{"componentType":5126,"count":2,"type":"VEC3"}]})");
  std::ofstream(dir / "lines.gltf") << lines.dump();
  EXPECT_NE(input_error([&] { import_gltf(dir / "lines.gltf"); }).find("no triangles"), std::string::npos);
  // --camera naming a camera the file does not have lists the ones it has.
  GltfCameraChoice cam;
  cam.camera = "nope";
  const std::string no_cam = input_error([&] { import_gltf(write_gltf_room(dir), cam); });
  EXPECT_NE(no_cam.find("0 'view'"), std::string::npos) << no_cam;
}

TEST(GltfImport, CameraAndLightChoices) {
  const test::TempDir dir_temp("gltf_choices");
  const fs::path& dir = dir_temp.path();
  const fs::path room = write_gltf_room(dir);
  const GltfImport by_file = import_gltf(room);
  EXPECT_NE(by_file.camera_source.find("camera 0 'view'"), std::string::npos) << by_file.camera_source;
  EXPECT_NE(by_file.light_source.find("spot light 0 'spot'"), std::string::npos) << by_file.light_source;
  EXPECT_NEAR(by_file.scene.light.cone_half_angle_deg, kOuterCone * 180.0 / 3.14159265358979, 1e-3);
  EXPECT_NEAR(by_file.scene.light.direction.y, -1.0f, 1e-6f);
  EXPECT_NEAR(by_file.scene.light.intensity.r, 20.0f, 1e-6f);
  EXPECT_NEAR(by_file.scene.camera.fov_y_deg, 57.2958f, 1e-3f);

  GltfCameraChoice given;
  given.eye = glm::vec3(1.0f, 1.0f, 1.0f);
  given.look_at = glm::vec3(0.0f, 0.0f, 0.0f);
  given.fov_y_deg = 40.0f;
  GltfLightChoice light;
  light.cone_half_angle_deg = 20.0f;
  const GltfImport by_hand = import_gltf(room, given, light);
  EXPECT_EQ(by_hand.scene.camera.position, glm::vec3(1.0f));
  EXPECT_EQ(by_hand.scene.camera.fov_y_deg, 40.0f);
  EXPECT_EQ(by_hand.scene.light.cone_half_angle_deg, 20.0f);
  EXPECT_NE(by_hand.camera_source.find("command line"), std::string::npos);
  EXPECT_NE(by_hand.light_source.find("--cone"), std::string::npos);

  GltfCameraChoice both;
  both.camera = "0";
  both.eye = glm::vec3(1.0f);
  EXPECT_THROW(import_gltf(room, both), UsageError);

  // A point light is no spot: the automatic one is used, and the message says why.
  RoomOptions point;
  point.spot_light = false;
  const GltfImport auto_light = import_gltf(write_gltf_room(dir, point));
  EXPECT_NE(auto_light.light_source.find("point/directional"), std::string::npos) << auto_light.light_source;

  // Frame 0 of a sequence is the static scene; later frames move camera and light.
  EXPECT_EQ(gltf_frame(by_file, 0, 4).light.position, by_file.scene.light.position);
  EXPECT_NE(gltf_frame(by_file, 1, 4).light.position, by_file.scene.light.position);
}

TEST(GltfImport, NamesAreEscapedAndSceneNamesAreFileNames) {
  EXPECT_EQ(escape_name("abc"), "abc");
  EXPECT_EQ(escape_name("a\tb\\"), "a\\x09b\\x5c");
  EXPECT_EQ(escape_name(std::string(100, 'x')).size(), 83u);
  EXPECT_EQ(scene_name_from_file("dir/Crytek Sponza.glb"), "Crytek_Sponza");
  EXPECT_EQ(scene_name_from_file("/x/..glb"), "gltf");
}

// ---- Recording (device) ---------------------------------------------------------------------------

class GltfRecordTest : public test::GpuTest {
 protected:
  Capture record(const Scene& scene, RecordSizes sizes) { return CaptureRecorder(device()).record(scene, sizes, 0, 1); }
};

TEST_F(GltfRecordTest, RoomGBufferAndRsmAreExact) {
  const test::TempDir dir_temp("gltf_room");
  const fs::path& dir = dir_temp.path();
  const GltfImport room = import_gltf(write_gltf_room(dir));
  ASSERT_EQ(room.triangles, 12u);
  const Scene& scene = room.scene;
  const Capture cap = record(scene, RecordSizes{96, 64, 64});

  const ViewImage& g = cap.gbuffer;
  std::size_t red = 0, blue = 0, valid = 0;
  const glm::vec3 lin_red = linear_rgb(kRed), lin_blue = linear_rgb(kBlue);
  for (uint32_t y = 0; y < g.height; ++y)
    for (uint32_t x = 0; x < g.width; ++x) {
      ASSERT_EQ(g.at(kValid, x, y), 1.0f) << "the room is closed: every camera texel sees a surface";
      ++valid;
      const glm::vec3 p(g.at(kPX, x, y), g.at(kPY, x, y), g.at(kPZ, x, y));
      const glm::vec3 n(g.at(kNX, x, y), g.at(kNY, x, y), g.at(kNZ, x, y));
      EXPECT_LT(distance_to_mesh(scene.mesh, p), 1e-3f) << "texel " << x << "," << y;
      EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
      EXPECT_GT(glm::dot(n, scene.camera.position - p), 0.0f);
      const glm::vec3 d(g.at(kDR, x, y), g.at(kDG, x, y), g.at(kDB, x, y));
      if (std::abs(p.y) > 1e-4f) {
        EXPECT_NEAR(d.r, 0.6f, 1e-5f) << "grey walls";
        EXPECT_NEAR(g.at(kRoughness, x, y), 0.25f, 1e-6f);
        continue;
      }
      EXPECT_NEAR(g.at(kRoughness, x, y), 0.64f, 1e-6f);
      // Floor: 1 m squares from x, z = -2; skip 0.15 m around their edges (filtering).
      const auto edge = [](float s) { return std::abs(s - std::round(s)); };
      if (edge(p.x) < 0.15f || edge(p.z) < 0.15f) continue;
      const int sx = static_cast<int>(std::floor(p.x + 2.0f)), sz = static_cast<int>(std::floor(p.z + 2.0f));
      const bool is_red = (sx + sz) % 2 == 0;
      const glm::vec3 want = is_red ? lin_red : lin_blue;
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(d[c], want[c], 3e-3f) << "floor texel " << x << "," << y;
      (is_red ? red : blue)++;
    }
  EXPECT_GT(red, 50u) << "the checker is visible in the diffuse channel";
  EXPECT_GT(blue, 50u);

  // RSM: flux only inside the cone, I * texel area * cos^3 * albedo there.
  const ViewImage& r = cap.rsm;
  const SpotLightDesc& light = scene.light;
  const float area = rsm_texel_area(light, 64);
  const float cos_cone = std::cos(glm::radians(light.cone_half_angle_deg));
  std::size_t inside = 0, outside = 0;
  for (uint32_t y = 0; y < r.height; ++y)
    for (uint32_t x = 0; x < r.width; ++x) {
      ASSERT_EQ(r.at(kValid, x, y), 1.0f);
      const glm::vec3 p(r.at(kPX, x, y), r.at(kPY, x, y), r.at(kPZ, x, y));
      EXPECT_LT(distance_to_mesh(scene.mesh, p), 1e-3f);
      const float cos_theta = glm::dot(glm::normalize(p - light.position), light.direction);
      const glm::vec3 flux(r.at(kDR, x, y), r.at(kDG, x, y), r.at(kDB, x, y));
      if (cos_theta < cos_cone - 1e-4f) {
        EXPECT_EQ(flux, glm::vec3(0.0f)) << "flux outside the cone at " << x << "," << y;
        ++outside;
        continue;
      }
      if (cos_theta < cos_cone + 1e-4f) continue;
      ++inside;
      EXPECT_GT(flux.r + flux.g + flux.b, 0.0f);
      if (std::abs(p.y) < 1e-4f) {
        const float edge_x = std::abs(p.x - std::round(p.x)), edge_z = std::abs(p.z - std::round(p.z));
        if (edge_x < 0.15f || edge_z < 0.15f) continue;
        const int sx = static_cast<int>(std::floor(p.x + 2.0f)), sz = static_cast<int>(std::floor(p.z + 2.0f));
        const glm::vec3 want = (sx + sz) % 2 == 0 ? lin_red : lin_blue;
        const float incident = 20.0f * area * cos_theta * cos_theta * cos_theta;
        EXPECT_NEAR(flux.r / incident, want.r, 3e-3f);
      }
    }
  EXPECT_GT(inside, 500u);
  EXPECT_GT(outside, 500u);
}

TEST_F(GltfRecordTest, SampleModelsRecordWithTheirTextures) {
  // The textured box, framed automatically: the logo's texels differ, so the diffuse channel is
  // not constant.
  const GltfImport box = import_gltf(kGltfModels / "BoxTextured-glTF-Binary/BoxTextured.glb");
  const Capture b = record(box.scene, RecordSizes{64, 48, 32});
  std::size_t valid = 0;
  float lo = 1.0f, hi = 0.0f;
  for (std::size_t i = 0; i < b.gbuffer.texels(); ++i) {
    if (b.gbuffer.planes[kValid][i] == 0.0f) continue;
    ++valid;
    lo = std::min(lo, b.gbuffer.planes[kDG][i]);
    hi = std::max(hi, b.gbuffer.planes[kDG][i]);
  }
  EXPECT_GT(valid, b.gbuffer.texels() / 10);
  EXPECT_GT(hi - lo, 0.2f) << "the texture is visible";
  std::size_t lit = 0;
  for (std::size_t i = 0; i < b.rsm.texels(); ++i) lit += b.rsm.planes[kDR][i] > 0.0f ? 1 : 0;
  EXPECT_GT(lit, 10u) << "the automatic spot reaches the box";

  // The engine from its own camera.
  const GltfImport engine = import_gltf(kGltfModels / "2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
  const Capture e = record(engine.scene, RecordSizes{64, 48, 32});
  std::size_t seen = 0;
  for (float v : e.gbuffer.planes[kValid]) seen += v != 0.0f ? 1 : 0;
  EXPECT_GT(seen, e.gbuffer.texels() / 10) << "the file's camera sees the engine";
}

TEST(GltfRecordCli, RecordsTheRoomWithItsSourceInTheSidecar) {
  const test::TempDir dir_temp("gltf_cli");
  const fs::path& dir = dir_temp.path();
  const fs::path room = write_gltf_room(dir);
  const auto r = test::run_cli("record --gltf " + room.string() + " --out " + (dir / "cap").string() +
                               " --gbuffer 48x32 --rsm 32");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("camera: the file's camera 0 'view'"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("light: the file's spot light 0 'spot'"), std::string::npos) << r.output;
  const Capture cap = load_capture(dir / "cap");
  ASSERT_TRUE(cap.meta.source.has_value());
  EXPECT_EQ(cap.meta.source->triangles, 12u);
  EXPECT_EQ(cap.meta.source->format, "gltf");
  EXPECT_EQ(cap.meta.source->content_hash, import_gltf(room).content_hash);
  EXPECT_EQ(cap.meta.source->file, room.filename().string()) << "the file by its name, not where it lay";
  EXPECT_EQ(cap.meta.scene, "room");

  // verify and tables take it like any capture.
  const auto verify = test::run_cli("verify --capture " + (dir / "cap").string() + " --camera-vsgls 64 --light-vsgls 32");
  EXPECT_EQ(verify.exit_code, 0) << verify.output;
  EXPECT_NE(verify.output.find("INFO  light_view"), std::string::npos) << "total power is reported, not judged";
  EXPECT_NE(verify.output.find("power_vs_cpu"), std::string::npos) << verify.output;
  const auto tables = test::run_cli("tables --capture " + (dir / "cap").string() + " --out " + (dir / "t").string() +
                                    " --quick --generators fis_tok15,fis_modified --camera-vsgls 48 --light-vsgls 24");
  ASSERT_EQ(tables.exit_code, 0) << tables.output;
  std::ifstream table_file(dir / "t" / "room.json");
  ASSERT_TRUE(table_file.good());
  const nlohmann::ordered_json table = nlohmann::ordered_json::parse(table_file);
  EXPECT_TRUE(table["table"].is_null());
  EXPECT_EQ(table["capture"]["source"]["triangles"], 12);
  EXPECT_EQ(table["capture"]["source"]["content_hash"], cap.meta.source->content_hash);
  EXPECT_EQ(table["scene"]["model_file"], room.filename().string());
  const auto shade = test::run_cli("shade --capture " + (dir / "cap").string() + " --out " + (dir / "shade").string() +
                                   " --vsgls 64");
  EXPECT_EQ(shade.exit_code, 0) << shade.output;
  EXPECT_TRUE(fs::exists(dir / "shade" / "shade_room_fis_modified.png")) << shade.output;
  const auto compare = test::run_cli("compare " + (dir / "t" / "room.json").string() + " " + (dir / "t" / "room.json").string());
  EXPECT_EQ(compare.exit_code, 3) << compare.output;  // compare: bad input or incomparable runs
  EXPECT_NE(compare.output.find("is null"), std::string::npos) << compare.output;

  // A light or a camera outside the room, looking away from it: refused, nothing written.
  const auto dark = test::run_cli("record --gltf " + room.string() + " --out " + (dir / "dark").string() +
                                  " --gbuffer 48x32 --rsm 32 --light-pos 0,-5,0 --light-dir 0,-1,0");
  EXPECT_EQ(dark.exit_code, 3) << dark.output;
  EXPECT_NE(dark.output.find("the spot light reaches no surface"), std::string::npos) << dark.output;
  EXPECT_FALSE(fs::exists(dir / "dark" / "capture.json"));
  const auto blind = test::run_cli("record --gltf " + room.string() + " --out " + (dir / "blind").string() +
                                   " --gbuffer 48x32 --rsm 32 --eye 0,-5,0 --look-at 0,-10,0");
  EXPECT_EQ(blind.exit_code, 3) << blind.output;
  EXPECT_NE(blind.output.find("the camera sees no surface"), std::string::npos) << blind.output;
  EXPECT_FALSE(fs::exists(dir / "blind" / "capture.json"));
  // The textured box alone: a convex object lights nothing of itself (all-zero BRSM PDF), which
  // is refused with the way out; with --ground it records.
  const std::string box = (kGltfModels / "BoxTextured-glTF-Binary/BoxTextured.glb").string();
  const auto lone = test::run_cli("record --gltf " + box + " --out " + (dir / "box").string() + " --gbuffer 48x32 --rsm 32");
  EXPECT_EQ(lone.exit_code, 3) << lone.output;
  EXPECT_NE(lone.output.find("--ground"), std::string::npos) << lone.output;
  EXPECT_FALSE(fs::exists(dir / "box" / "capture.json"));
  const auto grounded =
      test::run_cli("record --gltf " + box + " --ground --out " + (dir / "box").string() + " --gbuffer 48x32 --rsm 32");
  EXPECT_EQ(grounded.exit_code, 0) << grounded.output;
  EXPECT_NE(grounded.output.find("--ground: a grey floor"), std::string::npos) << grounded.output;
  // A broken file: exit 3 with the file named.
  const auto broken = test::run_cli("record --gltf " + (kGltfModels / "MissingBin/BoxTextured.gltf").string() +
                                    " --out " + (dir / "x").string());
  EXPECT_EQ(broken.exit_code, 3) << broken.output;
  EXPECT_NE(broken.output.find("BoxTextured0.bin"), std::string::npos) << broken.output;
}

}  // namespace
}  // namespace vsgl
