#pragma once
// Lines of code for Table 3's analog, counted from the sources rather than typed in, as the paper
// counted them: the code the default path compiles and runs (DESIGN.md §10).
// A counted line is a line with at least one character that is neither whitespace nor part of a
// comment (C++ and GLSL share the syntax: `// ...` to the end of the line and `/* ... */`, which
// may span lines). String literals are honoured, so "//" inside quotes is code. Preprocessor
// lines (#include, #version, #extension) count as code.
//
// Regions: a file shared by several configs (pyramid paths, mip strategies, FIS variants, sum
// passes) marks the lines of each with whole-line comments
//   // table3: begin NAME        (or NAME|OTHER: counted when either is)
//   // table3: end NAME          (the same spelling as its begin)
// Regions nest; a line counts only when every region around it is counted. The markers are
// comments and count for nothing.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vsgl {

// The rules above in a sentence each, for the table JSON (DESIGN.md §10).
inline constexpr const char* kTable3CountingRule =
    "Lines holding code (not blank, not only comments) of the files the run's path compiles: the generator's host "
    "C++ and the kernels it dispatches with the GLSL they include; of a shared file only the regions marked "
    "`// table3: begin NAME` that belong to this path (pyramid path, mip strategy, FIS variant, sum pass) count, "
    "and code that only verify or the report runs counts for no generator.";
inline constexpr const char* kTable3DifferenceRule =
    "A longest-common-subsequence line diff of the two generators' counted lines (comments removed, whitespace "
    "collapsed, files in the order listed): removed = lines of `from` outside the common subsequence, added = "
    "lines of `to` outside it, differing = removed + added; net = lines_of_code(to) - lines_of_code(from).";

// The source files of one generator, relative to the source tree (Table 3 analog).
struct SourceSet {
  std::vector<std::string> host;     // C++ files
  std::vector<std::string> kernels;  // kernels/*.comp it dispatches (one pipeline each)
  // Every region named in these files (and the GLSL they include), and whether this config
  // counts it. A marker naming a region missing here is an error.
  std::map<std::string, bool> regions;
};

uint32_t count_code_lines(std::string_view text);

// The counted lines of `text`, each with its comments removed and its runs of whitespace
// collapsed to one space (the form the Tok15/modified diff compares), honouring the region
// markers. Throws InputError naming `path` and the line for a malformed, unknown, unbalanced or
// unclosed marker.
std::vector<std::string> counted_code_lines(std::string_view text, const std::string& path,
                                            const std::map<std::string, bool>& regions);

struct CountedFile {
  std::string path;  // relative to the source tree
  uint32_t lines = 0;
  bool shader = false;  // a kernel or GLSL it includes (else host C++)
};

struct GeneratorLines {
  std::vector<CountedFile> files;  // host files, kernels, then the included GLSL (sorted, once each)
  uint32_t host = 0;               // lines of the host files
  uint32_t shader = 0;             // lines of the kernels and their includes
  uint32_t total = 0;
  std::vector<std::string> code;  // the counted lines in the order of `files` (counted_code_lines)
};

// Where the counted files are read from, by their path relative to the source tree.
struct SourceTree {
  // The text of the file `rel`; nullopt: no such file.
  std::function<std::optional<std::string>(const std::string& rel)> read;
  std::string where;  // for messages: a directory, or "built in"
};

// The files of a checkout at `dir` (the tests count the checkout to catch a stale embed).
SourceTree checkout_source_tree(const std::filesystem::path& dir);
// The files embedded at build time (core/embedded_files.hpp): what `tables` counts, so a copied
// binary counts the sources it was built from without the checkout.
SourceTree built_in_source_tree();

// Counts the generator's files plus every kernels/include/*.glsl reached by `#include "..."` from
// the counted lines of its kernels, transitively. Throws InputError naming a file that cannot be
// read (a tree without the kernels, a build that did not embed one) or a bad marker.
GeneratorLines count_generator_lines(const SourceSet& sources, const SourceTree& tree);
GeneratorLines count_generator_lines(const SourceSet& sources, const std::filesystem::path& source_dir);

}  // namespace vsgl
