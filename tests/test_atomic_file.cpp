// No half-written output after a kill (DESIGN.md §10, §12). Real `vsgl-bench tables` and
// `record` runs (of the test build of vsgl-bench, the shipped program with the test hooks:
// tests/hooks/) are stopped at known points of writing a known output file by the atomic
// writer's pause hook (tests/hooks/pause_at_write.hpp) and then killed by this test (SIGKILL;
// TerminateProcess on Windows: tests/child_process.hpp).
// Afterwards every output path must hold the complete old file or the complete new one, the
// file being written at "partial" or "complete" must still be the old one (and its temporary
// must exist: the hook really stopped mid-write), at "renamed" the new one; the next run must
// succeed and leave no temporary behind.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/capture/capture.hpp"
#include "harness/capture/capture_files.hpp"
#include "harness/core/error.hpp"
#include "harness/capture/exr_io.hpp"
#include "harness/core/json_schema_subset.hpp"
#include "harness/formats/sweep_model.hpp"
#include "harness/formats/table_model.hpp"
#include "child_process.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::string test_device() {
  const char* env = std::getenv("VSGL_TEST_DEVICE");
  return env != nullptr ? env : "llvmpipe";
}

struct Child {
  test::ChildProcess process;
  fs::path log;
};

// Starts the test build of vsgl-bench with `args`, stdout and stderr to `log`, and the pause hook
// set when `pause_at` is not empty.
Child start(const std::vector<std::string>& args, const fs::path& log, const std::string& pause_at,
            const fs::path& notify) {
  const test::EnvironmentChanges hook =
      pause_at.empty()
          ? test::EnvironmentChanges{{"VSGL_TEST_PAUSE_AT", ""}}
          : test::EnvironmentChanges{{"VSGL_TEST_PAUSE_AT", pause_at}, {"VSGL_TEST_PAUSE_NOTIFY", notify.string()}};
  return Child{test::ChildProcess::start(VSGL_BENCH_TEST_BUILD_EXE, args, log, hook), log};
}

int run_to_end(const std::vector<std::string>& args, const fs::path& log) {
  return start(args, log, "", {}).process.wait();
}

// Waits until the child reached the pause point (the marker appears), then kills it (SIGKILL;
// TerminateProcess). Fails (and kills the child) when it exits first or takes longer than the limit.
void kill_at_pause(Child c, const fs::path& notify) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(8);
  bool paused = false;
  while (std::chrono::steady_clock::now() < deadline) {
    if (fs::exists(notify) && !slurp(notify).empty()) {
      paused = true;
      break;
    }
    if (const auto code = c.process.exit_code_if_ended()) {
      ADD_FAILURE() << "the run ended (exit code " << *code << ") before the pause point:\n" << slurp(c.log);
      return;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  const bool killed = c.process.kill_and_wait();
  EXPECT_TRUE(paused) << "the run never reached the pause point:\n" << slurp(c.log);
  EXPECT_TRUE(killed);
  fs::remove(notify);
}

// The atomic writer's temporaries in `dir` (".NAME.tmp-PID-N"), of file `name` or of any file.
std::vector<std::string> temporaries(const fs::path& dir, const std::string& name = "") {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string n = e.path().filename().string();
    if (name.empty() ? n.find(".tmp-") != std::string::npos : n.rfind("." + name + ".tmp-", 0) == 0) names.push_back(n);
  }
  return names;
}

// A table JSON is complete when it parses and conforms to the schema; its markdown when it ends
// with the newline of its last line and names its table.
bool complete_table_file(const fs::path& p) {
  const std::string text = slurp(p);
  if (text.empty() || text.back() != '\n') return false;
  if (p.extension() == ".md") return text.find("Table") != std::string::npos;
  try {
    std::ifstream in(VSGL_SOURCE_DIR "/results/schema/table.schema.json");
    const nlohmann::ordered_json schema = nlohmann::ordered_json::parse(in);
    return validate_against_schema(nlohmann::ordered_json::parse(text), schema).empty();
  } catch (const nlohmann::ordered_json::exception&) {
    return false;
  }
}

