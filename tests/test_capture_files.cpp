// Capture storage (DESIGN.md §3) and its rejection of bad input (DESIGN.md §12). CPU only, no device.
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <random>
#include <set>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "harness/core/atomic_file.hpp"
#include "harness/capture/capture.hpp"
#include "harness/capture/capture_files.hpp"
#include "harness/capture/visibility_geometry.hpp"
#include "harness/core/error.hpp"
#include "harness/capture/exr_io.hpp"
#include "child_process.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

namespace fs = std::filesystem;

using test::read_json;
using test::TempDir;

std::set<std::string> file_names(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.insert(entry.path().filename().string());
  return names;
}

// Positions on the plane y = 0, unit normals in random directions, every 7th texel invalid (zero
// geometry), seeded random reflectance, PDF = mean reflectance on valid texels.
void fill_view(ViewImage& view, ViewKind kind, uint32_t width, uint32_t height, uint32_t seed) {
  view.resize(kind, width, height);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::normal_distribution<float> gauss(0.0f, 1.0f);
  for (uint32_t y = 0; y < height; ++y) {
    for (uint32_t x = 0; x < width; ++x) {
      if ((x + 3 * y) % 7 == 0) continue;  // invalid: background, all zero
      view.at(kPX, x, y) = 0.1f * static_cast<float>(x) - 2.0f;
      view.at(kPY, x, y) = 0.0f;
      view.at(kPZ, x, y) = -0.1f * static_cast<float>(y);
      view.at(kValid, x, y) = 1.0f;
      glm::vec3 n{gauss(rng), gauss(rng), gauss(rng)};
      if (glm::length(n) < 1e-3f) n = {0.0f, 1.0f, 0.0f};
      n = glm::normalize(n);
      view.at(kNX, x, y) = n.x;
      view.at(kNY, x, y) = n.y;
      view.at(kNZ, x, y) = n.z;
      float sum = 0.0f;
      for (int c = kDR; c <= kSB; ++c) {
        view.at(static_cast<Channel>(c), x, y) = unit(rng);
        sum += view.at(static_cast<Channel>(c), x, y);
      }
      view.at(kRoughness, x, y) = 0.05f + 0.95f * unit(rng);
      view.at(kPdf, x, y) = sum / 6.0f;
    }
  }
}

Capture make_capture() {
  Capture capture;
  CaptureMeta& meta = capture.meta;
  meta.scene = "synthetic";
  meta.frame = 2;
  meta.frames = 5;
  meta.camera.position = {0.1f, 1.7f, 3.3f};
  meta.camera.target = {0.0f, 0.2f, -1.0f};
  meta.camera.fov_y_deg = 47.5f;
  meta.camera.near_plane = 0.07f;
  meta.camera.far_plane = 73.0f;
  meta.light.position = {0.3f, 4.0f, -1.1f};
  meta.light.direction = glm::normalize(glm::vec3{0.1f, -1.0f, 0.2f});
  meta.light.cone_half_angle_deg = 33.3f;
  meta.light.intensity = {12.0f, 11.0f, 9.5f};
  meta.camera_view = glm::lookAt(meta.camera.position, meta.camera.target, meta.camera.up);
  meta.camera_projection = glm::perspective(glm::radians(meta.camera.fov_y_deg), 64.0f / 48.0f,
                                            meta.camera.near_plane, meta.camera.far_plane);
  meta.light_view = glm::lookAt(meta.light.position, meta.light.position + meta.light.direction,
                                meta.light.up);
  meta.light_projection = glm::perspective(glm::radians(2.0f * meta.light.cone_half_angle_deg),
                                           1.0f, meta.light.near_plane, meta.light.far_plane);
  meta.device = "test device";
  meta.tool_version = "0.1.0-test";
  meta.brsm_build_ms = 1.25;
  meta.brsm_pyramid = PyramidPath::kTexture;  // not the usual path, so the round trip shows it is read
  meta.brsm_importance = std::string(kBrsmImportanceModel);
  meta.brsm_bias_alpha = gpu::kBiasReductionAlpha;
  fill_view(capture.gbuffer, ViewKind::kCamera, 64, 48, 1234u);
  fill_view(capture.rsm, ViewKind::kLight, 32, 32, 5678u);
  return capture;
}

// Runs `load` expecting InputError whose message contains every needle.
void expect_input_error(const std::function<void()>& load, const std::vector<std::string>& needles) {
  try {
    load();
    ADD_FAILURE() << "no InputError thrown; expected one mentioning " << needles.front();
  } catch (const InputError& e) {
    const std::string message = e.what();
    for (const std::string& needle : needles) {
      EXPECT_NE(message.find(needle), std::string::npos)
          << "message lacks \"" << needle << "\": " << message;
    }
  }
}

