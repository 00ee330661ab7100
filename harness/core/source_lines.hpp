#pragma once
// Lines of code for Table 3's analog, counted from the sources rather than typed in.
// A counted line is a line with at least one character that is neither whitespace nor part of a
// comment (C++ and GLSL share the syntax: `// ...` to the end of the line and `/* ... */`, which
// may span lines). String literals are honoured, so "//" inside quotes is code. Preprocessor
// lines (#include, #version, #extension) count as code.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace vsgl {

// The source files of one generator, relative to the source tree (Table 3 analog).
struct SourceSet {
  std::vector<std::string> host;     // C++ files
  std::vector<std::string> kernels;  // kernels/*.comp it dispatches (one pipeline each)
};

uint32_t count_code_lines(std::string_view text);

struct CountedFile {
  std::string path;  // relative to the source tree
  uint32_t lines = 0;
};

struct GeneratorLines {
  std::vector<CountedFile> files;  // host files, kernels, then the included GLSL (sorted, once each)
  uint32_t total = 0;
};

// Counts the generator's files plus every kernels/include/*.glsl reached by
// `#include "..."` from its kernels, transitively. Throws InputError naming a file that cannot be
// read (e.g. --source-dir pointing at a tree without the kernels).
GeneratorLines count_generator_lines(const SourceSet& sources, const std::filesystem::path& source_dir);

}  // namespace vsgl
