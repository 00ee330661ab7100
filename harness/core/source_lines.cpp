#include "harness/core/source_lines.hpp"

#include <algorithm>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "harness/core/error.hpp"

namespace vsgl {

uint32_t count_code_lines(std::string_view text) {
  uint32_t lines = 0;
  bool in_block = false;   // inside /* */
  bool line_has_code = false;
  char quote = 0;          // inside "..." or '...'
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    const char next = i + 1 < text.size() ? text[i + 1] : '\0';
    if (c == '\n') {
      if (line_has_code) ++lines;
      line_has_code = false;
      quote = 0;  // an unterminated literal ends with its line (no raw strings in the counted files)
      continue;
    }
    if (in_block) {
      if (c == '*' && next == '/') {
        in_block = false;
        ++i;
      }
      continue;
    }
    if (quote != 0) {
      line_has_code = true;
      if (c == '\\') ++i;
      else if (c == quote) quote = 0;
      continue;
    }
    if (c == '/' && next == '/') {
      while (i + 1 < text.size() && text[i + 1] != '\n') ++i;  // rest of the line is comment
      continue;
    }
    if (c == '/' && next == '*') {
      in_block = true;
      ++i;
      continue;
    }
    if (c == '"' || c == '\'') quote = c;
    if (c != ' ' && c != '\t' && c != '\r' && c != '\f' && c != '\v') line_has_code = true;
  }
  if (line_has_code) ++lines;
  return lines;
}

namespace {

std::string read_source(const std::filesystem::path& source_dir, const std::string& rel) {
  std::ifstream in(source_dir / rel, std::ios::binary);
  if (!in) throw InputError((source_dir / rel).string() + ": cannot read a source file of a generator (Table 3 lines of code)");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

GeneratorLines count_generator_lines(const SourceSet& sources, const std::filesystem::path& source_dir) {
  GeneratorLines out;
  std::vector<std::string> own = sources.host;
  own.insert(own.end(), sources.kernels.begin(), sources.kernels.end());
  // Includes reached from the kernels, transitively, found as glslang finds them: beside the
  // including file first (interface/*.h include "interop.h"), then in kernels/include/.
  static const std::regex include_re(R"re(^\s*#\s*include\s+"([^"]+)")re");
  std::set<std::string> includes;
  std::vector<std::string> pending(sources.kernels.begin(), sources.kernels.end());
  std::vector<std::pair<std::string, std::string>> texts;  // path, text
  for (const auto& rel : own) texts.emplace_back(rel, read_source(source_dir, rel));
  while (!pending.empty()) {
    const std::string rel = pending.back();
    pending.pop_back();
    const std::string text = read_source(source_dir, rel);
    std::istringstream lines(text);
    std::string line;
    std::smatch m;
    while (std::getline(lines, line))
      if (std::regex_search(line, m, include_re)) {
        const std::filesystem::path beside = std::filesystem::path(rel).parent_path() / m[1].str();
        const std::string inc = std::filesystem::exists(source_dir / beside) && rel.rfind("kernels/include/", 0) == 0
                                    ? beside.lexically_normal().generic_string()
                                    : "kernels/include/" + m[1].str();
        if (includes.insert(inc).second) pending.push_back(inc);
      }
  }
  for (const auto& inc : includes) texts.emplace_back(inc, read_source(source_dir, inc));
  for (const auto& [path, text] : texts) {
    const uint32_t n = count_code_lines(text);
    out.files.push_back({path, n});
    out.total += n;
  }
  return out;
}

}  // namespace vsgl
