// The operating-system layer of harness/core (platform_*; DESIGN.md §13). The same calls carry
// the Windows build, where ci/windows-test.sh exercises them through vsgl-bench.exe.
#include <gtest/gtest.h>

#ifndef _WIN32
#include <sys/wait.h>
#endif
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include "harness/core/platform_arguments.hpp"
#include "harness/core/platform_console.hpp"
#include "harness/core/platform_file.hpp"
#include "harness/core/platform_path.hpp"
#include "harness/core/platform_process.hpp"
#include "child_process.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("vsgl_platform_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(Platform, ARunningProcessIsNotGoneAnEndedOneIs) {
  EXPECT_EQ(current_process_id(), static_cast<std::uint64_t>(::getpid()));
  EXPECT_FALSE(process_is_gone(current_process_id()));
  test::ChildProcess running = test::ChildProcess::start_idle();
  ASSERT_NE(running.id(), 0u);
  EXPECT_FALSE(process_is_gone(running.id()));
  ASSERT_TRUE(running.kill_and_wait());
  EXPECT_TRUE(process_is_gone(test::ended_process_id()));
#ifndef _WIN32
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) ::_exit(0);
  EXPECT_FALSE(process_is_gone(static_cast<std::uint64_t>(child)));  // a zombie until reaped
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_TRUE(process_is_gone(static_cast<std::uint64_t>(child)));
#endif
}

TEST(Platform, NewFileIsExclusiveAndReplaceFileReplacesTheTarget) {
  const fs::path dir = fresh_dir("file");
  const fs::path temporary = dir / "new.tmp", target = dir / "target.json";
  std::ofstream(target) << "old";
  NewFile file;
  ASSERT_FALSE(file.create(temporary));
  const std::string text = "new contents";
  EXPECT_FALSE(file.write({text.data(), text.size()}));
  EXPECT_FALSE(file.flush_to_disk());
  EXPECT_FALSE(file.close());
  NewFile again;
  EXPECT_EQ(again.create(temporary), std::errc::file_exists);
  EXPECT_FALSE(replace_file(temporary, target));
  EXPECT_EQ(test::read_text(target), text);
  EXPECT_FALSE(fs::exists(temporary));
  EXPECT_EQ(replace_file(dir / "missing", target), std::errc::no_such_file_or_directory);
  fs::remove_all(dir);
}

TEST(Platform, Utf8TextBecomesThePathOfThatName) {
  const std::string name = "données-Φγ-µ";
  const fs::path dir = fresh_dir("path");
  const fs::path p = path_from_utf8(dir.string() + "/" + name);
  EXPECT_EQ(p.filename().string(), name);
  fs::create_directories(p);
  EXPECT_TRUE(fs::is_directory(dir / std::u8string(u8"données-Φγ-µ")));
  fs::remove_all(dir);
}

#ifdef _WIN32
// Windows: this process's own arguments, from its wide command line (a non-ASCII one is
// ci/windows-test.sh's end-to-end run, in a folder named données-Φγ).
TEST(Platform, ArgumentsAreTheWideCommandLines) {
  Utf8Arguments args(__argc, __argv);
  ASSERT_EQ(args.argc(), __argc);
  EXPECT_NE(std::string(args.argv()[0]).find("vsgl_tests"), std::string::npos) << args.argv()[0];
  EXPECT_EQ(args.argv()[__argc], nullptr);
}
#else
TEST(Platform, ArgumentsAreKeptAsGiven) {
  std::string a0 = "vsgl-bench", a1 = "--out", a2 = "données";
  char* argv[] = {a0.data(), a1.data(), a2.data(), nullptr};
  Utf8Arguments args(3, argv);
  ASSERT_EQ(args.argc(), 3);
  EXPECT_EQ(std::string(args.argv()[2]), a2);
  EXPECT_EQ(args.argv()[3], nullptr);
}
#endif

TEST(Platform, AFileIsNotATerminal) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  EXPECT_FALSE(is_terminal(f));
  std::fclose(f);
}

}  // namespace
}  // namespace vsgl
