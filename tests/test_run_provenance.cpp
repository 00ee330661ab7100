// The provenance a run records: the commit, and whether the measured tree differs from it. A run
// that rewrites committed results (results/<device>/) is not "dirty"; an edited source file or
// an edited input of the tables (results/paper, results/schema) is.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "harness/timing/run_provenance.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p) << text;
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
  if (std::system("git --version >/dev/null 2>&1") != 0) GTEST_SKIP() << "no git on PATH";
  GitTree tree;
  ASSERT_TRUE(tree.ok());
  const SourceRevision clean = source_revision(tree.dir());
  EXPECT_EQ(clean.commit.size(), 40u);
  EXPECT_FALSE(clean.dirty);

  write(tree.dir() / "results/lavapipe/table1.json", "v2\n");  // what a run writes
  EXPECT_FALSE(source_revision(tree.dir()).dirty);
  write(tree.dir() / "harness/a.cpp", "v2\n");  // the measured code
  EXPECT_TRUE(source_revision(tree.dir()).dirty);
  tree.restore();
  for (const char* input : {"results/paper/paper_tables.json", "results/schema/table.schema.json"}) {
    write(tree.dir() / input, "v2\n");
    EXPECT_TRUE(source_revision(tree.dir()).dirty) << input;
    tree.restore();
  }
  EXPECT_FALSE(source_revision(tree.dir()).dirty);
}

}  // namespace
}  // namespace vsgl
