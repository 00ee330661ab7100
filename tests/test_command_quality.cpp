// `vsgl-bench quality` as a user runs it: usage and input errors exit with their codes, and a run on
// a recorded tiny capture (plus a 3-frame sequence) writes quality.json (conforming to
// results/schema/quality.schema.json: schema, capture hashes, claims with verdicts), quality.md and
// the pictures.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "harness/core/json_schema_subset.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

TEST(QualityCli, UsageAndInputErrors) {
  auto r = test::run_cli("quality");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--capture"), std::string::npos) << r.output;
  r = test::run_cli("quality --capture x --k-sweep 1,0");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  r = test::run_cli("quality --capture /nonexistent/vsgl_capture");
  EXPECT_EQ(r.exit_code, 3) << r.output;
}

TEST(QualityCli, TinyCaptureWritesJsonMarkdownAndPictures) {
  const test::TempDir root_temp("quality_cli");
  const std::filesystem::path& root = root_temp.path();
  const std::string sizes = " --gbuffer 96x64 --rsm 64";
  auto r = test::run_cli("record --scene tiny" + sizes + " --out " + (root / "cap").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = test::run_cli("record --scene tiny --frames 3" + sizes + " --out " + (root / "seq").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = test::run_cli("quality --capture " + (root / "cap").string() + " --sequence " + (root / "seq").string() +
                    " --frames 3 --generators fis_tok15,fis_modified --k-sweep 1,4 --error-stride 2 --flicker-width 48"
                    " --reference-rsm 32 --sequence-reference-rsm 16 --light-vsgls 128 --camera-vsgls 256 --out " +
                    (root / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto dir = root / "out" / "tiny";
  for (const char* f : {"quality.json", "quality.md", "tiny_renders.png", "tiny_worst_frames.png", "tiny_k_sweep.png",
                        "tiny_coverage_light_view_fis_tok15.png", "tiny_coverage_camera_view_fis_modified.png"})
    EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
  std::ifstream in(dir / "quality.json");
  const auto j = nlohmann::ordered_json::parse(in);
  EXPECT_EQ(j["schema"], "vsgl-quality");
  // stdev: sample (n - 1) since 3; flux origin and converged reference since 4; per-frame series
  // since 5; the reference ladder since 6; the errors against every rung since 7
  EXPECT_EQ(j["schema_version"], 7);
  // What the writer writes is what the committed schema describes.
  for (const std::string& problem : validate_against_schema(
           j, test::read_json(std::filesystem::path(VSGL_SOURCE_DIR) / "results/schema/quality.schema.json")))
    ADD_FAILURE() << problem;
  EXPECT_TRUE(j["capture"]["hashes"]["rsm"].contains("pdf")) << j["capture"]["hashes"].dump();
  EXPECT_EQ(j["flicker_static"]["generators"]["fis_modified"]["frames"], 3);
  EXPECT_EQ(j["flicker_animated"]["frames"], 3);
  EXPECT_EQ(j["k_sweep"]["fis_tok15"].size(), 2u);
  ASSERT_GE(j["claims"].size(), 6u);
  for (const auto& c : j["claims"]) EXPECT_TRUE(c.contains("verdict")) << c.dump();
  // DESIGN.md §11a: the PDF's frequency content per view; per FIS generator the coverage beside its
  // lattice floor, the excess the difference of the two.
  for (const char* view : {"light_view", "camera_view"}) {
    const auto& v = j["views"][view];
    EXPECT_GE(v["pdf_frequency"]["mean_square"].get<double>(), 1.0) << view;
    for (const char* g : {"fis_tok15", "fis_modified"}) {
      const auto& c = v["generators"][g]["coverage"];
      for (const char* fp : {"box", "eq3"}) {
        const double e = c[fp]["count_error"], f = c["lattice_floor"][fp]["count_error"];
        EXPECT_NEAR(c["excess"][fp]["count_error"].get<double>(), e - f, 1e-12) << view << " " << g << " " << fp;
        EXPECT_GT(f, 0.0) << view << " " << g << " " << fp;
      }
    }
  }
  // Fig. 1 is judged on the excess over the floor, per frame, with the bound of DESIGN.md §11a.1.
  bool fig1_on_excess = false;
  for (const auto& c : j["claims"])
    if (c["measure"].get<std::string>().rfind("light_view: coverage excess", 0) == 0) {
      fig1_on_excess = true;
      EXPECT_EQ(c["bound"], -0.02);
      EXPECT_EQ(c["frames"], 3);
      EXPECT_EQ(c["interval"].size(), 2u);
    }
  EXPECT_TRUE(fig1_on_excess) << j["claims"].dump();
  const double power = j["views"]["light_view"]["generators"]["fis_modified"]["power"]["power_ratio"];
  EXPECT_GT(power, 0.5);
  EXPECT_LT(power, 1.5);
  // Where the power comes from (flux_origin.hpp): the classes sum to the records' sum Phi / flux, the
  // view's flux shares to 1, and Eq. 5 keeps a PDF-proportional flux's power (count 1).
  for (const char* view : {"light_view", "camera_view"}) {
    double shares = 0;
    for (const auto& f : j["views"][view]["flux_by_pdf"]["flux_share"]) shares += f.get<double>();
    EXPECT_NEAR(shares, 1.0, 1e-9) << view;
    for (const char* g : {"fis_tok15", "fis_modified"}) {
      const auto& o = j["views"][view]["generators"][g]["flux_origin"];
      double gathered = 0;
      for (const auto& f : o["gathered"]) gathered += f.get<double>();
      const double ratio = j["views"][view]["generators"][g]["power"]["power_ratio"];
      EXPECT_NEAR(gathered, ratio, 2e-3 * ratio) << view << " " << g;
    }
    EXPECT_NEAR(j["views"][view]["generators"]["fis_modified"]["flux_origin"]["pdf_weighted_count"].get<double>(), 1.0,
                2e-3)
        << view;
  }
  // ... and over the 3 static frames' lattice offsets, for the light view.
  for (const char* g : {"fis_tok15", "fis_modified"}) {
    const auto& o = j["views"]["light_view"]["generators"][g]["flux_origin"]["over_frames"];
    EXPECT_EQ(o["frames"], 3) << g;
    EXPECT_LE(o["ratio_min"].get<double>(), o["ratio_mean"].get<double>()) << g;
    EXPECT_GE(o["ratio_max"].get<double>(), o["ratio_mean"].get<double>()) << g;
    EXPECT_EQ(o["gathered_mean"].size(), j["views"]["light_view"]["flux_by_pdf"]["flux_share"].size()) << g;
  }
  EXPECT_FALSE(j["views"]["camera_view"]["generators"]["fis_tok15"]["flux_origin"].contains("over_frames"));
  // The reference: RSM stride 2 (--reference-rsm 32 of 64), the coarser strides 16, 8, 4 against it
  // on the same pixels, the given camera stride, and the PDF-support reference beside it.
  const auto& ref = j["reference"];
  EXPECT_EQ(ref["rsm_stride"], 2);
  ASSERT_EQ(ref["convergence"].size(), 4u);
  EXPECT_EQ(ref["convergence"][0]["rsm_stride"], 16);
  EXPECT_EQ(ref["convergence"][3]["rsm_stride"], 2);
  EXPECT_EQ(ref["convergence"][3]["relative_rmse"], 0.0);
  EXPECT_EQ(ref["own_error"], ref["convergence"][2]["relative_rmse"]);
  EXPECT_EQ(ref["camera_size"]["error_stride"], 2);
  EXPECT_LE(ref["support"]["vpls"].get<uint64_t>(), ref["vpls"].get<uint64_t>());
  EXPECT_TRUE(j["reference_error_support"].contains("fis_modified"));
  // DESIGN.md §11a.1: every static frame's error, flicker and (FIS) coverage, at the reference's
  // pixels; the offset-0 frame is the render the reference error describes.
  const auto& fs = j["frames_static"];
  EXPECT_EQ(fs["gbuffer_stride"], 2);
  EXPECT_EQ(fs["image"], ref["image"]);
  EXPECT_EQ(j["flicker_static"]["image"], ref["image"]);
  for (const char* g : {"fis_tok15", "fis_modified"}) {
    const auto& series = fs["generators"][g]["series"];
    for (const char* metric : {"rel_mse", "relative_rmse", "scaled_rmse", "scale", "flip", "p99_pixel_error",
                               "max_pixel_error", "flicker_deviation", "light_view_coverage_excess",
                               "camera_view_coverage_excess", "light_view_max_over_mean", "camera_view_mass_stdev"}) {
      ASSERT_TRUE(series.contains(metric)) << g << " " << metric;
      EXPECT_EQ(series[metric]["per_frame"].size(), 3u) << g << " " << metric;
      EXPECT_LE(series[metric]["mean"].get<double>(), series[metric]["max"].get<double>()) << g << " " << metric;
    }
    EXPECT_DOUBLE_EQ(series["relative_rmse"]["per_frame"][0].get<double>(),
                     j["reference_error"][g]["relative_rmse"].get<double>())
        << g;
    for (const auto& v : series["flip"]["per_frame"]) {
      EXPECT_GT(v.get<double>(), 0.0) << g;
      EXPECT_LE(v.get<double>(), 1.0) << g;
    }
    EXPECT_LT(fs["generators"][g]["worst_frame"].get<int>(), 3) << g;
    // The K sweep's row at the run's K reuses the static frames.
    EXPECT_EQ(j["k_sweep"][g][0]["per_frame"]["relative_rmse"]["per_frame"], series["relative_rmse"]["per_frame"]) << g;
    EXPECT_EQ(j["k_sweep"][g][1]["per_frame"]["flicker_deviation"]["per_frame"].size(), 3u) << g;
  }
  EXPECT_EQ(j["frames_animated"]["generators"]["fis_modified"]["series"]["error_flicker_deviation"]["per_frame"].size(),
            3u);
  for (const char* metric : {"relative_rmse", "p99_pixel_error", "flip", "rel_mse"})
    EXPECT_GT(ref["own_errors"][metric].get<double>(), 0.0) << metric;
  // The shading it was made with (DESIGN.md §8): Tok15 Eq. 3 with two lobes, and §3.3's alpha.
  EXPECT_EQ(j["config"]["shading"]["model"], "tok15-eq3-k2");
  EXPECT_EQ(j["config"]["shading"]["bias_reduction_alpha"].get<double>(), 1.0);
  // The ladder (DESIGN.md §11a): the rungs at RSM strides 16, 8, 4 and 2 of the 64^2 RSM, each
  // against the next finer; the last difference is the own error, the rate the geometric mean of
  // the two ratios, eps_inf = own rho / (1 - rho) where rho < 1.
  const auto& ladder = ref["ladder"];
  EXPECT_EQ(ladder["rsm_strides"], nlohmann::ordered_json::array({16, 8, 4, 2}));
  EXPECT_EQ(ladder["rsm_sides"], nlohmann::ordered_json::array({4, 8, 16, 32}));
  // Every rung's mean luminance, the reference's last: lit pixels exist, so each is positive.
  ASSERT_EQ(ladder["mean_luminance"].size(), 4u);
  for (const auto& y : ladder["mean_luminance"]) EXPECT_GT(y.get<double>(), 0.0);
  for (const char* metric : {"relative_rmse", "p99_pixel_error", "flip", "rel_mse", "scaled_rmse"}) {
    const auto& l = ladder["metrics"][metric];
    ASSERT_EQ(l["differences"].size(), 3u) << metric;
    EXPECT_EQ(l["differences"][2], ref["own_errors"][metric]) << metric;
    const double e8 = l["differences"][0], e4 = l["differences"][1], e2 = l["differences"][2];
    EXPECT_DOUBLE_EQ(l["ratios"][0].get<double>(), e4 / e8) << metric;
    EXPECT_DOUBLE_EQ(l["ratios"][1].get<double>(), e2 / e4) << metric;
    const double rate = l["rate"];
    EXPECT_NEAR(rate, std::sqrt(e2 / e8), 1e-12 * rate) << metric;
    if (rate < 1.0) EXPECT_NEAR(l["remaining_error"].get<double>(), e2 * rate / (1.0 - rate), 1e-12) << metric;
    else EXPECT_TRUE(l["remaining_error"].is_null()) << metric;
  }
  EXPECT_FALSE(ladder["metrics"].contains("scale"));
  // Every static frame and K sweep step against the stride-2 rung too, and each reference-decided
  // claim with what the rule read.
  for (const char* g : {"fis_tok15", "fis_modified"}) {
    EXPECT_EQ(fs["generators"][g]["second_rung"]["relative_rmse"]["per_frame"].size(), 3u) << g;
    EXPECT_EQ(fs["generators"][g]["second_rung"]["p99_pixel_error"]["per_frame"].size(), 3u) << g;
    EXPECT_NE(fs["generators"][g]["second_rung"]["relative_rmse"]["per_frame"],
              fs["generators"][g]["series"]["relative_rmse"]["per_frame"])
        << g;
    for (const auto& row : j["k_sweep"][g])
      EXPECT_EQ(row["per_frame_second_rung"]["relative_rmse"]["per_frame"].size(), 3u) << g;
    EXPECT_EQ(j["k_sweep"][g][0]["per_frame_second_rung"]["relative_rmse"]["per_frame"],
              fs["generators"][g]["second_rung"]["relative_rmse"]["per_frame"])
        << g;
    // ... and against the coarser rungs, strides 16 and 8 (schema 7), each a different image.
    const auto& coarse = fs["generators"][g]["coarse_rungs"];
    ASSERT_EQ(coarse.size(), 2u) << g;
    EXPECT_EQ(coarse[0]["p99_pixel_error"]["per_frame"].size(), 3u) << g;
    EXPECT_NE(coarse[0]["relative_rmse"]["per_frame"], coarse[1]["relative_rmse"]["per_frame"]) << g;
    for (const auto& row : j["k_sweep"][g]) EXPECT_EQ(row["per_frame_coarse_rungs"].size(), 2u) << g;
    EXPECT_EQ(j["k_sweep"][g][0]["per_frame_coarse_rungs"][1]["relative_rmse"]["per_frame"],
              coarse[1]["relative_rmse"]["per_frame"])
        << g;
  }
  EXPECT_EQ(fs["coarse_rung_strides"], nlohmann::ordered_json::array({16, 8}));
  bool tail = false;
  for (const auto& c : j["claims"])
    if (c["measure"].get<std::string>().rfind("tail error", 0) == 0) {
      tail = true;
      EXPECT_EQ(c["reference_metric"], "p99_pixel_error");
      EXPECT_EQ(c["reference_rate"], ladder["metrics"]["p99_pixel_error"]["rate"]);
      EXPECT_EQ(c["reference_remaining_error"], ladder["metrics"]["p99_pixel_error"]["remaining_error"]);
      EXPECT_TRUE(c["second_rung"].contains("verdict")) << c.dump();
      // The ratio against each of the four rungs, the reference's last (DESIGN.md §11a *Rule*).
      ASSERT_EQ(c["rung_estimates"].size(), 4u) << c.dump();
      EXPECT_EQ(c["rung_estimates"][3], c["estimate"]) << c.dump();
      EXPECT_EQ(c["rung_estimates"][2], c["second_rung"]["estimate"]) << c.dump();
    }
  EXPECT_TRUE(tail) << j["claims"].dump();
}

// A reference capture (--reference-capture): the same frame with a 4x larger RSM lends the reference
// its texels as VPLs, which the document names; a capture of another frame is refused (exit 3).
TEST(QualityCli, ReferenceCaptureLendsItsLargerRsm) {
  const test::TempDir root_temp("quality_reference_capture");
  const std::filesystem::path& root = root_temp.path();
  const auto record = [&](const std::string& sizes, const char* name) {
    const auto r = test::run_cli("record --scene tiny " + sizes + " --out " + (root / name).string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
  };
  record("--gbuffer 96x64 --rsm 32", "cap");
  record("--gbuffer 96x64 --rsm 128", "ref");
  record("--gbuffer 64x64 --rsm 128", "other_camera");
  const std::string options =
      " --frames 2 --generators fis_tok15 --k-sweep 1 --error-stride 4 --light-vsgls 64"
      " --camera-vsgls 128 --out ";
  const auto quality = [&](const std::string& extra, const char* out) {
    return test::run_cli("quality --capture " + (root / "cap").string() + extra + options + (root / out).string());
  };
  auto r = quality("", "own");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = quality(" --reference-capture " + (root / "ref").string(), "lent");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto own = test::read_json(root / "own" / "tiny" / "quality.json");
  const auto lent = test::read_json(root / "lent" / "tiny" / "quality.json");
  for (const std::string& problem : validate_against_schema(
           lent, test::read_json(std::filesystem::path(VSGL_SOURCE_DIR) / "results/schema/quality.schema.json")))
    ADD_FAILURE() << problem;
  EXPECT_EQ(own["reference"]["vpl_source"]["capture"], "the capture itself");
  EXPECT_EQ(lent["reference"]["vpl_source"]["capture"], "reference capture");
  EXPECT_EQ(lent["reference"]["vpl_source"]["rsm"], nlohmann::ordered_json::array({128, 128}));
  EXPECT_EQ(lent["reference"]["reference_rsm_side"], 128);
  EXPECT_EQ(lent["capture"]["rsm"], nlohmann::ordered_json::array({32, 32}));  // the generators' input is unchanged
  // 16 times the texels: far more VPLs, the same light to within the discretisation.
  EXPECT_GT(lent["reference"]["vpls"].get<double>(), 8.0 * own["reference"]["vpls"].get<double>());
  EXPECT_NEAR(lent["reference"]["power_ratio"].get<double>(), 1.0, 0.1);
  std::ifstream md(root / "lent" / "tiny" / "quality.md");
  const std::string text((std::istreambuf_iterator<char>(md)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("the 128x128 RSM of the reference capture"), std::string::npos);

  r = quality(" --reference-capture " + (root / "other_camera").string(), "refused");
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("64x64 G-buffer, the capture 96x64"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(root / "refused" / "tiny" / "quality.json"));
}

}  // namespace
}  // namespace vsgl

namespace vsgl {
namespace {

// Fig. 7 (DESIGN.md §11a.2) with --visibility ism on the atrium stand-in, whose columns occlude
// part of the indirect light: the occlusion block (R_v's ladder over the occluded region, every
// frame's error over it against each rung, the exact control), its picture, and the two Fig. 7
// claims per FIS generator; --visibility none leaves all of it out.
TEST(QualityCli, VisibilityAddsTheOccludedLightOfFig7) {
  const test::TempDir root_temp("quality_occlusion");
  const std::filesystem::path& root = root_temp.path();
  auto r = test::run_cli("record --scene atrium --gbuffer 96x54 --rsm 32 --out " + (root / "cap").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string options =
      " --frames 3 --k-sweep 1 --error-stride 1 --light-vsgls 64 --camera-vsgls 128 --ism-side 16"
      " --control-frames 2 --out ";
  r = test::run_cli("quality --capture " + (root / "cap").string() + " --visibility ism" + options +
                    (root / "ism").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto dir = root / "ism" / "atrium";
  EXPECT_TRUE(std::filesystem::exists(dir / "atrium_occlusion.png"));
  std::ifstream in(dir / "quality.json");
  const auto j = nlohmann::ordered_json::parse(in);
  for (const std::string& problem : validate_against_schema(
           j, test::read_json(std::filesystem::path(VSGL_SOURCE_DIR) / "results/schema/quality.schema.json")))
    ADD_FAILURE() << problem;
  EXPECT_EQ(j["config"]["visibility"], "ism");
  const auto& o = j["occlusion"];
  EXPECT_NE(o["visibility"].get<std::string>().find("16x16"), std::string::npos) << o["visibility"];
  // R_v from the full 32^2 RSM, its rungs at strides 8, 4, 2 and 1.
  EXPECT_EQ(o["reference"]["rsm_stride"], 1);
  EXPECT_EQ(o["reference"]["ladder"]["rsm_strides"], nlohmann::ordered_json::array({8, 4, 2, 1}));
  EXPECT_EQ(o["reference"]["ladder"]["metrics"]["relative_rmse"]["differences"].size(), 3u);
  const uint64_t occluded = o["region"]["occluded_pixels"], surface = o["region"]["surface_pixels"];
  ASSERT_GE(occluded, 50u) << o["region"].dump();
  EXPECT_LE(occluded, surface);
  EXPECT_GT(o["region"]["occluded_light_share"].get<double>(), 0.0);
  EXPECT_EQ(o["note"], "");
  EXPECT_EQ(o["frames"]["coarse_rung_strides"], nlohmann::ordered_json::array({8, 4}));
  for (const char* g : {"fis_tok15", "fis_modified", "kmeans_2d", "kmeans_3d"}) {
    const auto& gen = o["frames"]["generators"][g];
    EXPECT_EQ(gen["series"]["relative_rmse"]["per_frame"].size(), 3u) << g;
    EXPECT_EQ(gen["second_rung"]["relative_rmse"]["per_frame"].size(), 3u) << g;
    EXPECT_EQ(gen["coarse_rungs"].size(), 2u) << g;
    EXPECT_EQ(o["control"]["relative_rmse"][g].size(), 2u) << g;
    for (const auto& e : gen["series"]["relative_rmse"]["per_frame"]) EXPECT_GT(e.get<double>(), 0.0) << g;
  }
  int fig7 = 0;
  for (const auto& c : j["claims"])
    if (c["measure"].get<std::string>().rfind("Fig. 7 ", 0) == 0) {
      ++fig7;
      EXPECT_EQ(c["rung_estimates"].size(), 4u) << c.dump();
    }
  EXPECT_EQ(fig7, 4);
  std::ifstream md_in(dir / "quality.md");
  const std::string md((std::istreambuf_iterator<char>(md_in)), std::istreambuf_iterator<char>());
  EXPECT_NE(md.find("## Fig. 7: the light occluded by the columns"), std::string::npos);

  r = test::run_cli("quality --capture " + (root / "cap").string() + " --visibility none" +
                    " --frames 3 --k-sweep 1"
                    " --error-stride 2 --light-vsgls 64 --camera-vsgls 128 --out " +
                    (root / "none").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream none_in(root / "none" / "atrium" / "quality.json");
  const auto n = nlohmann::ordered_json::parse(none_in);
  EXPECT_EQ(n["config"]["visibility"], "none");
  EXPECT_FALSE(n.contains("occlusion"));
  for (const auto& c : n["claims"]) EXPECT_NE(c["measure"].get<std::string>().rfind("Fig. 7 ", 0), 0u);
  EXPECT_FALSE(std::filesystem::exists(root / "none" / "atrium" / "atrium_occlusion.png"));
}

// A capture without the visibility geometry is refused by --visibility ism (the default) before
// any work, naming the option of `record` that stores it and --visibility none; the maps' options
// without --visibility ism and more control frames than frames are refused too. Nothing is written.
TEST(QualityCli, VisibilityNeedsTheGeometryAndItsOwnOptions) {
  const test::TempDir root_temp("quality_visibility_errors");
  const std::filesystem::path& root = root_temp.path();
  auto r = test::run_cli("record --scene tiny --gbuffer 48x32 --rsm 16 --visibility-points 0 --out " +
                         (root / "cap").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string capture = " --capture " + (root / "cap").string() + " --out " + (root / "out").string();
  r = test::run_cli("quality" + capture);
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("--visibility-points"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--visibility none"), std::string::npos) << r.output;
  r = test::run_cli("quality" + capture + " --visibility none --ism-side 16");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--ism-side"), std::string::npos) << r.output;
  r = test::run_cli("quality" + capture + " --visibility exact --frames 2 --control-frames 3");
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("--control-frames"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(root / "out")) << "nothing is written";
}

}  // namespace
}  // namespace vsgl
