// The harness's folders are layers (harness/CMakeLists.txt, cmake/Layers.cmake): a file may
// include its own folder and the folders its layer USES, never one above it or beside it, never
// another folder's detail/, and only tests/ and bench/ may include a testing/ folder. The layer
// table is the one CMake built the libraries from, so the check and the link lines cannot drift.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>
#include "test_support.hpp"

namespace {

namespace fs = std::filesystem;
using LayerTable = std::map<std::string, std::set<std::string>>;

LayerTable parse_layer_table(std::istream& in) {
  LayerTable table;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const auto colon = line.find(':');
    if (colon == std::string::npos) continue;
    std::set<std::string>& uses = table[line.substr(0, colon)];
    std::istringstream rest(line.substr(colon + 1));
    for (std::string dep; rest >> dep;) uses.insert(dep);
  }
  return table;
}

// `#include "harness/<folder>/<rest>"` lines of one file that break the rules, as
// "path:line: reason". `from_folder` is the including file's layer ("" for tests/ and bench/).
std::vector<std::string> violations_in(const fs::path& file, const std::string& shown, const std::string& from_folder,
                                       const LayerTable& table) {
  static const std::regex include_re(R"re(^\s*#\s*include\s+"harness/([^/"]+)/([^"]*)")re");
  std::vector<std::string> out;
  std::ifstream in(file);
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    std::smatch m;
    if (!std::regex_search(line, m, include_re)) continue;
    const std::string target = m[1].str(), rest = m[2].str();
    const std::string where = shown + ":" + std::to_string(number) + ": ";
    if (!table.contains(target)) {
      out.push_back(where + "includes harness/" + target + "/, which is not a layer");
      continue;
    }
    const bool own = target == from_folder;
    if (!from_folder.empty() && !own && !table.at(from_folder).contains(target))
      out.push_back(where + "layer '" + from_folder + "' includes '" + target + "', which it does not use (up or sideways)");
    if (!own && (rest.starts_with("detail/") || rest.find("/detail/") != std::string::npos))
      out.push_back(where + "includes the detail/ of layer '" + target + "'");
    if (!from_folder.empty() && (rest.starts_with("testing/") || rest.find("/testing/") != std::string::npos) &&
        shown.find("/testing/") == std::string::npos)
      out.push_back(where + "library code includes a testing/ folder (only tests/ and bench/ may)");
  }
  return out;
}

// Every violation in a source tree laid out like this one (harness/, bench/, tests/).
std::vector<std::string> layering_violations(const fs::path& root, const LayerTable& table) {
  std::vector<std::string> out;
  for (const char* top : {"harness", "bench", "tests"}) {
    if (!fs::exists(root / top)) continue;
    for (const auto& entry : fs::recursive_directory_iterator(root / top)) {
      const auto ext = entry.path().extension();
      if (!entry.is_regular_file() || (ext != ".hpp" && ext != ".cpp" && ext != ".h")) continue;
      const fs::path rel = fs::relative(entry.path(), root);
      std::string folder;
      if (std::string(top) == "harness") {
        auto it = rel.begin();
        ++it;
        if (it == rel.end() || std::next(it) == rel.end()) {
          out.push_back(rel.string() + ": a source file directly in harness/, outside every layer");
          continue;
        }
        folder = it->string();
        if (!table.contains(folder)) {
          out.push_back(rel.string() + ": folder harness/" + folder + "/ is not a layer of harness/CMakeLists.txt");
          continue;
        }
      }
      const auto v = violations_in(entry.path(), rel.string(), folder, table);
      out.insert(out.end(), v.begin(), v.end());
    }
  }
  return out;
}

std::string joined_lines(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines) s += "  " + l + "\n";
  return s;
}

// The layer table CMake wrote: VSGL_LAYERS_FILE from the environment when set (it must exist),
// else where this build wrote it, else beside a test binary that travelled without its build
// folder (ci/device-pack.sh packs the table with the tests). Empty when none is there.
fs::path layer_table_file() {
  if (const char* env = std::getenv("VSGL_LAYERS_FILE"); env != nullptr && *env != '\0') return env;
  std::error_code ec;
  if (fs::exists(VSGL_LAYERS_FILE, ec)) return VSGL_LAYERS_FILE;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  for (const fs::path& p :
       {exe.parent_path() / "harness_layers.txt", exe.parent_path().parent_path() / "harness_layers.txt"})
    if (!ec && fs::exists(p, ec)) return p;
  return {};
}

TEST(Layering, NoIncludePointsUpTheLayers) {
  const fs::path file = layer_table_file();
  if (file.empty())
    GTEST_SKIP() << "no layer table: not at " << VSGL_LAYERS_FILE
                 << " (where the build wrote it), not beside the test binary, and VSGL_LAYERS_FILE is not set";
  std::ifstream in(file);
  ASSERT_TRUE(in) << "cannot read the layer table " << file;
  const LayerTable table = parse_layer_table(in);
  ASSERT_GE(table.size(), 8u);
  const auto v = layering_violations(VSGL_SOURCE_DIR, table);
  EXPECT_TRUE(v.empty()) << v.size() << " include(s) break the layering:\n" << joined_lines(v);
}

// The check itself can fail: a tree with one include of each forbidden kind.
TEST(Layering, FlagsUpwardSidewaysDetailAndTestingIncludes) {
  const vsgl::test::TempDir root_temp("layering");
  const std::filesystem::path& root = root_temp.path();
  const auto write = [&](const std::string& rel, const std::string& text) {
    fs::create_directories((root / rel).parent_path());
    std::ofstream(root / rel) << text;
  };
  std::istringstream spec("core:\nvk: core\nmath: core\ngenerators: core vk math\n");
  const LayerTable table = parse_layer_table(spec);
  write("harness/core/ok.hpp", "#include <vector>\n");
  write("harness/vk/fine.cpp", "#include \"harness/core/ok.hpp\"\n#include \"harness/vk/fine.hpp\"\n");
  write("harness/core/up.cpp", "#include \"harness/vk/fine.hpp\"\n");                 // up
  write("harness/math/side.cpp", "#include \"harness/vk/fine.hpp\"\n");               // sideways
  write("harness/generators/deep.cpp", "#include \"harness/vk/detail/x.hpp\"\n");     // detail/
  write("harness/generators/prod.cpp", "#include \"harness/generators/testing/t.hpp\"\n");  // testing/
  write("harness/generators/testing/t.cpp", "#include \"harness/generators/testing/t.hpp\"\n");
  write("tests/t.cpp", "#include \"harness/generators/testing/t.hpp\"\n#include \"harness/vk/fine.hpp\"\n");
  write("harness/stray.cpp", "\n");
  const auto v = layering_violations(root, table);
  ASSERT_EQ(v.size(), 5u) << joined_lines(v);
  const std::string all = joined_lines(v);
  EXPECT_NE(all.find("harness/core/up.cpp:1: layer 'core' includes 'vk'"), std::string::npos) << all;
  EXPECT_NE(all.find("harness/math/side.cpp:1: layer 'math' includes 'vk'"), std::string::npos) << all;
  EXPECT_NE(all.find("includes the detail/ of layer 'vk'"), std::string::npos) << all;
  EXPECT_NE(all.find("harness/generators/prod.cpp:1: library code includes a testing/ folder"), std::string::npos) << all;
  EXPECT_NE(all.find("harness/stray.cpp: a source file directly in harness/"), std::string::npos) << all;
}

}  // namespace