TEST(KillDuringWrite, TablesOutputsAreOldOrNewNeverPartial) {
  const test::TempDir root_temp("kill_tables");
  const fs::path& root = root_temp.path();
  const fs::path out = root / "out";
  const std::vector<std::string> args = {
      "tables", "--quick", "--captures", (root / "captures").string(), "--out", out.string(), "--gbuffer", "96x64",
      "--rsm", "64", "--camera-vsgls", "48", "--light-vsgls", "24", "--generators", "fis_tok15",
      "--repetitions", "2", "--max-repetitions", "2", "--no-progress", "--device", test_device()};
  ASSERT_EQ(run_to_end(args, root / "first.log"), 0) << slurp(root / "first.log");
  // The order of first writes (each table as soon as it is measured; table1.* is written again,
  // with the Table 1 -> 2 change, after table2.*).
  const std::vector<std::string> outputs = {"table1.json", "table1.md", "table2.json", "table2.md"};

  const fs::path notify = root / "paused";
  // Every point once, on files early and late in the write order.
  for (const auto& [point, file] : std::vector<std::pair<std::string, std::string>>{
           {"partial", "table1.json"}, {"complete", "table2.md"}, {"renamed", "table1.md"}}) {
    {
      SCOPED_TRACE(point + ":" + file);
      std::map<std::string, std::string> old;
      for (const auto& f : outputs) old[f] = slurp(out / f);
      kill_at_pause(start(args, root / "killed.log", point + ":" + file, notify), notify);
      for (const auto& f : outputs) {
        const std::string now = slurp(out / f);
        EXPECT_TRUE(now == old[f] || complete_table_file(out / f)) << f << " is neither the old file nor a complete new one";
      }
      if (point == "renamed") {
        EXPECT_NE(slurp(out / file), old[file]) << "renamed: the new file is in place";
        EXPECT_TRUE(complete_table_file(out / file));
      } else {
        EXPECT_EQ(slurp(out / file), old[file]) << point << ": the old file is untouched";
        // The killed writer's temporary (proof that it stopped mid-write); older ones of this
        // file, left by earlier kills, were removed when this run began to write it.
        EXPECT_EQ(temporaries(out, file).size(), 1u);
      }
      // Files after the paused one were not touched.
      bool after = false;
      for (const auto& f : outputs) {
        if (after) {
          EXPECT_EQ(slurp(out / f), old[f]) << f << " was written after the kill";
        }
        after = after || f == file;
      }
    }
  }
  // The next run completes and removes what killed runs left behind.
  ASSERT_EQ(run_to_end(args, root / "last.log"), 0) << slurp(root / "last.log");
  for (const auto& f : outputs) EXPECT_TRUE(complete_table_file(out / f)) << f;
  EXPECT_TRUE(temporaries(out).empty()) << temporaries(out).front();
}

