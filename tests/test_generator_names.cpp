// Generator ids are spelled once, in harness/core/generator_ids.hpp, and everything else reads
// them there or from the descriptors (DESIGN.md §6): no file of the library, the programs or the
// kernels holds one as a string literal, so a renamed generator cannot leave a stale copy behind.
// No device.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>
#include <vector>

#include "harness/generators/generator_registry.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

using test::kSource;

TEST(GeneratorNames, NoSourceFileOutsideTheIdsSpellsAGeneratorIdAsALiteral) {
  std::string ids;
  for (const std::string& name : generator_names()) ids += (ids.empty() ? "" : "|") + name;
  ASSERT_FALSE(ids.empty());
  // A literal that is an id, or starts one of the stable names ("fis_modified/light_view").
  const std::regex quoted("\"(" + ids + ")[\"/]");
  std::vector<std::string> found;
  std::size_t files = 0;
  for (const char* top : {"harness", "bench", "kernels"})
    for (const auto& entry : std::filesystem::recursive_directory_iterator(kSource / top)) {
      const std::string ext = entry.path().extension().string();
      if (!entry.is_regular_file() || (ext != ".cpp" && ext != ".hpp" && ext != ".comp" && ext != ".glsl")) continue;
      const std::filesystem::path relative = std::filesystem::relative(entry.path(), kSource);
      if (relative == "harness/core/generator_ids.hpp") continue;
      ++files;
      std::ifstream in(entry.path());
      std::string line;
      for (int number = 1; std::getline(in, line); ++number)
        if (std::regex_search(line, quoted))
          found.push_back(relative.string() + ":" + std::to_string(number) + ": " + line);
    }
  EXPECT_GT(files, 100u);  // the walk saw the tree
  EXPECT_TRUE(found.empty()) << "generator ids spelled outside harness/core/generator_ids.hpp:\n"
                             << [&] {
                                  std::string all;
                                  for (const std::string& f : found) all += f + "\n";
                                  return all;
                                }();
}

}  // namespace
}  // namespace vsgl
