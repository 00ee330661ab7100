// Error messages never echo raw bytes of a file (DESIGN.md §12): harness/core/printable_text.hpp,
// and the loaders that put file-derived text (JSON keys and values, names, parser messages) into their
// messages, on corrupted files. CPU only. (The capture loader on a corrupted EXR channel name:
// tests/test_capture_files.cpp CaptureIo.CorruptChannelNameIsEscapedInTheMessage.)
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "input_error.hpp"
#include "cli_runner.hpp"
#include "harness/core/error.hpp"
#include "harness/report/paper_tables.hpp"
#include "harness/core/printable_text.hpp"
#include "harness/compare/regression_run.hpp"
#include "test_support.hpp"

namespace vsgl {
namespace {

namespace fs = std::filesystem;
using namespace std::string_literals;

bool all_printable_ascii(const std::string& s) {
  for (const char ch : s) {
    const auto b = static_cast<unsigned char>(ch);
    if ((b < 0x20 || b > 0x7e) && b != '\n') return false;
  }
  return true;
}

TEST(PrintableText, PrintableAsciiAsIsEverythingElseAsHex) {
  EXPECT_EQ(printable_text("P.X roughness ~!{}\"'"), "P.X roughness ~!{}\"'");
  EXPECT_EQ(printable_text("val\x97" "d"), "val\\x97d");
  EXPECT_EQ(printable_text("\x1b[2J\r\n\t"), "\\x1b[2J\\x0d\\x0a\\x09");
  EXPECT_EQ(printable_text("a\0b"s), "a\\x00b");
  EXPECT_EQ(printable_text("\xc3\xa9t\xc3\xa9"), "\\xc3\\xa9t\\xc3\\xa9");  // valid UTF-8 is escaped too
  EXPECT_EQ(printable_text("\x7f\xff"), "\\x7f\\xff");
  // The backslash itself, so that "\x97" in a message can only mean the byte.
  EXPECT_EQ(printable_text("a\\x97"), "a\\x5cx97");
  EXPECT_EQ(quoted_text("val\x97" "d"), "\"val\\x97d\"");
}

TEST(PrintableText, LongTextIsCut) {
  EXPECT_EQ(printable_text(std::string(300, 'a')), std::string(kPrintableTextMaxBytes, 'a') + "...");
  EXPECT_EQ(printable_text("abcdef", 3), "abc...");
  EXPECT_EQ(printable_text("abc", 3), "abc");
}

class TempFile {
 public:
  explicit TempFile(const std::string& name, const std::string& bytes) : dir_("printable"), path_(dir_ / name) {
    std::ofstream(path_, std::ios::binary) << bytes;
  }
  const fs::path& path() const { return path_; }

 private:
  test::TempDir dir_;
  fs::path path_;
};

using test::input_error;

// A table JSON whose generator name (a key) holds a terminal escape and a non-ASCII letter.
const std::string kHostileTable =
    R"({"schema_version": 1, "table": 1, "capture": {"hashes": {}}, "config": {},
        "generators": {"fis\u001b[2J\u00e9": {}}})";

TEST(PrintableTextInLoaders, RunJsonKeyIsEscaped) {
  const TempFile file("table1.json", kHostileTable);
  const std::string message = input_error([&] { (void)load_bench_run(file.path()); });
  EXPECT_NE(message.find("/generators/fis\\x1b[2J\\xc3\\xa9/views"), std::string::npos) << message;
  EXPECT_TRUE(all_printable_ascii(message)) << message;
}

TEST(PrintableTextInLoaders, ParserMessageAboutRawBytesIsEscaped) {
  // Not JSON: invalid UTF-8 inside a string; nlohmann's message quotes what it last read.
  const TempFile file("table1.json", "{\"schema_version\": \"val\x97\x1b" "d");
  const std::string message = input_error([&] { (void)load_bench_run(file.path()); });
  EXPECT_NE(message.find("not valid JSON"), std::string::npos) << message;
  EXPECT_TRUE(all_printable_ascii(message)) << message;
}

TEST(PrintableTextInLoaders, PaperTablesKeyIsEscaped) {
  const TempFile file("paper_tables.json",
                      R"({"setup": {"gpu": "g"}, "tables": {"1": {"k\u0007\u00ff": {"camera_view": {}}}}})");
  const std::string message = input_error([&] { (void)load_paper_tables(file.path()); });
  EXPECT_NE(message.find("tables.1.k\\x07\\xc3\\xbf.camera_view"), std::string::npos) << message;
  EXPECT_TRUE(all_printable_ascii(message)) << message;
}

TEST(PrintableTextInLoaders, CompareCommandPrintsNoRawBytes) {
  const TempFile file("table1.json", kHostileTable);
  const auto r = test::run_cli("compare " + file.path().string() + " " + file.path().string());
  EXPECT_EQ(r.exit_code, 3) << r.output;  // bad input
  EXPECT_NE(r.output.find("fis\\x1b[2J\\xc3\\xa9"), std::string::npos) << r.output;
  EXPECT_TRUE(all_printable_ascii(r.output)) << r.output;
}

}  // namespace
}  // namespace vsgl