void expect_load_fails(const fs::path& dir, const std::vector<std::string>& needles) {
  expect_input_error([&] { load_capture(dir); }, needles);
}

// Rewrites one view's EXR with the given planes (keeping the sidecar), through the EXR helper.
void rewrite_view(const fs::path& dir, const ViewImage& view, bool with_pdf,
                  const std::string& skip = "", ExrSampleType type_of_nx = ExrSampleType::kFloat) {
  std::vector<ExrChannelToWrite> channels;
  const auto names = channel_names(view.kind);
  for (int c = 0; c < (with_pdf ? kChannelCount : kPdf); ++c) {
    if (names[c] == skip) continue;
    channels.push_back({names[c], view.planes[c], c == kNX ? type_of_nx : ExrSampleType::kFloat});
  }
  write_exr(dir / view_file_name(view.kind), view.width, view.height, channels);
}

void write_json(const fs::path& path, const nlohmann::ordered_json& doc) { write_text_atomic(path, doc.dump(2)); }

void expect_planes_equal(const ViewImage& a, const ViewImage& b) {
  ASSERT_EQ(a.kind, b.kind);
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  ASSERT_EQ(a.has_pdf, b.has_pdf);
  for (int c = 0; c < kChannelCount; ++c) {
    ASSERT_EQ(a.planes[c].size(), b.planes[c].size()) << channel_names(a.kind)[c];
    EXPECT_EQ(std::memcmp(a.planes[c].data(), b.planes[c].data(), a.planes[c].size() * 4), 0)
        << "plane " << channel_names(a.kind)[c] << " differs";
  }
}

void expect_meta_equal(const CaptureMeta& a, const CaptureMeta& b) {
  EXPECT_EQ(a.scene, b.scene);
  EXPECT_EQ(a.frame, b.frame);
  EXPECT_EQ(a.frames, b.frames);
  EXPECT_EQ(a.device, b.device);
  EXPECT_EQ(a.tool_version, b.tool_version);
  EXPECT_EQ(a.brsm_build_ms, b.brsm_build_ms);
  EXPECT_EQ(a.brsm_pyramid, b.brsm_pyramid);
  EXPECT_EQ(a.camera.position, b.camera.position);
  EXPECT_EQ(a.camera.target, b.camera.target);
  EXPECT_EQ(a.camera.up, b.camera.up);
  EXPECT_EQ(a.camera.fov_y_deg, b.camera.fov_y_deg);
  EXPECT_EQ(a.camera.near_plane, b.camera.near_plane);
  EXPECT_EQ(a.camera.far_plane, b.camera.far_plane);
  EXPECT_EQ(a.light.position, b.light.position);
  EXPECT_EQ(a.light.direction, b.light.direction);
  EXPECT_EQ(a.light.up, b.light.up);
  EXPECT_EQ(a.light.cone_half_angle_deg, b.light.cone_half_angle_deg);
  EXPECT_EQ(a.light.intensity, b.light.intensity);
  EXPECT_EQ(a.light.near_plane, b.light.near_plane);
  EXPECT_EQ(a.light.far_plane, b.light.far_plane);
  EXPECT_EQ(a.camera_view, b.camera_view);
  EXPECT_EQ(a.camera_projection, b.camera_projection);
  EXPECT_EQ(a.light_view, b.light_view);
  EXPECT_EQ(a.light_projection, b.light_projection);
  EXPECT_EQ(a.gbuffer_hashes, b.gbuffer_hashes);
  EXPECT_EQ(a.rsm_hashes, b.rsm_hashes);
}

TEST(CaptureIo, PlaneHashIsFnv1a64OfTheBytes) {
  EXPECT_EQ(plane_hash({}), "fnv1a64:cbf29ce484222325");  // the FNV-1a offset basis
  // Little-endian bytes "abcd" and "abcdabcd": reference values computed independently.
  const float abcd = std::bit_cast<float>(0x64636261u);
  EXPECT_EQ(plane_hash({abcd}), "fnv1a64:fc179f83ee0724dd");
  EXPECT_EQ(plane_hash({abcd, abcd}), "fnv1a64:2bc7b43705aa8655");
  EXPECT_NE(plane_hash({0.0f}), plane_hash({-0.0f}));
}