// A command line's arguments, split at spaces (the paths of these tests have none).
std::vector<std::string> words(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

// `tables` writes each table as soon as it is measured: killed while writing Table 2, it leaves
// Table 1's JSON and markdown complete, without the Table 1 -> 2 change (Table 2 was not there to
// compare with) and readable by the table model; killed once Table 1 was rewritten with the change,
// both tables are there and agree.
TEST(KillDuringWrite, TablesKeepEachTableTheyFinished) {
  const test::TempDir root_temp("kill_tables_each");
  const fs::path& root = root_temp.path();
  const fs::path out = root / "out";
  // Two small captures of the paper tables' procedural stand-ins (the paper's models may be
  // found beside the checkout, and recording those takes long).
  for (const char* scene : {"atrium", "conference"}) {
    const std::vector<std::string> record =
        words(std::string("record --scene ") + scene + " --gbuffer 96x64 --rsm 64 --out " + (root / scene).string() +
              " --device " + test_device());
    ASSERT_EQ(run_to_end(record, root / "record.log"), 0) << slurp(root / "record.log");
  }
  const std::vector<std::string> args =
      words("tables --quick --capture " + (root / "atrium").string() + " --capture " + (root / "conference").string() +
            " --out " + out.string() +
            " --camera-vsgls 48 --light-vsgls 24 --generators fis_tok15 --repetitions 2 --max-repetitions 2"
            " --copy-mib 1 --no-progress --device " +
            test_device());
  const fs::path notify = root / "paused";
  const auto table = [&](const std::string& name) {
    return table_model_from_json(nlohmann::ordered_json::parse(slurp(out / name)), name);
  };

  kill_at_pause(start(args, root / "killed.log", "partial:table2.json", notify), notify);
  for (const char* f : {"table1.json", "table1.md"}) EXPECT_TRUE(complete_table_file(out / f)) << f;
  EXPECT_FALSE(fs::exists(out / "table2.json"));
  EXPECT_FALSE(fs::exists(out / "table2.md"));
  TableModel t1 = table("table1.json");
  EXPECT_EQ(t1.table, std::optional<int>(1));
  ASSERT_TRUE(t1.ratios.has_value());
  EXPECT_FALSE(t1.ratios->table1_to_table2.has_value()) << "no Table 2 yet to compare with";
  EXPECT_EQ(slurp(out / "table1.md").find("Table 2 / Table 1"), std::string::npos);

  // The second write of table1.json (the rewrite with the change) is in place.
  kill_at_pause(start(args, root / "killed.log", "renamed:table1.json:2", notify), notify);
  for (const char* f : {"table1.json", "table2.json", "table2.md"}) EXPECT_TRUE(complete_table_file(out / f)) << f;
  t1 = table("table1.json");
  EXPECT_EQ(table("table2.json").table, std::optional<int>(2));
  ASSERT_TRUE(t1.ratios.has_value());
  EXPECT_TRUE(t1.ratios->table1_to_table2.has_value());
  EXPECT_EQ(nlohmann::ordered_json::parse(slurp(out / "table1.json"))["ratios"]["table1_to_table2"],
            nlohmann::ordered_json::parse(slurp(out / "table2.json"))["ratios"]["table1_to_table2"]);
  // Its markdown is rewritten after it: still the one without the change.
  EXPECT_EQ(slurp(out / "table1.md").find("Table 2 / Table 1"), std::string::npos);
}

// `sweep` rewrites sweep.json after each point: killed once its second point's file is in place,
// the sweep leaves a sweep.json that conforms to the schema and reads as an incomplete sweep of
// those two points, with fits over them and no markdown yet; killed while writing the complete
// sweep.json, the markdown is there but the file still says "complete": false.
TEST(KillDuringWrite, SweepKeepsThePointsItFinished) {
  const test::TempDir root_temp("kill_sweep");
  const fs::path& root = root_temp.path();
  const fs::path out = root / "out";
  const std::vector<std::string> args = words(
      "sweep --scene tiny --gbuffer 96x64 --rsm 64 --captures " + (root / "captures").string() + " --out " +
      out.string() + " --generators fis_modified --quick --no-progress --axis vsgls=8,16,32 --device " + test_device());
  const fs::path notify = root / "paused";
  std::ifstream schema_in(VSGL_SOURCE_DIR "/results/schema/sweep.schema.json");
  const nlohmann::ordered_json schema = nlohmann::ordered_json::parse(schema_in);

  kill_at_pause(start(args, root / "killed.log", "renamed:sweep.json:2", notify), notify);
  const nlohmann::ordered_json doc = nlohmann::ordered_json::parse(slurp(out / "sweep.json"));
  const auto problems = validate_against_schema(doc, schema);
  EXPECT_TRUE(problems.empty()) << problems.front();
  EXPECT_EQ(doc["complete"], false);
  const SweepModel m = read_sweep_file(out / "sweep.json");
  EXPECT_FALSE(m.complete);
  ASSERT_EQ(m.points.size(), 2u);
  EXPECT_EQ(m.planned_points(), 3u);
  EXPECT_EQ(m.reached_points(), 2u);
  EXPECT_EQ(m.axes[0].values[m.points[1].value_index[0]].text, "16");
  ASSERT_FALSE(m.fits.empty());
  for (const SweepFitModel& f : m.fits) EXPECT_EQ(f.points.size(), 2u);
  EXPECT_FALSE(m.claims.has_value());
  EXPECT_FALSE(fs::exists(out / "sweep.md")) << "the markdown is the complete sweep's";

  // Writes 1-3 follow the points; the 4th is the complete sweep.json, after the markdown and plots.
  kill_at_pause(start(args, root / "killed.log", "complete:sweep.json:4", notify), notify);
  EXPECT_TRUE(fs::exists(out / "sweep.md"));
  EXPECT_TRUE(fs::exists(out / "sweep_vsgls_total.svg"));
  const SweepModel all = read_sweep_file(out / "sweep.json");
  EXPECT_FALSE(all.complete);
  EXPECT_EQ(all.points.size(), 3u);
  EXPECT_EQ(all.reached_points(), 3u);
}

TEST(KillDuringWrite, RecordOutputsAreOldOrNewNeverPartial) {
  const test::TempDir root_temp("kill_record");
  const fs::path& root = root_temp.path();
  const fs::path dir = root / "tiny";
  const std::vector<std::string> args = {"record", "--scene", "tiny", "--gbuffer", "96x64", "--rsm", "64",
                                         "--out", dir.string(), "--device", test_device()};
  ASSERT_EQ(run_to_end(args, root / "first.log"), 0) << slurp(root / "first.log");
  const std::vector<std::string> outputs = {"gbuffer.exr", "rsm.exr", "capture.json"};  // write order
  auto complete = [&](const std::string& f) {
    try {
      if (f == "capture.json") {
        const nlohmann::ordered_json doc = nlohmann::ordered_json::parse(slurp(dir / f));
        return doc.is_object();
      } else {
        (void)read_exr(dir / f);  // reads every pixel: a partial file fails
      }
      return true;
    } catch (const std::exception&) {
      return false;
    }
  };
  const fs::path notify = root / "paused";
  for (const auto& [point, file] : std::vector<std::pair<std::string, std::string>>{
           {"partial", "rsm.exr"}, {"complete", "capture.json"}, {"renamed", "gbuffer.exr"}}) {
    SCOPED_TRACE(point + ":" + file);
    std::map<std::string, std::string> old;
    for (const auto& f : outputs) old[f] = slurp(dir / f);
    kill_at_pause(start(args, root / "killed.log", point + ":" + file, notify), notify);
    for (const auto& f : outputs) EXPECT_TRUE(slurp(dir / f) == old[f] || complete(f)) << f;
    if (point != "renamed") {
      EXPECT_EQ(slurp(dir / file), old[file]);
      EXPECT_EQ(temporaries(dir, file).size(), 1u);
    }
    // Whatever the kill left, the capture loads: recording is deterministic, so the old and the
    // new files are the same capture (and the loader's hashes would refuse a mix of two).
    EXPECT_NO_THROW((void)load_capture(dir));
  }
  ASSERT_EQ(run_to_end(args, root / "last.log"), 0) << slurp(root / "last.log");
  EXPECT_NO_THROW((void)load_capture(dir));
  EXPECT_TRUE(temporaries(dir).empty()) << temporaries(dir).front();
}

}  // namespace
}  // namespace vsgl
