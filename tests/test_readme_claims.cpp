// The README's table of the paper's claims states verdicts; this test reads each one from the
// committed results it cites, so the table can never say what the files do not. A row is
//   | `KEY` | what | VERDICTS (paper scenes) | VERDICTS (Sibenik) | VERDICTS (stand-ins) |
// where KEY is a table claim id (tableN.json /claims/*/id), "quality: MEASURE" (the start of a
// quality.json claim's measure; a Fig. 7 claim of a run without visibility reads "not measured
// (--visibility none)") or "sweep: ID" (a claim of sweep/pdf-sharpness_<scene>/sweep.json),
// and a VERDICTS cell begins with one verdict per table or scene:
//   "T1 holds, T2 inconclusive" / "sponza holds, conference-room no clear difference (within 0.02)";
// "not run" for a sweep a column has no file of; "not a table scene" for a timing claim in the
// Sibenik column (the paper's Fig. 5 lower-row scene has no table).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "harness/core/json_reader.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

namespace fs = std::filesystem;
using ojson = nlohmann::ordered_json;
using test::kSource;

struct ClaimColumn {
  fs::path dir;                     // results/lavapipe or results/lavapipe/stand-ins
  std::vector<std::string> scenes;  // quality/<scene>
  bool tables;                      // the column's scenes are Tables 1 and 2
  const char* name;
};

std::vector<std::string> cells_of(const std::string& row) {
  std::vector<std::string> cells;
  std::stringstream in(row);
  std::string cell;
  std::getline(in, cell, '|');  // before the first bar
  while (std::getline(in, cell, '|')) {
    const auto a = cell.find_first_not_of(' '), b = cell.find_last_not_of(' ');
    cells.push_back(a == std::string::npos ? "" : cell.substr(a, b - a + 1));
  }
  if (!cells.empty() && cells.back().empty()) cells.pop_back();
  return cells;
}

std::string table_verdict(const fs::path& dir, int table, const std::string& id) {
  const ojson doc = read_json_file(dir / ("table" + std::to_string(table) + ".json"), "the table");
  for (const ojson& c : doc.at("claims"))
    if (c.at("id") == id)
      return c.at("holds").is_null() ? "inconclusive" : c.at("holds").get<bool>() ? "holds" : "does not hold";
  ADD_FAILURE() << dir << ": table " << table << " has no claim " << id;
  return "?";
}

std::string sweep_verdict(const fs::path& file, const std::string& id) {
  const ojson doc = read_json_file(file, "the sweep");
  for (const ojson& c : doc.value("claims", ojson::array()))
    if (c.at("id") == id)
      return c.at("holds").is_null() ? "inconclusive" : c.at("holds").get<bool>() ? "holds" : "does not hold";
  ADD_FAILURE() << file << " has no claim " << id;
  return "?";
}

std::string quality_verdict(const fs::path& dir, const std::string& scene, const std::string& measure) {
  const ojson doc = read_json_file(dir / "quality" / scene / "quality.json", "the quality report");
  std::string found;
  int matches = 0;
  for (const ojson& c : doc.at("claims"))
    if (c.at("measure").get<std::string>().rfind(measure, 0) == 0) {
      found = c.at("verdict").get<std::string>();
      ++matches;
    }
  // Fig. 7 is measured only with visibility (DESIGN.md §11a.2): a run without it has no such claim.
  const ojson config = doc.value("config", ojson::object());
  if (matches == 0 && measure.rfind("Fig. 7 ", 0) == 0 && config.value("visibility", "none") == "none")
    return "not measured (--visibility none)";
  EXPECT_EQ(matches, 1) << dir << "/quality/" << scene << ": claims whose measure starts with '" << measure << "'";
  return found;
}

TEST(ReadmeClaims, EveryVerdictIsTheCommittedResults) {
  std::ifstream in(kSource / "README.md");
  ASSERT_TRUE(in) << "README.md";
  const ClaimColumn columns[] = {{kSource / "results/lavapipe", {"sponza", "conference-room"}, true, "paper scenes"},
                                 {kSource / "results/lavapipe", {"sibenik"}, false, "Sibenik"},
                                 {kSource / "results/lavapipe/stand-ins", {"atrium", "conference"}, true, "stand-ins"}};
  constexpr int kColumns = static_cast<int>(std::size(columns));
  const std::regex key_cell("^`([^`]+)`$");
  bool inside = false;
  int rows = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.find("<!-- claims:begin -->") != std::string::npos) inside = true;
    if (line.find("<!-- claims:end -->") != std::string::npos) inside = false;
    std::smatch m;
    const std::vector<std::string> cells = cells_of(line);
    if (!inside || cells.size() != 2 + kColumns || !std::regex_match(cells[0], m, key_cell)) continue;
    const std::string key = m[1];
    SCOPED_TRACE(key);
    ++rows;
    for (int c = 0; c < kColumns; ++c) {
      std::string expected;
      if (key.rfind("sweep: ", 0) == 0) {
        for (const std::string& scene : columns[c].scenes) {
          const fs::path file = columns[c].dir / "sweep" / ("pdf-sharpness_" + scene) / "sweep.json";
          if (!fs::exists(file)) continue;
          expected += (expected.empty() ? "" : ", ") + scene + " " + sweep_verdict(file, key.substr(7));
        }
        if (expected.empty()) expected = "not run";
      } else if (key.rfind("quality: ", 0) == 0) {
        for (const std::string& scene : columns[c].scenes)
          expected +=
              (expected.empty() ? "" : ", ") + scene + " " + quality_verdict(columns[c].dir, scene, key.substr(9));
      } else if (!columns[c].tables) {
        expected = "not a table scene";
      } else {
        expected = "T1 " + table_verdict(columns[c].dir, 1, key) + ", T2 " + table_verdict(columns[c].dir, 2, key);
      }
      EXPECT_EQ(cells[2 + c].substr(0, expected.size()), expected) << "README column " << columns[c].name;
    }
  }
  EXPECT_GE(rows, 8) << "the README's claims table (between <!-- claims:begin --> and <!-- claims:end -->)";
}

}  // namespace
}  // namespace vsgl