TEST(CaptureIo, ChannelNamesFollowTheChannelEnum) {
  ASSERT_EQ(channel_names(ViewKind::kCamera).size(), static_cast<std::size_t>(kChannelCount));
  ASSERT_EQ(channel_names(ViewKind::kLight).size(), static_cast<std::size_t>(kChannelCount));
  EXPECT_STREQ(channel_names(ViewKind::kCamera)[kNX], "N.X");
  EXPECT_STREQ(channel_names(ViewKind::kCamera)[kDG], "albedo_diffuse.G");
  EXPECT_STREQ(channel_names(ViewKind::kLight)[kSB], "flux_specular.B");
  EXPECT_STREQ(channel_names(ViewKind::kLight)[kPdf], "pdf");
  EXPECT_STREQ(view_file_name(ViewKind::kLight), "rsm.exr");
  EXPECT_STREQ(view_label(ViewKind::kCamera), "gbuffer");
  ViewImage view;
  view.resize(ViewKind::kLight, 5, 3);
  EXPECT_EQ(view.kind, ViewKind::kLight);
  for (const auto& plane : view.planes) EXPECT_EQ(plane, std::vector<float>(15, 0.0f));
}

TEST(CaptureIo, RoundTripIsBitExact) {
  TempDir temp;
  const fs::path dir = temp.path() / "nested" / "capture";  // created by write_capture
  const Capture capture = make_capture();
  const CaptureMeta written = write_capture(capture, dir);
  EXPECT_EQ(file_names(dir), (std::set<std::string>{"capture.json", "gbuffer.exr", "rsm.exr"}))
      << "temporary files left behind";
  for (int c = 0; c < kChannelCount; ++c) {
    EXPECT_EQ(written.gbuffer_hashes[c], plane_hash(capture.gbuffer.planes[c]));
    EXPECT_EQ(written.rsm_hashes[c], plane_hash(capture.rsm.planes[c]));
  }
  const Capture loaded = load_capture(dir);
  expect_planes_equal(capture.gbuffer, loaded.gbuffer);
  expect_planes_equal(capture.rsm, loaded.rsm);
  expect_meta_equal(written, loaded.meta);

  const nlohmann::ordered_json sidecar = read_json(dir / "capture.json");
  EXPECT_EQ(sidecar["format"], "vsgl-capture");
  EXPECT_EQ(sidecar["units"]["intensity"], "W/sr");
  EXPECT_EQ(sidecar["rsm"]["pdf"], "brsm");
  EXPECT_EQ(sidecar["brsm_pyramid"], "texture");
  EXPECT_EQ(sidecar["gbuffer"]["channels"]["albedo_specular.B"], written.gbuffer_hashes[kSB]);
  EXPECT_EQ(sidecar["camera"]["view"][12], static_cast<double>(capture.meta.camera_view[3][0]));

  // The EXR holds exactly the named float channels, readable by any EXR reader.
  const ExrImage rsm = read_exr(dir / "rsm.exr");
  EXPECT_EQ(rsm.channels.size(), static_cast<std::size_t>(kChannelCount));
  ASSERT_NE(rsm.find("flux_diffuse.R"), nullptr);
  EXPECT_EQ(rsm.find("flux_diffuse.R")->type, ExrSampleType::kFloat);
  EXPECT_EQ(rsm.find("flux_diffuse.R")->values, capture.rsm.planes[kDR]);
}

// Two triangles and three points: enough to see every field come back.
VisibilityGeometry small_geometry() {
  VisibilityGeometry g;
  g.triangle_vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1.5f}};
  g.points = {{{0.25f, 0.25f, 0}, {0, 0, 1}, 0}, {{0.5f, 0.25f, 1}, {0, 0, -1}, 1}, {{0.1f, 0.7f, 0}, {0, 0, 1}, 0}};
  g.point_seed = 0x1234567890abcdefull;
  return g;
}

