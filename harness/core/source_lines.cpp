#include "harness/core/source_lines.hpp"

#include <algorithm>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "harness/core/path_text.hpp"
#include "harness/core/embedded_files.hpp"
#include "harness/core/error.hpp"

namespace vsgl {
namespace {

// One physical line: its code with comments removed and whitespace collapsed (empty: no code),
// and its raw text (where markers are looked for).
struct PhysicalLine {
  std::string code;
  std::string raw;
  bool starts_in_comment = false;  // inside a /* */ opened on an earlier line
};

std::vector<PhysicalLine> split_code(std::string_view text) {
  // A checkout with CRLF line ends (git's autocrlf on Windows) counts as the LF one: a '\r' left at
  // a line's end would hide its Table 3 marker from the marker pattern.
  std::string lf;
  if (text.find("\r\n") != std::string_view::npos) {
    lf.reserve(text.size());
    for (std::size_t i = 0; i < text.size(); ++i)
      if (!(text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n')) lf += text[i];
    text = lf;
  }
  std::vector<PhysicalLine> out(1);
  bool in_block = false;  // inside /* */
  char quote = 0;         // inside "..." or '...'
  bool pending_space = false;
  const auto put = [&](char c) {
    std::string& code = out.back().code;
    if (pending_space && !code.empty()) code += ' ';
    pending_space = false;
    code += c;
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    const char next = i + 1 < text.size() ? text[i + 1] : '\0';
    if (c == '\n') {
      out.emplace_back();
      out.back().starts_in_comment = in_block;
      pending_space = false;
      quote = 0;  // an unterminated literal ends with its line (no raw strings in the counted files)
      continue;
    }
    out.back().raw += c;
    if (in_block) {
      if (c == '*' && next == '/') {
        in_block = false;
        out.back().raw += next;
        ++i;
        pending_space = true;
      }
      continue;
    }
    if (quote != 0) {
      put(c);
      if (c == '\\' && next != '\0' && next != '\n') {
        put(next);
        out.back().raw += next;
        ++i;
      } else if (c == quote) {
        quote = 0;
      }
      continue;
    }
    if (c == '/' && next == '/') {
      while (i + 1 < text.size() && text[i + 1] != '\n') out.back().raw += text[++i];  // rest of the line is comment
      continue;
    }
    if (c == '/' && next == '*') {
      in_block = true;
      out.back().raw += next;
      ++i;
      continue;
    }
    if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
      pending_space = true;
      continue;
    }
    if (c == '"' || c == '\'') quote = c;
    put(c);
  }
  return out;
}

// An open region: its spelling (NAME or NAME|OTHER), where it began, and whether it is counted.
struct OpenRegion {
  std::string spec;
  std::size_t line;
  bool counted;
};

std::string known_regions(const std::map<std::string, bool>& regions) {
  if (regions.empty()) return "none";
  std::string s;
  for (const auto& [name, counted] : regions) s += (s.empty() ? "" : ", ") + name;
  return s;
}

std::string read_source(const SourceTree& tree, const std::string& rel) {
  std::optional<std::string> text = tree.read(rel);
  if (!text)
    throw InputError(rel + " (" + tree.where + "): cannot read a source file of a generator (Table 3 lines of code)");
  return std::move(*text);
}

}  // namespace

uint32_t count_code_lines(std::string_view text) {
  uint32_t lines = 0;
  for (const PhysicalLine& l : split_code(text))
    if (!l.code.empty()) ++lines;
  return lines;
}

std::vector<std::string> counted_code_lines(std::string_view text, const std::string& path,
                                            const std::map<std::string, bool>& regions) {
  static const std::regex marker_re(R"re(^\s*//\s*table3:(.*)$)re");
  static const std::regex form_re(R"re(^\s*(begin|end)\s+([a-z0-9_]+(\|[a-z0-9_]+)*)\s*$)re");
  std::vector<std::string> out;
  std::vector<OpenRegion> open;
  const std::vector<PhysicalLine> lines = split_code(text);
  for (std::size_t n = 0; n < lines.size(); ++n) {
    const PhysicalLine& l = lines[n];
    const std::string where = path + ":" + std::to_string(n + 1) + ": ";
    std::smatch m;
    if (!l.starts_in_comment && l.code.empty() && std::regex_match(l.raw, m, marker_re)) {
      const std::string body = m[1].str();
      std::smatch f;
      if (!std::regex_match(body, f, form_re))
        throw InputError(where + "malformed Table 3 marker '" + l.raw +
                         "' (expected `// table3: begin NAME` or `// table3: end NAME`, NAME in [a-z0-9_], "
                         "alternatives joined by |)");
      const std::string spec = f[2].str();
      if (f[1] == "begin") {
        bool counted = false;
        std::stringstream names(spec);
        std::string name;
        while (std::getline(names, name, '|')) {
          const auto it = regions.find(name);
          if (it == regions.end())
            throw InputError(where + "unknown Table 3 region '" + name +
                             "' (the regions of this generator: " + known_regions(regions) + ")");
          counted = counted || it->second;
        }
        open.push_back({spec, n + 1, counted});
      } else if (open.empty()) {
        throw InputError(where + "`// table3: end " + spec + "` without a matching begin");
      } else if (open.back().spec != spec) {
        throw InputError(where + "`// table3: end " + spec + "` closes region '" + open.back().spec +
                         "' begun on line " + std::to_string(open.back().line));
      } else {
        open.pop_back();
      }
      continue;
    }
    if (l.code.empty()) continue;
    if (std::all_of(open.begin(), open.end(), [](const OpenRegion& r) { return r.counted; })) out.push_back(l.code);
  }
  if (!open.empty())
    throw InputError(path + ":" + std::to_string(open.back().line) + ": Table 3 region '" + open.back().spec +
                     "' is never ended (`// table3: end " + open.back().spec + "` missing)");
  return out;
}

SourceTree checkout_source_tree(const std::filesystem::path& dir) {
  return SourceTree{[dir](const std::string& rel) -> std::optional<std::string> {
                      std::ifstream in(dir / rel, std::ios::binary);
                      if (!in) return std::nullopt;
                      std::ostringstream ss;
                      ss << in.rdbuf();
                      return ss.str();
                    },
                    path_text(dir)};
}

SourceTree built_in_source_tree() {
  return SourceTree{[](const std::string& rel) -> std::optional<std::string> {
                      const std::optional<std::string_view> text = embedded_file(rel);
                      if (!text) return std::nullopt;
                      return std::string(*text);
                    },
                    "built in"};
}

GeneratorLines count_generator_lines(const SourceSet& sources, const std::filesystem::path& source_dir) {
  return count_generator_lines(sources, checkout_source_tree(source_dir));
}

GeneratorLines count_generator_lines(const SourceSet& sources, const SourceTree& tree) {
  GeneratorLines out;
  // Includes reached from the kernels' counted lines, transitively, found as glslang finds them:
  // beside the including file first (interface/*.h include "interop.h"), then in kernels/include/.
  static const std::regex include_re(R"re(^#\s*include\s*"([^"]+)")re");
  std::set<std::string> includes;
  for (const auto& rel : sources.host) {
    const std::vector<std::string> code = counted_code_lines(read_source(tree, rel), rel, sources.regions);
    out.files.push_back({rel, static_cast<uint32_t>(code.size()), false});
    out.host += static_cast<uint32_t>(code.size());
    out.code.insert(out.code.end(), code.begin(), code.end());
  }
  std::vector<std::string> pending(sources.kernels.rbegin(), sources.kernels.rend());
  std::vector<std::pair<std::string, std::vector<std::string>>> kernels, included;
  while (!pending.empty()) {
    const std::string rel = pending.back();
    pending.pop_back();
    const bool is_include = rel.rfind("kernels/include/", 0) == 0 &&
                            std::find(sources.kernels.begin(), sources.kernels.end(), rel) == sources.kernels.end();
    std::vector<std::string> code = counted_code_lines(read_source(tree, rel), rel, sources.regions);
    for (const std::string& line : code) {
      std::smatch m;
      if (!std::regex_search(line, m, include_re)) continue;
      const std::filesystem::path beside = std::filesystem::path(rel).parent_path() / m[1].str();
      const std::string inc =
          rel.rfind("kernels/include/", 0) == 0 && tree.read(beside.lexically_normal().generic_string())
              ? beside.lexically_normal().generic_string()
              : "kernels/include/" + m[1].str();
      if (includes.insert(inc).second) pending.push_back(inc);
    }
    (is_include ? included : kernels).emplace_back(rel, std::move(code));
  }
  std::sort(included.begin(), included.end());
  for (auto* group : {&kernels, &included})
    for (auto& [rel, code] : *group) {
      out.files.push_back({rel, static_cast<uint32_t>(code.size()), true});
      out.shader += static_cast<uint32_t>(code.size());
      out.code.insert(out.code.end(), code.begin(), code.end());
    }
  out.total = out.host + out.shader;
  return out;
}

}  // namespace vsgl
