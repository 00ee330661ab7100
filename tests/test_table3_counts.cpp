// Table 3 counted as the paper counted (DESIGN.md §10): the region markers of
// harness/core/source_lines.hpp (nested, alternatives, unbalanced, unknown, malformed), the line
// diff of harness/core/line_diff.hpp, the real generators' counts (the FIS variants differ by a
// few lines, the default path leaves the other paths' regions out) and the per-iteration split of
// the k-means dispatches, and the sources built into the program (what `tables` counts) being
// exactly the checkout's files that some config counts. The split on recorded commands:
// tests/test_timing_runner.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>
#include <string>

#include "test_support.hpp"
#include "harness/core/embedded_files.hpp"
#include "harness/core/error.hpp"
#include "harness/core/line_diff.hpp"
#include "harness/core/source_lines.hpp"
#include "harness/generators/generator_registry.hpp"
#include "harness/report/measured_table.hpp"
#include "harness/vk/command_stream.hpp"

namespace vsgl {
namespace {

namespace fs = std::filesystem;

const std::map<std::string, bool> kRegions{{"a", true}, {"b", false}, {"c", true}};

std::vector<std::string> lines_of(const std::string& text) { return counted_code_lines(text, "x.cpp", kRegions); }

std::string counting_error(const std::string& text) {
  try {
    lines_of(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

bool has_line(const std::vector<std::string>& lines, const std::string& needle) {
  return std::any_of(lines.begin(), lines.end(),
                     [&](const std::string& l) { return l.find(needle) != std::string::npos; });
}

TEST(Table3Markers, RegionsCountOnlyWhenEveryEnclosingOneIsCounted) {
  const std::string text =
      "int shared;\n"
      "// table3: begin a\n"
      "int in_a;\n"
      "  // table3: begin b\n"
      "int in_a_b;\n"
      "  // table3: begin c\n"
      "int in_a_b_c;\n"
      "  // table3: end c\n"
      "  // table3: end b\n"
      "  // table3: begin c\n"
      "int in_a_c;   // trailing comment\n"
      "  // table3: end c\n"
      "// table3: end a\n"
      "// table3: begin b\n"
      "int in_b;\n"
      "// table3: end b\n"
      "// table3: begin b|c\n"
      "int in_b_or_c;\n"
      "// table3: end b|c\n"
      "int   last ;\n";
  EXPECT_EQ(lines_of(text),
            (std::vector<std::string>{"int shared;", "int in_a;", "int in_a_c;", "int in_b_or_c;", "int last ;"}));
  // The markers are comments: a file of markers only counts nothing, and count_code_lines (no
  // regions) sees them as comments too.
  EXPECT_TRUE(lines_of("// table3: begin a\n// table3: end a\n").empty());
  EXPECT_EQ(count_code_lines(text), 8u);
  // GLSL shares the syntax; a marker inside a block comment is no marker.
  EXPECT_EQ(lines_of("/*\n// table3: begin b\n*/\nfloat x;\n"), std::vector<std::string>{"float x;"});
}

// A checkout with CRLF line ends (git's autocrlf on Windows) counts exactly as the LF one, its
// markers included; a lone '\r' inside a line stays whitespace.
TEST(Table3Markers, CrlfLineEndsCountAsLf) {
  const std::string lf =
      "int shared; // why\n// table3: begin b\nint in_b;\n// table3: end b\n/* a\n b */ int after;\n"
      "// table3: begin a\nint in_a;\n// table3: end a\n";
  std::string crlf;
  for (char c : lf) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  EXPECT_EQ(lines_of(crlf), lines_of(lf));
  EXPECT_EQ(lines_of(crlf), (std::vector<std::string>{"int shared;", "int after;", "int in_a;"}));
  EXPECT_EQ(count_code_lines(crlf), count_code_lines(lf));
  EXPECT_EQ(lines_of("int\rx;\r\n"), std::vector<std::string>{"int x;"});
}

TEST(Table3Markers, UnbalancedUnknownAndMalformedMarkersAreErrors) {
  EXPECT_NE(counting_error("// table3: end a\n").find("x.cpp:1: `// table3: end a` without a matching begin"),
            std::string::npos)
      << counting_error("// table3: end a\n");
  const std::string crossed =
      counting_error("// table3: begin a\n// table3: begin c\n// table3: end a\n// table3: end c\n");
  EXPECT_NE(crossed.find("x.cpp:3:"), std::string::npos) << crossed;
  EXPECT_NE(crossed.find("closes region 'c' begun on line 2"), std::string::npos) << crossed;
  const std::string unclosed = counting_error("int a;\n// table3: begin a\nint b;\n");
  EXPECT_NE(unclosed.find("x.cpp:2: Table 3 region 'a' is never ended"), std::string::npos) << unclosed;
  const std::string unknown = counting_error("// table3: begin a|zz\n// table3: end a|zz\n");
  EXPECT_NE(unknown.find("unknown Table 3 region 'zz'"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("a, b, c"), std::string::npos) << unknown;  // names what it knows
  for (const char* bad :
       {"// table3: start a\n", "// table3: begin\n", "// table3: begin A\n", "// table3: begin a b\n", "// table3:\n"})
    EXPECT_NE(counting_error(bad).find("malformed Table 3 marker"), std::string::npos) << bad << counting_error(bad);
  // A file that names no region needs none; one that does must be given its names.
  EXPECT_THROW(counted_code_lines("// table3: begin a\n// table3: end a\n", "y.glsl", {}), InputError);
}

TEST(Table3Markers, GeneratorLinesSplitHostAndShaderAndSkipIncludesOfExcludedRegions) {
  const test::TempDir temp("table3_regions");
  const fs::path& root = temp.path();
  fs::create_directories(root / "kernels/include");
  // Binary: lines end in "\n" as in the checkout, on Windows too (text mode would write "\r\n").
  const auto write = [](const fs::path& file) { return std::ofstream(file, std::ios::binary); };
  write(root / "host.cpp") << "int f();\n// table3: begin b\nint g();\n// table3: end b\n";
  write(root / "kernels/k.comp") << "#version 450\n// table3: begin b\n#include \"unused.glsl\"\n// table3: end b\n"
                                 << "#include \"used.glsl\"\nvoid main() {}\n";
  write(root / "kernels/include/used.glsl") << "float u;\n";
  // unused.glsl does not exist: an excluded #include is never read.
  const GeneratorLines lines = count_generator_lines(SourceSet{{"host.cpp"}, {"kernels/k.comp"}, kRegions}, root);
  EXPECT_EQ(lines.host, 1u);
  EXPECT_EQ(lines.shader, 3u + 1u);
  EXPECT_EQ(lines.total, 5u);
  ASSERT_EQ(lines.files.size(), 3u);
  EXPECT_FALSE(lines.files[0].shader);
  EXPECT_TRUE(lines.files[2].shader);
  EXPECT_EQ(lines.code.size(), lines.total);
  SourceSet counted_b{{"host.cpp"}, {"kernels/k.comp"}, kRegions};
  counted_b.regions["b"] = true;
  EXPECT_THROW(count_generator_lines(counted_b, root), InputError);  // now unused.glsl is needed, and missing
}

TEST(Table3Diff, CountsLinesOutsideTheLongestCommonSubsequence) {
  EXPECT_EQ(diff_lines({}, {}).differing(), 0u);
  const LineDiff same = diff_lines({"a", "b"}, {"a", "b"});
  EXPECT_EQ(same.removed + same.added, 0u);
  const LineDiff d = diff_lines({"a", "x", "b", "c"}, {"a", "b", "y", "z", "c"});
  EXPECT_EQ(d.removed, 1u);  // x
  EXPECT_EQ(d.added, 2u);    // y, z
  EXPECT_EQ(d.differing(), 3u);
  const LineDiff moved = diff_lines({"a", "b"}, {"b", "a"});  // order matters, unlike a multiset
  EXPECT_EQ(moved.differing(), 2u);
}

TEST(Table3Counts, FisVariantsDifferByAFewLinesOfTheModifiedLevelChoice) {
  const GeneratorLines tok15 = count_generator_lines(generator_sources("fis_tok15"), VSGL_SOURCE_DIR);
  const GeneratorLines modified = count_generator_lines(generator_sources("fis_modified"), VSGL_SOURCE_DIR);
  EXPECT_GT(modified.total, tok15.total);  // the paper: 232 vs 222
  EXPECT_EQ(modified.host + modified.shader, modified.total);
  EXPECT_EQ(modified.code.size(), modified.total);
  const LineDiff d = diff_lines(tok15.code, modified.code);
  EXPECT_GT(d.added, 0u);
  EXPECT_GT(d.removed, 0u);
  EXPECT_LE(d.differing(), 40u) << "the variants share everything but choose_level() and estimate_power()";
  EXPECT_TRUE(has_line(modified.code, "BISECTION_ITERATIONS"));
  EXPECT_FALSE(has_line(tok15.code, "BISECTION_ITERATIONS"));
  EXPECT_TRUE(has_line(tok15.code, "max(N * s.pdf, pc.K)"));  // Eq. 4
  EXPECT_FALSE(has_line(modified.code, "max(N * s.pdf, pc.K)"));
  // k-means needs more shaders and more lines (the paper: about five times the lines; how many
  // times here is claim 6 of the tables, not a property of the counter).
  const GeneratorLines kmeans = count_generator_lines(generator_sources("kmeans_2d"), VSGL_SOURCE_DIR);
  EXPECT_GT(kmeans.total, modified.total);
  EXPECT_GT(kmeans.shader, modified.shader);
  EXPECT_GT(generator_sources("kmeans_2d").kernels.size(), generator_sources("fis_modified").kernels.size());
}

// The lines of every host file, whole (what Table 3 counted before the regions).
uint32_t whole_host_lines(const SourceSet& s) {
  uint32_t n = 0;
  for (const auto& rel : s.host) {
    std::ifstream in(fs::path(VSGL_SOURCE_DIR) / rel);
    n += count_code_lines(std::string(std::istreambuf_iterator<char>(in), {}));
  }
  return n;
}

TEST(Table3Counts, DefaultPathLeavesTheOtherPathsRegionsOut) {
  GeneratorConfig blit;
  blit.mipmapping = MipStrategy::kBlit;
  GeneratorConfig buffer;
  buffer.pyramid = PyramidPath::kBuffer;
  const GeneratorLines by_default = count_generator_lines(generator_sources("fis_modified"), VSGL_SOURCE_DIR);
  const GeneratorLines by_blit = count_generator_lines(generator_sources("fis_modified", blit), VSGL_SOURCE_DIR);
  const GeneratorLines by_buffer = count_generator_lines(generator_sources("fis_modified", buffer), VSGL_SOURCE_DIR);
  // The default (texture path, single-pass downsampler) has no blit chain, no buffer pyramid and
  // no verify readback; each of the others has its own and not the default's.
  EXPECT_TRUE(has_line(by_default.code, "spd_tail_"));
  EXPECT_FALSE(has_line(by_default.code, "vkCmdBlitImage("));
  EXPECT_FALSE(has_line(by_default.code, "\"fis_mip_level.comp\""));
  EXPECT_FALSE(has_line(by_default.code, "download_pyramid"));
  EXPECT_TRUE(has_line(by_blit.code, "vkCmdBlitImage("));
  EXPECT_FALSE(has_line(by_blit.code, "spd_tail_"));
  EXPECT_TRUE(has_line(by_buffer.code, "\"fis_mip_level.comp\""));
  EXPECT_FALSE(has_line(by_buffer.code, "sampler_"));
  EXPECT_FALSE(has_line(by_buffer.code, "vkCmdBlitImage("));
  const uint32_t whole = whole_host_lines(generator_sources("fis_modified"));
  for (const GeneratorLines* l : {&by_default, &by_blit, &by_buffer}) EXPECT_LT(l->host, whole);
  // The sum passes of k-means likewise.
  const GeneratorLines sequential = count_generator_lines(generator_sources("kmeans_3d"), VSGL_SOURCE_DIR);
  const GeneratorLines segmented = count_generator_lines(generator_sources("kmeans_3d_segsum"), VSGL_SOURCE_DIR);
  EXPECT_FALSE(has_line(sequential.code, "segsum_pieces_"));
  EXPECT_TRUE(has_line(segmented.code, "segsum_pieces_"));
  EXPECT_FALSE(has_line(segmented.code, "*sum_set_"));
  // Every generator under every config reads its markers without error.
  for (const auto& g : generator_names())
    for (const GeneratorConfig* c : {&blit, &buffer})
      EXPECT_GT(count_generator_lines(generator_sources(g, *c), VSGL_SOURCE_DIR).total, 100u) << g;
}

// `tables` counts the files built in (core/embedded_files.hpp), so that a copied binary needs no
// checkout: under every config each generator's count from them equals the checkout's, line for
// line (a stale build fails here), and the files built in for Table 3 (harness/CMakeLists.txt,
// VSGL_TABLE3_FILES) are exactly those some config counts, none missing and none extra.
TEST(Table3Counts, TheBuiltInSourcesAreExactlyTheCountedCheckoutFiles) {
  std::vector<GeneratorConfig> configs;
  for (const PyramidPath path : {PyramidPath::kTexture, PyramidPath::kBuffer})
    for (const MipStrategy mip : {MipStrategy::kSinglePass, MipStrategy::kPerLevel, MipStrategy::kBlit}) {
      GeneratorConfig c;
      c.pyramid = path;
      c.mipmapping = mip;
      configs.push_back(c);
    }
  const SourceTree built_in = built_in_source_tree();
  std::set<std::string> counted;
  for (const auto& g : generator_names())
    for (const GeneratorConfig& c : configs) {
      const GeneratorLines checkout = count_generator_lines(generator_sources(g, c), VSGL_SOURCE_DIR);
      const GeneratorLines embedded = count_generator_lines(generator_sources(g, c), built_in);
      EXPECT_EQ(embedded.total, checkout.total) << g << ": rebuild to embed the edited sources";
      EXPECT_EQ(embedded.host, checkout.host) << g;
      EXPECT_EQ(embedded.shader, checkout.shader) << g;
      EXPECT_EQ(embedded.code, checkout.code) << g;
      for (const CountedFile& f : checkout.files) counted.insert(f.path);
    }
  std::set<std::string> embedded;
  for (const char* under : {"harness/", "kernels/"})
    for (const std::string& name : embedded_file_names(under))
      if (name.rfind("harness/scene/presets/", 0) != 0) embedded.insert(name);
  for (const std::string& f : counted)
    EXPECT_TRUE(embedded.count(f)) << f << " is counted but not in VSGL_TABLE3_FILES";
  for (const std::string& f : embedded)
    EXPECT_TRUE(counted.count(f)) << f << " is in VSGL_TABLE3_FILES but never counted";
  // A file that was not built in is an InputError that names it, not a zero.
  SourceSet missing = generator_sources("fis_modified");
  missing.host.push_back("harness/generators/no_such_file.cpp");
  try {
    (void)count_generator_lines(missing, built_in);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no_such_file.cpp (built in)"), std::string::npos) << e.what();
  }
}

TEST(Table3Dispatches, IterationsTimesPerIterationPlusOutsideIsTheTotal) {
  CaseTiming c;
  c.generator = "kmeans_2d";
  c.view = "camera_view";
  c.iteration_dispatches = {61, 61, 61, 61};
  c.dispatch_count = 4 * 61 + 25;
  const IterationDispatches d = iteration_dispatches(c);
  EXPECT_EQ(d.iterations, 4u);
  EXPECT_EQ(d.per_iteration, 61u);
  EXPECT_EQ(d.outside, 25u);
  EXPECT_EQ(d.iterations * d.per_iteration + d.outside, c.dispatch_count);
  c.iteration_dispatches = {};  // no iterations: everything is outside
  EXPECT_EQ(iteration_dispatches(c).outside, c.dispatch_count);
  EXPECT_EQ(iteration_dispatches(c).per_iteration, 0u);
  c.iteration_dispatches = {61, 60};
  EXPECT_THROW(iteration_dispatches(c), std::logic_error);
  c.iteration_dispatches = {1000};
  EXPECT_THROW(iteration_dispatches(c), std::logic_error);
}

TEST(Table3Dispatches, CommandStreamIterationsMustBeBalanced) {
  CommandStream stream(VK_NULL_HANDLE);  // nothing is recorded: only the bookkeeping is exercised
  EXPECT_THROW(stream.end_iteration(), std::logic_error);
  stream.begin_iteration();
  EXPECT_THROW(stream.begin_iteration(), std::logic_error);
  stream.end_iteration();
  EXPECT_EQ(stream.iteration_dispatches(), std::vector<uint32_t>{0u});
}

}  // namespace
}  // namespace vsgl