// The visibility geometry (DESIGN.md §8a) travels with the capture: its file beside the EXRs, its
// counts, seed and hash in the sidecar, read back bit for bit; without it, the capture is as before.
TEST(CaptureIo, VisibilityGeometryRoundTripsThroughTheSidecar) {
  TempDir temp;
  Capture capture = make_capture();
  capture.visibility_geometry = small_geometry();
  const CaptureMeta written = write_capture(capture, temp.path());
  EXPECT_EQ(file_names(temp.path()),
            (std::set<std::string>{"capture.json", "gbuffer.exr", "rsm.exr", kVisibilityGeometryFile}));
  ASSERT_TRUE(written.visibility_geometry);
  const nlohmann::ordered_json sidecar = read_json(temp.path() / "capture.json");
  EXPECT_EQ(sidecar["visibility_geometry"]["triangles"], 2);
  EXPECT_EQ(sidecar["visibility_geometry"]["points"], 3);
  EXPECT_EQ(sidecar["visibility_geometry"]["point_seed"], 0x1234567890abcdefull);
  std::string bytes;
  {  // closed before the capture is written over (Windows does not remove an open file)
    std::ifstream in(temp.path() / kVisibilityGeometryFile, std::ios::binary);
    bytes.assign((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  }
  EXPECT_EQ(sidecar["visibility_geometry"]["hash"], bytes_hash(bytes));
  EXPECT_EQ(bytes.size(), 40u + 2 * 36 + 3 * 28);

  const Capture loaded = load_capture(temp.path());
  EXPECT_FALSE(loaded.visibility_geometry);  // read only by the commands that shade with visibility
  const VisibilityGeometry back = load_visibility_geometry(temp.path(), loaded.meta);
  const VisibilityGeometry want = small_geometry();
  EXPECT_EQ(back.triangle_vertices, want.triangle_vertices);
  ASSERT_EQ(back.points.size(), want.points.size());
  for (std::size_t i = 0; i < want.points.size(); ++i) {
    EXPECT_EQ(back.points[i].position, want.points[i].position);
    EXPECT_EQ(back.points[i].normal, want.points[i].normal);
    EXPECT_EQ(back.points[i].triangle, want.points[i].triangle);
  }
  EXPECT_EQ(back.point_seed, want.point_seed);

  // Written again without it, the capture names none and the old file is gone.
  const CaptureMeta plain = write_capture(make_capture(), temp.path());
  EXPECT_FALSE(plain.visibility_geometry);
  EXPECT_EQ(file_names(temp.path()), (std::set<std::string>{"capture.json", "gbuffer.exr", "rsm.exr"}));
}

// A capture recorded without the geometry is refused by name of the option that records it; a
// changed, short or long file, a non-finite or non-unit value, or a sidecar file name that is a
// path are refused naming the file and the problem.
TEST(CaptureIo, VisibilityGeometryMissingOrDamagedIsRefused) {
  {
    TempDir temp;
    const CaptureMeta meta = write_capture(make_capture(), temp.path());
    expect_input_error([&] { load_visibility_geometry(temp.path(), meta); },
                       {"capture.json", "no visibility geometry", "--visibility-points", "--visibility none"});
  }
  TempDir temp;
  Capture capture = make_capture();
  capture.visibility_geometry = small_geometry();
  const CaptureMeta meta = write_capture(capture, temp.path());
  const fs::path file = temp.path() / kVisibilityGeometryFile;
  std::string bytes;
  {
    std::ifstream in(file, std::ios::binary);
    bytes.assign((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  }
  const auto write_bytes = [&](const std::string& b) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(b.data(), static_cast<std::streamsize>(b.size()));
  };
  std::string changed = bytes;
  changed[60] ^= 0x01;  // inside the first triangle
  write_bytes(changed);
  expect_input_error([&] { load_visibility_geometry(temp.path(), meta); },
                     {kVisibilityGeometryFile, "hash", "record the capture again"});
  write_bytes(bytes);
  EXPECT_NO_THROW(load_visibility_geometry(temp.path(), meta));

  const std::string where = "g.bin";
  expect_input_error([&] { decode_visibility_geometry(std::span(bytes.data(), bytes.size() - 4), where); },
                     {"g.bin", "announces 2 triangles and 3 points"});
  expect_input_error([&] { decode_visibility_geometry(bytes + "x", where); }, {"g.bin", "announces"});
  expect_input_error([&] { decode_visibility_geometry(std::string("not a file"), where); }, {"g.bin", "VSGLVIS1"});
  VisibilityGeometry bad = small_geometry();
  bad.points[1].position.y = std::numeric_limits<float>::quiet_NaN();
  expect_input_error([&] { decode_visibility_geometry(encode_visibility_geometry(bad), where); },
                     {"point 1", "finite"});
  bad = small_geometry();
  bad.points[2].normal = {0, 0, 2};
  expect_input_error([&] { decode_visibility_geometry(encode_visibility_geometry(bad), where); }, {"point 2", "unit"});
  bad = small_geometry();
  bad.points[0].triangle = 2;  // the file holds triangles 0 and 1
  expect_input_error([&] { decode_visibility_geometry(encode_visibility_geometry(bad), where); },
                     {"point 0", "triangle 2", "holds 2"});
  bad = small_geometry();
  bad.triangle_vertices[4].x = std::numeric_limits<float>::infinity();
  expect_input_error([&] { decode_visibility_geometry(encode_visibility_geometry(bad), where); },
                     {"triangle 1", "not finite"});

  nlohmann::ordered_json sidecar = read_json(temp.path() / "capture.json");
  sidecar["visibility_geometry"]["file"] = "../elsewhere.bin";
  std::ofstream(temp.path() / "capture.json") << sidecar.dump(2);
  expect_load_fails(temp.path(), {"visibility_geometry", "file name"});
}

TEST(CaptureIo, RsmWithoutPdfRoundTripsWithoutPdfChannel) {
  TempDir temp;
  Capture capture = make_capture();
  capture.rsm.has_pdf = false;
  capture.meta.brsm_pyramid.reset();
  std::fill(capture.rsm.planes[kPdf].begin(), capture.rsm.planes[kPdf].end(), 0.0f);
  // All-zero flux is allowed on an RSM (a light that hits nothing reflective).
  for (int c = kDR; c <= kSB; ++c) {
    std::fill(capture.rsm.planes[c].begin(), capture.rsm.planes[c].end(), 0.0f);
  }
  const CaptureMeta written = write_capture(capture, temp.path());
  EXPECT_TRUE(written.rsm_hashes[kPdf].empty());
  const ExrImage rsm = read_exr(temp.path() / "rsm.exr");
  EXPECT_EQ(rsm.find("pdf"), nullptr);
  EXPECT_EQ(rsm.channels.size(), static_cast<std::size_t>(kChannelCount - 1));
  const nlohmann::ordered_json sidecar = read_json(temp.path() / "capture.json");
  EXPECT_EQ(sidecar["rsm"]["has_pdf"], false);
  EXPECT_EQ(sidecar["rsm"]["pdf"], "none");
  EXPECT_FALSE(sidecar["rsm"]["channels"].contains("pdf"));
  EXPECT_FALSE(sidecar.contains("brsm_pyramid"));

  const Capture loaded = load_capture(temp.path());
  EXPECT_FALSE(loaded.rsm.has_pdf);
  expect_planes_equal(capture.rsm, loaded.rsm);
  expect_meta_equal(written, loaded.meta);
}

TEST(CaptureIo, RsmLackingPdfWhileSidecarSaysHasPdfIsRejected) {
  TempDir temp;
  const Capture capture = make_capture();
  write_capture(capture, temp.path());
  rewrite_view(temp.path(), capture.rsm, /*with_pdf=*/false);
  expect_load_fails(temp.path(), {"rsm.exr", "missing channel", "\"pdf\""});
}

TEST(CaptureIo, RsmWithPdfWhileSidecarSaysNoneIsRejected) {
  TempDir temp;
  Capture capture = make_capture();
  capture.rsm.has_pdf = false;
  write_capture(capture, temp.path());
  capture.rsm.has_pdf = true;
  rewrite_view(temp.path(), capture.rsm, /*with_pdf=*/true);
  expect_load_fails(temp.path(), {"rsm.exr", "unexpected extra channel", "\"pdf\""});
}

// DESIGN.md §8: a BRSM PDF made by another importance than this version's is refused, naming why
// and what to do; a capture without a PDF needs none.
TEST(CaptureIo, PdfOfAnOlderImportanceIsRefused) {
  {
    TempDir temp;
    Capture capture = make_capture();
    capture.meta.brsm_importance.clear();  // written before the key: the old importance
    write_capture(capture, temp.path());
    expect_load_fails(temp.path(), {"capture.json", "older importance", "record the capture again"});
  }
  {
    TempDir temp;
    Capture capture = make_capture();
    capture.meta.brsm_importance = "vpl-lobe-sg";
    write_capture(capture, temp.path());
    expect_load_fails(temp.path(), {"capture.json", "vpl-lobe-sg", std::string(kBrsmImportanceModel)});
  }
  {
    TempDir temp;
    Capture capture = make_capture();
    capture.meta.brsm_bias_alpha = 0.5;
    write_capture(capture, temp.path());
    expect_load_fails(temp.path(), {"capture.json", "alpha 0.5"});
  }
  {
    TempDir temp;
    Capture capture = make_capture();
    capture.meta.brsm_importance.clear();
    capture.rsm.has_pdf = false;
    write_capture(capture, temp.path());
    const Capture loaded = load_capture(temp.path());
    EXPECT_FALSE(loaded.rsm.has_pdf);
  }
  {
    TempDir temp;
    write_capture(make_capture(), temp.path());
    const Capture loaded = load_capture(temp.path());
    EXPECT_EQ(loaded.meta.brsm_importance, kBrsmImportanceModel);
    EXPECT_EQ(loaded.meta.brsm_bias_alpha, double{gpu::kBiasReductionAlpha});
  }
}

TEST(CaptureIo, MissingDirectoryIsRejected) {
  TempDir temp;
  const fs::path dir = temp.path() / "no-such-capture";
  expect_load_fails(dir, {dir.generic_string(), "does not exist"});
}

TEST(CaptureIo, MissingSidecarIsRejected) {
  TempDir temp;
  write_capture(make_capture(), temp.path());
  fs::remove(temp.path() / "capture.json");
  expect_load_fails(temp.path(), {(temp.path() / "capture.json").generic_string(), "missing"});
}

TEST(CaptureIo, GarbageSidecarIsRejected) {
  TempDir temp;
  write_capture(make_capture(), temp.path());
  write_text_atomic(temp.path() / "capture.json", std::string("\x7f\x45garbage{]\x01", 11));
  expect_load_fails(temp.path(), {(temp.path() / "capture.json").generic_string(), "not valid JSON"});
}

TEST(CaptureIo, SidecarMissingKeyOrWrongTypeIsNamed) {
  TempDir temp;
  write_capture(make_capture(), temp.path());
  const fs::path sidecar_path = temp.path() / "capture.json";
  const nlohmann::ordered_json original = read_json(sidecar_path);

  nlohmann::ordered_json doc = original;
  doc["camera"].erase("fov_y_deg");
  write_json(sidecar_path, doc);
  expect_load_fails(temp.path(), {"capture.json", "\"camera.fov_y_deg\"", "missing"});

  doc = original;
  doc["rsm"]["width"] = "32";
  write_json(sidecar_path, doc);
  expect_load_fails(temp.path(), {"capture.json", "\"rsm.width\"", "type string"});

  doc = original;
  doc["light"]["view"].erase(3);
  write_json(sidecar_path, doc);
  expect_load_fails(temp.path(), {"capture.json", "\"light.view\" has 15 elements"});

  doc = original;
  doc["gbuffer"]["channels"].erase("roughness");
  write_json(sidecar_path, doc);
  expect_load_fails(temp.path(), {"capture.json", "\"gbuffer.channels.roughness\"", "missing"});

  doc = original;
  doc["brsm_pyramid"] = "buffers";
  write_json(sidecar_path, doc);
  expect_load_fails(temp.path(), {"capture.json", "\"brsm_pyramid\" is \"buffers\"", "\"buffer\" or \"texture\""});

  // A capture written before the path was recorded still loads; its path is unknown.
  doc = original;
  doc.erase("brsm_pyramid");
  write_json(sidecar_path, doc);
  EXPECT_FALSE(load_capture(temp.path()).meta.brsm_pyramid.has_value());

  doc = original;
  doc["format_version"] = 2;
  write_json(sidecar_path, doc);
  expect_load_fails(temp.path(), {"capture.json", "format_version 2"});
}

TEST(CaptureIo, MissingGbufferIsRejected) {
  TempDir temp;
  write_capture(make_capture(), temp.path());
  fs::remove(temp.path() / "gbuffer.exr");
  expect_load_fails(temp.path(), {(temp.path() / "gbuffer.exr").generic_string(), "missing EXR"});
}

TEST(CaptureIo, TruncatedRsmIsRejected) {
  TempDir temp;
  write_capture(make_capture(), temp.path());
  const fs::path rsm = temp.path() / "rsm.exr";
  fs::resize_file(rsm, fs::file_size(rsm) / 2);
  expect_load_fails(temp.path(), {rsm.generic_string(), "truncated"});
}

// Cut anywhere (header, offset table, pixel data, last byte), the file fails at load.
TEST(CaptureIo, ExrTruncatedAnywhereIsRejected) {
  TempDir temp;
  write_capture(make_capture(), temp.path());
  const fs::path gbuffer = temp.path() / "gbuffer.exr";
  std::vector<char> original(fs::file_size(gbuffer));
  std::ifstream(gbuffer, std::ios::binary).read(original.data(),
                                                static_cast<std::streamsize>(original.size()));
  const std::size_t size = original.size();
  for (std::size_t cut : {std::size_t{0}, std::size_t{3}, std::size_t{40}, std::size_t{300},
                          size / 4, size - 1000, size - 1}) {
    SCOPED_TRACE("truncated to " + std::to_string(cut) + " of " + std::to_string(size) + " bytes");
    write_file_atomic(gbuffer, std::span<const char>(original.data(), cut));
    expect_load_fails(temp.path(), {gbuffer.generic_string(), "EXR"});
  }
}

TEST(CaptureIo, GarbageExrIsRejected) {
  TempDir temp;
  write_capture(make_capture(), temp.path());
  const fs::path gbuffer = temp.path() / "gbuffer.exr";
  write_text_atomic(gbuffer, "this is not an EXR file");
  expect_load_fails(temp.path(), {gbuffer.generic_string(), "corrupt"});
}

TEST(CaptureIo, SizeDifferentFromSidecarIsRejected) {
  TempDir temp;
  write_capture(make_capture(), temp.path());
  nlohmann::ordered_json doc = read_json(temp.path() / "capture.json");
  doc["gbuffer"]["width"] = 65;
  write_json(temp.path() / "capture.json", doc);
  expect_load_fails(temp.path(), {"gbuffer.exr", "64x48", "65x48"});
}

TEST(CaptureIo, MissingChannelIsRejected) {
  TempDir temp;
  const Capture capture = make_capture();
  write_capture(capture, temp.path());
  rewrite_view(temp.path(), capture.gbuffer, true, /*skip=*/"N.X");
  expect_load_fails(temp.path(), {"gbuffer.exr", "missing channel", "\"N.X\""});
}

TEST(CaptureIo, ExtraChannelIsRejected) {
  TempDir temp;
  const Capture capture = make_capture();
  write_capture(capture, temp.path());
  std::vector<ExrChannelToWrite> channels;
  for (int c = 0; c < kChannelCount; ++c) {
    channels.push_back({channel_names(ViewKind::kLight)[c], capture.rsm.planes[c]});
  }
  channels.push_back({"Z", capture.rsm.planes[kPZ]});
  write_exr(temp.path() / "rsm.exr", 32, 32, channels);
  expect_load_fails(temp.path(), {"rsm.exr", "unexpected extra channel", "\"Z\""});
}

TEST(CaptureIo, HalfChannelIsRejected) {
  TempDir temp;
  const Capture capture = make_capture();
  write_capture(capture, temp.path());
  rewrite_view(temp.path(), capture.gbuffer, true, "", ExrSampleType::kHalf);
  expect_load_fails(temp.path(), {"gbuffer.exr", "\"N.X\"", "half", "expected float"});
}

TEST(CaptureIo, NanTexelIsRejected) {
  TempDir temp;
  Capture capture = make_capture();
  capture.gbuffer.at(kDG, 5, 7) = std::numeric_limits<float>::quiet_NaN();
  write_capture(capture, temp.path());
  expect_load_fails(temp.path(), {"gbuffer.exr", "albedo_diffuse.G", "NaN", "texel (5, 7)"});
}

TEST(CaptureIo, InfTexelIsRejected) {
  TempDir temp;
  Capture capture = make_capture();
  capture.rsm.at(kPZ, 31, 2) = -std::numeric_limits<float>::infinity();
  write_capture(capture, temp.path());
  expect_load_fails(temp.path(), {"rsm.exr", "\"P.Z\"", "-Inf", "texel (31, 2)"});
}

TEST(CaptureIo, ValidFlagOtherThanZeroOrOneIsRejected) {
  TempDir temp;
  Capture capture = make_capture();
  capture.rsm.at(kValid, 4, 4) = 0.5f;
  write_capture(capture, temp.path());
  expect_load_fails(temp.path(), {"rsm.exr", "valid flag", "texel (4, 4)"});
}

TEST(CaptureIo, NonUnitNormalIsRejectedOnlyOnValidTexels) {
  TempDir temp;
  Capture capture = make_capture();
  ASSERT_EQ(capture.gbuffer.at(kValid, 0, 0), 0.0f);  // (0, 0) is invalid
  capture.gbuffer.at(kNX, 0, 0) = 3.0f;               // ignored there
  write_capture(capture, temp.path());
  EXPECT_NO_THROW(load_capture(temp.path()));

  ASSERT_EQ(capture.gbuffer.at(kValid, 10, 3), 1.0f);
  capture.gbuffer.at(kNY, 10, 3) += 0.01f;
  write_capture(capture, temp.path());
  expect_load_fails(temp.path(), {"gbuffer.exr", "not unit length", "texel (10, 3)"});
}

TEST(CaptureIo, NegativePdfIsRejected) {
  TempDir temp;
  Capture capture = make_capture();
  capture.rsm.at(kPdf, 3, 9) = -0.25f;
  write_capture(capture, temp.path());
  expect_load_fails(temp.path(), {"rsm.exr", "negative", "texel (3, 9)"});
}

TEST(CaptureIo, AllZeroCameraPdfIsRejected) {
  TempDir temp;
  Capture capture = make_capture();
  std::fill(capture.gbuffer.planes[kPdf].begin(), capture.gbuffer.planes[kPdf].end(), 0.0f);
  write_capture(capture, temp.path());
  expect_load_fails(temp.path(), {"gbuffer.exr", "all-zero PDF", "no texel can be sampled"});
}

TEST(CaptureIo, AllZeroRsmPdfIsRejectedWhenPresent) {
  TempDir temp;
  Capture capture = make_capture();
  std::fill(capture.rsm.planes[kPdf].begin(), capture.rsm.planes[kPdf].end(), 0.0f);
  write_capture(capture, temp.path());
  expect_load_fails(temp.path(), {"rsm.exr", "all-zero PDF"});
}

TEST(CaptureIo, ChangedFileIsRejectedByHash) {
  TempDir temp;
  Capture capture = make_capture();
  const CaptureMeta written = write_capture(capture, temp.path());
  capture.gbuffer.at(kRoughness, 20, 20) += 0.125f;  // still a valid value
  rewrite_view(temp.path(), capture.gbuffer, true);
  expect_load_fails(temp.path(), {"gbuffer.exr", "\"roughness\"", "hash mismatch",
                                  written.gbuffer_hashes[kRoughness],
                                  plane_hash(capture.gbuffer.planes[kRoughness])});
}

TEST(CaptureIo, WriteRejectsPlanesOfTheWrongSize) {
  TempDir temp;
  Capture capture = make_capture();
  capture.rsm.planes[kNZ].pop_back();
  expect_input_error([&] { write_capture(capture, temp.path()); }, {"rsm.exr", "\"N.Z\""});
  EXPECT_TRUE(file_names(temp.path()).empty());
}

TEST(CaptureIo, WriteRejectsASceneNameThatIsNotUtf8) {
  TempDir temp;
  Capture capture = make_capture();
  capture.meta.scene = "bad\xff";
  expect_input_error([&] { write_capture(capture, temp.path()); }, {"capture.json", "UTF-8"});
  EXPECT_FALSE(fs::exists(temp.path() / "capture.json"));  // the capture was never committed
}

TEST(CaptureIo, AtomicWriterReplacesAndLeavesNoTemporaries) {
  TempDir temp;
  const fs::path file = temp.path() / "result.json";
  write_text_atomic(file, "first");
  write_text_atomic(file, "second");
  std::ifstream in(file);
  std::string content;
  std::getline(in, content);
  EXPECT_EQ(content, "second");
  EXPECT_EQ(file_names(temp.path()), std::set<std::string>{"result.json"});

  // A rename that fails (a directory is in the way) reports the path and removes the temporary.
  const fs::path blocked = temp.path() / "blocked";
  fs::create_directories(blocked / "inside");
  expect_input_error([&] { write_text_atomic(blocked, "x"); }, {blocked.generic_string(), "renaming"});
  EXPECT_EQ(file_names(temp.path()), (std::set<std::string>{"blocked", "result.json"}));

  // A directory that does not exist: nothing to clean up, still a clear error.
  const fs::path nowhere = temp.path() / "missing" / "out.json";
  expect_input_error([&] { write_text_atomic(nowhere, "x"); }, {nowhere.generic_string()});
}


// DESIGN.md §12: a corrupted channel name (the byte of 'i' in "valid" flipped to 0x97, as seen on a
// damaged rsm.exr) reaches the message escaped, never as raw bytes (harness/core/printable_text.hpp).
TEST(CaptureIo, CorruptChannelNameIsEscapedInTheMessage) {
  TempDir temp;
  write_capture(make_capture(), temp.path());
  const fs::path rsm = temp.path() / "rsm.exr";
  std::string bytes = [&] {
    std::ifstream in(rsm, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  }();
  const std::string name("valid\0", 6);
  const std::size_t at = bytes.find(name);
  ASSERT_NE(at, std::string::npos) << "the channel list names \"valid\"";
  bytes[at + 3] = static_cast<char>(0x97);
  write_file_atomic(rsm, std::span<const char>(bytes.data(), bytes.size()));
  try {
    load_capture(temp.path());
    ADD_FAILURE() << "the corrupted capture loaded";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("unexpected extra channel \"val\\x97d\""), std::string::npos) << message;
    for (const char ch : message) EXPECT_TRUE(ch >= 0x20 && ch <= 0x7e) << "raw byte " << int(ch) << " in: " << message;
  }
}

// DESIGN.md §10: temporaries of a killed writer (".NAME.tmp-PID-N" whose PID is gone) are removed by
// the next write of NAME; one of a live process is left alone (it may still be writing).
TEST(CaptureIo, AtomicWriterRemovesTemporariesOfDeadWriters) {
  TempDir temp;
  const std::uint64_t dead = test::ended_process_id();
  ASSERT_GT(dead, 0u);
  test::ChildProcess running = test::ChildProcess::start_idle();
  const fs::path file = temp.path() / "table1.json";
  const std::string stale = ".table1.json.tmp-" + std::to_string(dead) + "-0";
  const std::string live = ".table1.json.tmp-" + std::to_string(running.id()) + "-3";
  const std::string other = ".table2.json.tmp-" + std::to_string(dead) + "-1";
  for (const auto& name : {stale, live, other}) std::ofstream(temp.path() / name) << "partial";
  write_text_atomic(file, "new");
  EXPECT_EQ(file_names(temp.path()), (std::set<std::string>{"table1.json", live, other}));
}

// The scene names output files (`shade`): a sidecar whose scene is a path is refused, escaped.
TEST(CaptureIo, SceneThatIsNotANameIsRejected) {
  TempDir temp;
  write_capture(make_capture(), temp.path());
  nlohmann::ordered_json doc = read_json(temp.path() / "capture.json");
  doc["scene"] = "../../tmp/x\x1b";
  write_json(temp.path() / "capture.json", doc);
  expect_load_fails(temp.path(), {"capture.json", "key \"scene\"", "\"../../tmp/x\\x1b\"", "a name"});
}

}  // namespace
}  // namespace vsgl
