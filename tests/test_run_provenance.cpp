// The provenance a run records: the commit, and whether the measured tree differs from it, both
// fixed at build time by cmake/WriteBuildInfo.cmake (run here on a scratch repository) so that a
// copied binary needs no .git. A run that rewrites committed results (results/<device>/) is not
// "dirty"; an edited source file or an edited input of the tables (results/paper, results/schema)
// is. A tree without .git (a source tarball) is "unknown", saying why.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include <unistd.h>

#include <vulkan/vulkan.h>

#include "bench/cli/program_version.hpp"
#include "harness/core/build_info.hpp"
#include "harness/core/version.hpp"
#include "harness/formats/run_header.hpp"
#include "cli_runner.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

namespace fs = std::filesystem;

struct SourceRevision {
  std::string commit;
  bool dirty = false;
  std::string note;
};

void write(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p) << text;
}

// What cmake/WriteBuildInfo.cmake writes for `tree`: the commit, the dirty flag and the note.
SourceRevision written_revision(const fs::path& tree) {
  const test::TempDir out("build_info");
  const fs::path file = out.path() / "build_info_data.cpp";
  const std::string command = std::string("'") + VSGL_CMAKE_COMMAND + "' -DSOURCE_DIR='" + tree.string() +
                              "' -DOUTPUT='" + file.string() + "' -P '" + VSGL_SOURCE_DIR +
                              "/cmake/WriteBuildInfo.cmake' >/dev/null 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
  std::ifstream in(file);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::smatch commit, dirty, note;
  EXPECT_TRUE(std::regex_search(text, commit, std::regex("kGitCommit = \"([^\"]*)\";"))) << text;
  EXPECT_TRUE(std::regex_search(text, dirty, std::regex("kGitDirty = (true|false);"))) << text;
  EXPECT_TRUE(std::regex_search(text, note, std::regex("kGitNote = \"([^\"]*)\";"))) << text;
  return SourceRevision{commit[1].str(), dirty[1].str() == "true", note[1].str()};
}

class GitTree {
 public:
  GitTree() : temp_("provenance"), dir_(temp_.path()) {
    for (const char* f : {"harness/a.cpp", "results/paper/paper_tables.json", "results/schema/table.schema.json",
                          "results/lavapipe/table1.json"}) {
      write(dir_ / f, "v1\n");
    }
    ok_ = sh("git init -q && git -c user.name=t -c user.email=t@t add -A && "
             "git -c user.name=t -c user.email=t@t commit -qm init");
  }
  bool ok() const { return ok_; }
  const fs::path& dir() const { return dir_; }
  bool sh(const std::string& command) const {
    return std::system(("cd '" + dir_.string() + "' && " + command + " >/dev/null 2>&1").c_str()) == 0;
  }
  void restore() const { sh("git checkout -q -- ."); }

 private:
  test::TempDir temp_;
  fs::path dir_;
  bool ok_ = false;
};

TEST(RunProvenance, RewrittenResultsAreCleanEditedSourcesAndInputsAreDirty) {
#ifdef _WIN32
  GTEST_SKIP() << "cmake/WriteBuildInfo.cmake runs on the build host with its git and CMake: the host's build tests it";
#endif
  if (std::system("git --version >/dev/null 2>&1") != 0) GTEST_SKIP() << "no git on PATH";
  GitTree tree;
  ASSERT_TRUE(tree.ok());
  const SourceRevision clean = written_revision(tree.dir());
  EXPECT_EQ(clean.commit.size(), 40u);
  EXPECT_FALSE(clean.dirty);

  write(tree.dir() / "results/lavapipe/table1.json", "v2\n");  // what a run writes
  EXPECT_FALSE(written_revision(tree.dir()).dirty);
  write(tree.dir() / "harness/a.cpp", "v2\n");  // the measured code
  EXPECT_TRUE(written_revision(tree.dir()).dirty);
  tree.restore();
  for (const char* input : {"results/paper/paper_tables.json", "results/schema/table.schema.json"}) {
    write(tree.dir() / input, "v2\n");
    EXPECT_TRUE(written_revision(tree.dir()).dirty) << input;
    tree.restore();
  }
  EXPECT_FALSE(written_revision(tree.dir()).dirty);
  EXPECT_EQ(written_revision(tree.dir()).note, "");
}

TEST(RunProvenance, ATreeWithoutGitIsUnknownAndSaysWhy) {
#ifdef _WIN32
  GTEST_SKIP() << "cmake/WriteBuildInfo.cmake runs on the build host with its git and CMake: the host's build tests it";
#endif
  const test::TempDir tree("tarball");
  write(tree.path() / "harness/a.cpp", "v1\n");
  const SourceRevision rev = written_revision(tree.path());
  EXPECT_EQ(rev.commit, "unknown");
  EXPECT_FALSE(rev.dirty);
  EXPECT_NE(rev.note.find("not a git checkout"), std::string::npos) << rev.note;
}

// What the runs write is what the build fixed: no git is asked at run time.
TEST(RunProvenance, TheJsonAndVersionNameTheBuildsCommitAndCompiler) {
  const BuildInfo b = build_info();
  const BuildRecord record = this_build();
  EXPECT_EQ(record.git_commit, b.git_commit);
  EXPECT_EQ(record.git_dirty, b.git_dirty);
  EXPECT_EQ(record.compiler, compiler_description());
  EXPECT_EQ(record.vsgl_bench_version, kVersionString);
  EXPECT_FALSE(b.git_commit.empty());
  if (b.git_commit == "unknown") {
    EXPECT_FALSE(b.git_note.empty());
  }
  const std::string v = version_text("vsgl-bench");
  EXPECT_NE(v.find("commit " + b.git_commit), std::string::npos) << v;
  EXPECT_NE(v.find("compiler " + compiler_description()), std::string::npos) << v;
}

// `vsgl-bench --version`, without a device: the version, the build's commit, the compiler, the
// Vulkan headers it was compiled against and the licence, one a line.
TEST(VersionUsage, VersionNamesTheCommitCompilerVulkanHeadersAndLicence) {
  const auto r = test::run_cli_without_vulkan("--version");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("vsgl-bench " + std::string(kVersionString) + "\n"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("\ncommit " + build_info().git_commit), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("\ncompiler " + compiler_description() + "\n"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("\nVulkan headers " + cli::vulkan_header_version() + "\n"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("\nlicence Apache-2.0 "), std::string::npos) << r.output;
}

// The Vulkan header version is the one this file was compiled against, as "major.minor.patch".
TEST(VersionUsage, VulkanHeaderVersionIsTheIncludedHeaders) {
  EXPECT_EQ(cli::vulkan_header_version(), std::to_string(VK_API_VERSION_MAJOR(VK_HEADER_VERSION_COMPLETE)) + "." +
                                              std::to_string(VK_API_VERSION_MINOR(VK_HEADER_VERSION_COMPLETE)) + "." +
                                              std::to_string(VK_HEADER_VERSION));
}

}  // namespace
}  // namespace vsgl
