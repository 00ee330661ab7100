// Wavefront OBJ + MTL import (DESIGN.md §3): small files the tests write (a room of quads with
// materials and a PNG texture, relative indices, cut-outs and normal maps, every error a user
// can make) and the OBJ files of Debian's assimp-testmodels, which nobody here wrote.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>
#include <fstream>
#include <string>

#include "cli_runner.hpp"
#include "gpu_test.hpp"
#include "input_error.hpp"
#include "harness/capture/capture_files.hpp"
#include "harness/core/error.hpp"
#include "harness/quality/png_image.hpp"
#include "harness/scene/capture_provisioning.hpp"
#include "harness/scene/model_scene.hpp"
#include "harness/scene/obj_scene.hpp"

namespace vsgl {
namespace {

namespace fs = std::filesystem;
using test::input_error;
const fs::path kObjModels = "/usr/share/assimp/models/OBJ";

fs::path temp_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("vsgl_obj_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

fs::path write_text(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

void write_checker(const fs::path& path, uint8_t a = 230, uint8_t b = 40) {
  Rgb8Image img{4, 4, {}};
  for (uint32_t y = 0; y < 4; ++y)
    for (uint32_t x = 0; x < 4; ++x) {
      const uint8_t v = (x / 2 + y / 2) % 2 == 0 ? a : b;
      img.rgb.insert(img.rgb.end(), {v, v, v});
    }
  write_png_atomic(path, img);
}

// A closed 4 x 3 x 4 m room of six quads seen from inside: a textured glossy floor ("floor":
// Kd, Ks, Ns, map_Kd) and grey walls ("wall": Kd and Ns only).
const char* kRoomMtl =
    "# room materials\n"
    "newmtl floor\n"
    "Kd 1 1 1\n"
    "Ks 0.5 0.4 0.3\n"
    "Ns 98\n"
    "map_Kd checker.png\n"
    "\n"
    "newmtl wall\n"
    "Kd 0.6 0.6 0.6\n"
    "Ns 0\n";

std::string room_obj(const std::string& mtllib = "room.mtl") {
  return "# a room\nmtllib " + mtllib +
         "\n"
         "v -2 0 -2\nv 2 0 -2\nv 2 0 2\nv -2 0 2\n"
         "v -2 3 -2\nv 2 3 -2\nv 2 3 2\nv -2 3 2\n"
         "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
         "vn 0 1 0\nvn 0 -1 0\nvn 1 0 0\nvn -1 0 0\nvn 0 0 1\nvn 0 0 -1\n"
         "g floor\nusemtl floor\n"
         "f 1/1/1 4/4/1 3/3/1 2/2/1\n"
         "g walls\nusemtl wall\n"
         "f 5//2 6//2 7//2 8//2\n"
         "f 1//3 5//3 8//3 4//3\n"
         "f 2//4 3//4 7//4 6//4\n"
         "f 1//5 2//5 6//5 5//5\n"
         "f 4//6 8//6 7//6 3//6\n";
}

fs::path write_obj_room(const fs::path& dir) {
  write_text(dir / "room.mtl", kRoomMtl);
  write_checker(dir / "checker.png");
  return write_text(dir / "room.obj", room_obj());
}

TEST(ObjImport, QuadRoomMapsItsMaterialsAndTexture) {
  const fs::path dir = temp_dir("room");
  const GltfImport room = import_obj(write_obj_room(dir));
  EXPECT_EQ(room.triangles, 12u) << "six quads, two triangles each";
  EXPECT_EQ(room.bounds_lo, glm::vec3(-2, 0, -2));
  EXPECT_EQ(room.bounds_hi, glm::vec3(2, 3, 2));
  const Scene& s = room.scene;
  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_EQ(s.materials[0].name, "floor");
  EXPECT_EQ(s.materials[0].model, MaterialModel::kVertexAlbedo);
  ASSERT_EQ(s.textures.size(), 1u);
  EXPECT_EQ(s.materials[0].base_color_texture, 0);
  EXPECT_TRUE(s.textures[0].srgb);
  EXPECT_EQ(s.textures[0].width, 4u);
  EXPECT_EQ(s.textures[0].rgba8[0], 230);
  EXPECT_FALSE(s.materials[0].alpha_mask);
  EXPECT_EQ(s.materials[1].base_color_texture, -1);
  std::size_t floor = 0, wall = 0;
  for (uint32_t i : s.mesh.indices) {
    const SceneVertex& v = s.mesh.vertices[i];
    EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-6f);
    if (v.material == 0) {
      ++floor;
      EXPECT_EQ(v.normal, glm::vec3(0, 1, 0));
      EXPECT_EQ(v.diffuse, glm::vec3(1.0f));
      EXPECT_NEAR(v.specular.r, 0.5f, 1e-6f);
      EXPECT_NEAR(v.specular.b, 0.3f, 1e-6f);
      EXPECT_NEAR(v.roughness, std::sqrt(2.0f / 100.0f), 1e-6f) << "alpha = sqrt(2 / (Ns + 2))";
      // vt 0 0 at (-2, 0, -2) ... vt 0 1 at (-2, 0, 2): v flipped to the scene's top-left origin.
      if (v.position == glm::vec3(-2, 0, 2)) {
        EXPECT_EQ(v.uv, glm::vec2(0.0f, 0.0f));
      }
      if (v.position == glm::vec3(-2, 0, -2)) {
        EXPECT_EQ(v.uv, glm::vec2(0.0f, 1.0f));
      }
    } else {
      ++wall;
      EXPECT_EQ(v.material, 1u);
      EXPECT_NEAR(v.diffuse.g, 0.6f, 1e-6f);
      EXPECT_EQ(v.specular, glm::vec3(0.04f)) << "no Ks statement: F0 0.04";
      EXPECT_NEAR(v.roughness, 1.0f, 1e-6f) << "Ns 0: alpha 1";
    }
  }
  EXPECT_EQ(floor, 6u);
  EXPECT_EQ(wall, 30u);
  // Triangles wind counter-clockwise seen from their normal's side.
  for (std::size_t t = 0; t < s.mesh.indices.size(); t += 3) {
    const SceneVertex& a = s.mesh.vertices[s.mesh.indices[t]];
    const SceneVertex& b = s.mesh.vertices[s.mesh.indices[t + 1]];
    const SceneVertex& c = s.mesh.vertices[s.mesh.indices[t + 2]];
    EXPECT_GT(glm::dot(glm::cross(b.position - a.position, c.position - a.position), a.normal), 0.0f);
  }
  for (const std::string& n : room.notes) EXPECT_EQ(n.find("WARNING"), std::string::npos) << n;
  EXPECT_NE(room.camera_source.find("automatic"), std::string::npos);
  EXPECT_EQ(room.content_hash.rfind("fnv1a64:", 0), 0u);
  // The hash covers the texture: another checker is another scene.
  write_checker(dir / "checker.png", 200, 40);
  EXPECT_NE(import_obj(dir / "room.obj").content_hash, room.content_hash);
  EXPECT_EQ(import_model(dir / "room.obj").triangles, 12u) << "import_model: .obj is OBJ";
  fs::remove_all(dir);
}

TEST(ObjImport, RelativeIndicesAndPolygonsGiveTheSameTriangles) {
  const fs::path dir = temp_dir("relative");
  const GltfImport absolute = import_obj(write_text(dir / "a.obj", "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nv 0.5 0 1.5\nf 1 4 5 3 2\n"));
  const GltfImport relative = import_obj(write_text(dir / "r.obj", "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nv 0.5 0 1.5\nf -5 -2 -1 -3 -4\n"));
  EXPECT_EQ(absolute.triangles, 3u) << "a pentagon is three triangles";
  ASSERT_EQ(relative.triangles, absolute.triangles);
  for (std::size_t i = 0; i < absolute.scene.mesh.indices.size(); ++i)
    EXPECT_EQ(relative.scene.mesh.vertices[relative.scene.mesh.indices[i]].position,
              absolute.scene.mesh.vertices[absolute.scene.mesh.indices[i]].position);
  // No normals: every face gets its own (flat), facing +y for this counter-clockwise fan.
  for (const SceneVertex& v : absolute.scene.mesh.vertices) EXPECT_EQ(v.normal, glm::vec3(0, 1, 0));
  bool said = false;
  for (const std::string& n : absolute.notes) said = said || n.find("flat shading") != std::string::npos;
  EXPECT_TRUE(said);
  fs::remove_all(dir);
}

TEST(ObjImport, MissingMaterialLibraryIsAWarningAndGrey) {
  const fs::path dir = temp_dir("nomtl");
  const GltfImport room = import_obj(write_text(dir / "room.obj", room_obj("gone.mtl")));
  EXPECT_EQ(room.triangles, 12u);
  for (const SceneVertex& v : room.scene.mesh.vertices) EXPECT_EQ(v.diffuse, glm::vec3(0.5f));
  bool warned = false;
  for (const std::string& n : room.notes)
    warned = warned || (n.find("WARNING") != std::string::npos && n.find("'gone.mtl'") != std::string::npos);
  EXPECT_TRUE(warned);
  fs::remove_all(dir);
}

TEST(ObjImport, CutOutsAndNormalMaps) {
  const fs::path dir = temp_dir("cutout");
  write_checker(dir / "leaf.png");
  write_checker(dir / "mask.png", 255, 0);
  write_checker(dir / "normal.png", 128, 128);
  write_text(dir / "m.mtl",
             "newmtl leaf\nKd 0.2 0.8 0.2\nmap_Kd leaf.png\nmap_d mask.png\nmap_bump normal.png\n"
             "newmtl glass\nKd 1 1 1\nd 0.3\n"
             "newmtl rough\nKd 1 1 1\nKs 3 3 3\nnorm normal.png\n");
  const GltfImport g = import_obj(write_text(dir / "m.obj",
                                             "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                                             "usemtl leaf\nf 1/1 2/2 3/3 4/4\nusemtl glass\nf 1/1 2/2 3/3\nusemtl rough\nf 1/1 3/3 4/4\n"));
  const Scene& s = g.scene;
  ASSERT_EQ(s.materials.size(), 3u);
  const Material& leaf = s.materials[0];
  EXPECT_TRUE(leaf.alpha_mask);
  EXPECT_FLOAT_EQ(leaf.alpha_cutoff, 0.5f);
  ASSERT_GE(leaf.base_color_texture, 0);
  const TextureImage& t = s.textures[static_cast<std::size_t>(leaf.base_color_texture)];
  EXPECT_EQ(t.rgba8[0], 230) << "RGB from map_Kd";
  EXPECT_EQ(t.rgba8[3], 255) << "alpha from map_d's first channel";
  EXPECT_EQ(t.rgba8[2 * 4 + 3], 0);
  EXPECT_GE(leaf.normal_texture, 0);
  EXPECT_FALSE(s.textures[static_cast<std::size_t>(leaf.normal_texture)].srgb);
  EXPECT_TRUE(s.materials[1].alpha_mask) << "d < 1: a cut-out";
  EXPECT_FLOAT_EQ(s.materials[1].base_color_factor.a, 0.3f);
  EXPECT_GE(s.materials[2].normal_texture, 0) << "norm";
  for (const SceneVertex& v : s.mesh.vertices) {
    if (v.material == 2) {
      EXPECT_NEAR(glm::dot(v.specular, glm::vec3(0.2126f, 0.7152f, 0.0722f)), 1.0f, 1e-5f) << "Ks 3: luminance 1";
    }
    if (s.materials[v.material].normal_texture < 0) continue;
    EXPECT_NEAR(glm::length(glm::vec3(v.tangent)), 1.0f, 1e-4f) << "tangents computed";
    EXPECT_NEAR(std::abs(glm::dot(glm::vec3(v.tangent), glm::vec3(1, 0, 0))), 1.0f, 1e-4f) << "along +u";
  }
  bool said = false;
  for (const std::string& n : g.notes) said = said || n.find("tangents computed") != std::string::npos;
  EXPECT_TRUE(said);
  fs::remove_all(dir);
}

TEST(ObjImport, BadFilesNameTheFileAndLine) {
  const fs::path dir = temp_dir("bad");
  const fs::path bad_index = write_text(dir / "bad\x01index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 9\n");
  std::string e = input_error([&] { import_obj(bad_index); });
  EXPECT_NE(e.find("OBJ file"), std::string::npos) << e;
  EXPECT_NE(e.find("bad\\x01index.obj"), std::string::npos) << "escaped: " << e;
  EXPECT_NE(e.find("line 5"), std::string::npos) << e;
  EXPECT_NE(e.find("out of range"), std::string::npos) << e;

  e = input_error([&] { import_obj(write_text(dir / "rel.obj", "v 0 0 0\nf -1 -2 -3\nv 1 0 0\n")); });
  EXPECT_NE(e.find("line 2"), std::string::npos) << "a relative index before its vertex: " << e;
  e = input_error([&] { import_obj(write_text(dir / "zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n")); });
  EXPECT_NE(e.find("line 4"), std::string::npos) << e;
  e = input_error([&] { import_obj(write_text(dir / "vn.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//2 3//1\n")); });
  EXPECT_NE(e.find("line 5"), std::string::npos) << e;
  EXPECT_NE(e.find("normal"), std::string::npos) << e;

  e = input_error([&] { import_obj(write_text(dir / "nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n")); });
  EXPECT_NE(e.find("nan.obj"), std::string::npos) << e;
  EXPECT_NE(e.find("line 2"), std::string::npos) << e;
  EXPECT_NE(e.find("non-finite"), std::string::npos) << e;
  e = input_error([&] { import_obj(write_text(dir / "inf.obj", "v 0 0 0\r\nv 1 1e999 0\r\nv 0 1 0\r\nf 1 2 3\r\n")); });
  EXPECT_NE(e.find("line 2"), std::string::npos) << "CRLF lines count once: " << e;

  e = input_error([&] { import_obj(write_text(dir / "points.obj", "v 0 0 0\nv 1 0 0\np 1 2\nl 1 2\n")); });
  EXPECT_NE(e.find("has no faces"), std::string::npos) << e;
  e = input_error([&] { import_obj(write_text(dir / "empty.obj", "")); });
  EXPECT_NE(e.find("has no faces"), std::string::npos) << e;

  write_text(dir / "t.mtl", "newmtl a\nKd 1 1 1\n\nnewmtl b\nKd 1 0 0\nmap_Kd nothere.png\n");
  e = input_error([&] { import_obj(write_text(dir / "t.obj", "mtllib t.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl b\nf 1 2 3\n")); });
  EXPECT_NE(e.find("t.obj"), std::string::npos) << e;
  EXPECT_NE(e.find("'nothere.png'"), std::string::npos) << e;
  EXPECT_NE(e.find("'t.mtl' line 6"), std::string::npos) << e;
  EXPECT_NE(e.find("missing"), std::string::npos) << e;
  write_text(dir / "garbage.png", "not a png");
  write_text(dir / "g.mtl", "newmtl a\nmap_Kd garbage.png\n");
  e = input_error([&] { import_obj(write_text(dir / "g.obj", "mtllib g.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n")); });
  EXPECT_NE(e.find("could not be decoded"), std::string::npos) << e;

  // An mtllib naming a directory (found by fuzz_obj: its read threw through tinyobjloader) is a
  // missing library; a directory given as the file is an error.
  fs::create_directories(dir / "lib.mtl");
  const GltfImport dir_lib = import_obj(write_text(dir / "d.obj", "mtllib lib.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
  EXPECT_NE(dir_lib.notes.at(0).find("WARNING"), std::string::npos);
  write_text(dir / "empty.mtl", "");
  const GltfImport empty_lib = import_obj(write_text(dir / "e.obj", "mtllib empty.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
  for (const std::string& n : empty_lib.notes) EXPECT_EQ(n.find("WARNING"), std::string::npos) << "an empty library is no missing one: " << n;
  e = input_error([&] { import_obj(dir / "lib.mtl"); });
  EXPECT_NE(e.find("directory"), std::string::npos) << e;
  e = input_error([&] { import_obj(dir / "absent.obj"); });
  EXPECT_NE(e.find("absent.obj"), std::string::npos) << e;
  GltfCameraChoice cam;
  cam.camera = "main";
  e = input_error([&] { import_obj(bad_index, cam); });
  EXPECT_NE(e.find("OBJ files have none"), std::string::npos) << e;
  fs::remove_all(dir);
}

TEST(ObjImport, ModelImportChoosesByExtension) {
  const fs::path dir = temp_dir("ext");
  const std::string e = input_error([&] { import_model(write_text(dir / "scene.fbx", "x")); });
  EXPECT_NE(e.find("scene.fbx"), std::string::npos) << e;
  EXPECT_NE(e.find(".gltf"), std::string::npos) << e;
  EXPECT_NE(e.find(".glb"), std::string::npos) << e;
  EXPECT_NE(e.find(".obj"), std::string::npos) << e;
  const std::string g = input_error([&] { import_model(write_text(dir / "scene.GLTF", "{}")); });
  EXPECT_NE(g.find("glTF file"), std::string::npos) << "upper-case .GLTF is glTF: " << g;
  write_obj_room(dir);
  fs::copy_file(dir / "room.obj", dir / "ROOM.OBJ");
  EXPECT_EQ(import_model(dir / "ROOM.OBJ").triangles, 12u);
  fs::remove_all(dir);
}

TEST(ObjImport, SampleFiles) {
  if (!fs::exists(kObjModels / "box.obj"))
    GTEST_SKIP() << "Debian's assimp-testmodels is not installed (" << kObjModels << "): sample OBJ files not imported";
  const GltfImport box = import_obj(kObjModels / "box.obj");
  EXPECT_EQ(box.triangles, 12u);
  const GltfImport cube = import_obj(kObjModels / "cube_usemtl.obj");
  EXPECT_GE(cube.scene.materials.size(), 3u);
  EXPECT_GT(cube.triangles, 0u);
  std::set<float> ns;
  for (const SceneVertex& v : cube.scene.mesh.vertices) ns.insert(v.roughness);
  EXPECT_GE(ns.size(), 2u) << "several Ns exponents: several roughnesses";
  const GltfImport concave = import_obj(kObjModels / "concave_polygon.obj");
  EXPECT_GT(concave.triangles, 0u);
  const GltfImport wuson = import_obj(kObjModels / "WusonOBJ.obj");
  EXPECT_GT(wuson.triangles, 1000u);
  EXPECT_GT(wuson.bounds_hi.y, wuson.bounds_lo.y);
  const GltfImport spider = import_obj(kObjModels / "spider.obj");
  EXPECT_GT(spider.scene.textures.size(), 0u) << "spider.mtl's JPEG textures";
  const std::string e = input_error([&] { import_obj(kObjModels / "point_cloud.obj"); });
  EXPECT_NE(e.find("has no faces"), std::string::npos) << e;
}

// The hand-written room recorded through the library at a tiny size: the capture on disk loads
// with every check of load_capture (finite values, unit normals, hashes) and both PDFs are nonzero.
class ObjRecordTest : public test::GpuTest {};

TEST_F(ObjRecordTest, RoomRecordsAValidCaptureWithABrsmPdf) {
  const fs::path dir = temp_dir("record");
  GltfCameraChoice cam;
  cam.eye = glm::vec3(0.0f, 2.4f, 1.8f);
  cam.look_at = glm::vec3(0.0f, 0.0f, -0.4f);
  GltfLightChoice light;  // inside the closed room (the automatic spot would sit above its ceiling)
  light.position = glm::vec3(0.3f, 2.9f, -0.2f);
  light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
  light.cone_half_angle_deg = 40.0f;
  light.intensity = glm::vec3(20.0f);
  const GltfImport room = import_obj(write_obj_room(dir), cam, light);
  record_capture(device(), room.scene, RecordSizes{48, 32, 32}, 0, 1, dir / "capture");
  const Capture cap = load_capture(dir / "capture");
  ASSERT_TRUE(cap.rsm.has_pdf);
  double gbuffer_pdf = 0.0, rsm_pdf = 0.0;
  std::size_t valid = 0;
  for (uint32_t y = 0; y < cap.gbuffer.height; ++y)
    for (uint32_t x = 0; x < cap.gbuffer.width; ++x) {
      valid += cap.gbuffer.at(kValid, x, y) == 1.0f;
      gbuffer_pdf += static_cast<double>(cap.gbuffer.at(kPdf, x, y));
    }
  for (uint32_t y = 0; y < cap.rsm.height; ++y)
    for (uint32_t x = 0; x < cap.rsm.width; ++x) rsm_pdf += static_cast<double>(cap.rsm.at(kPdf, x, y));
  EXPECT_EQ(valid, std::size_t{48} * 32) << "the room is closed: every camera texel sees a surface";
  EXPECT_GT(gbuffer_pdf, 0.0);
  EXPECT_GT(rsm_pdf, 0.0) << "the floor lights the walls: the BRSM PDF is not zero";
  fs::remove_all(dir);
}

// The same room through the command line, as a user records one: `record --model room.obj` with a
// camera and a spot inside it, then `verify` on the capture; each broken variant exits 3 naming
// its file, and writes nothing.
TEST(ObjRecordCli, HandWrittenRoomRecordsAndVerifiesAndBrokenVariantsWriteNothing) {
  const fs::path dir = temp_dir("cli");
  const fs::path room = write_obj_room(dir);
  const std::string view =
      " --eye 0,2.4,1.8 --look-at 0,0,-0.4 --light-pos 0.3,2.9,-0.2 --light-dir 0,-1,0 --cone 40 "
      "--intensity 20 --gbuffer 48x32 --rsm 32";
  const auto rec = test::run_cli("record --model " + room.string() + view + " --out " + (dir / "cap").string());
  ASSERT_EQ(rec.exit_code, 0) << rec.output;
  const auto ver = test::run_cli("verify --capture " + (dir / "cap").string());
  EXPECT_EQ(ver.exit_code, 0) << ver.output;
  const Capture cap = load_capture(dir / "cap");
  ASSERT_TRUE(cap.meta.source);
  EXPECT_EQ(cap.meta.source->format, "obj");
  EXPECT_EQ(cap.meta.source->triangles, 12u);

  // A missing .mtl: a warning, grey faces, a capture all the same.
  const fs::path lonely = write_text(dir / "lonely.obj", room_obj("gone.mtl"));
  const auto grey = test::run_cli("record --model " + lonely.string() + view + " --out " + (dir / "grey").string());
  EXPECT_EQ(grey.exit_code, 0) << grey.output;
  EXPECT_NE(grey.output.find("gone.mtl"), std::string::npos) << grey.output;
  EXPECT_NE(grey.output.find("WARNING"), std::string::npos) << grey.output;

  write_text(dir / "notex.mtl", "newmtl floor\nmap_Kd nothere.png\n");
  std::string notex = room_obj("notex.mtl");
  const struct {
    std::string file, text, says;
  } broken[] = {
      {"index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", "out of range"},
      {"nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", "non-finite"},
      {"texture.obj", notex, "nothere.png"},
      {"faceless.obj", "v 0 0 0\nv 1 0 0\nl 1 2\n", "has no faces"},
  };
  for (const auto& b : broken) {
    SCOPED_TRACE(b.file);
    const fs::path file = write_text(dir / b.file, b.text);
    const fs::path out = dir / ("out_" + b.file);
    const auto r = test::run_cli("record --model " + file.string() + view + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 3) << r.output;
    EXPECT_NE(r.output.find(b.file), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(b.says), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out)) << "a refused model writes nothing";
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vsgl
