#include "harness/scene/detail/obj_text.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace vsgl::obj {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t'; }

// The text's lines as tinyobjloader reads them: ended by \n, \r or \r\n, each cut at a NUL
// (tinyobjloader parses each line as a C string).
template <class F>
void for_each_line(std::string_view text, F&& f) {
  std::size_t at = 0;
  int line = 0;
  while (at < text.size()) {
    std::size_t end = at;
    while (end < text.size() && text[end] != '\n' && text[end] != '\r') ++end;
    std::string_view l = text.substr(at, end - at);
    if (const std::size_t nul = l.find('\0'); nul != std::string_view::npos) l = l.substr(0, nul);
    ++line;
    f(l, line);
    at = end;
    if (at < text.size() && text[at] == '\r') ++at;
    if (at < text.size() && text[at] == '\n' && (text[end] == '\n' || at == end + 1)) ++at;
  }
}

std::string_view trim_front(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  return s;
}

std::vector<std::string_view> words(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && (is_space(s[i]) || s[i] == '\r')) ++i;
    std::size_t j = i;
    while (j < s.size() && !is_space(s[j]) && s[j] != '\r') ++j;
    if (j > i) out.push_back(s.substr(i, j - i));
    i = j;
  }
  return out;
}

// A face index as tinyobjloader's atoi reads it (leading sign and digits), as a long long so
// that no value wraps; a part without digits reads 0.
long long index_value(std::string_view part) {
  const std::string s(part);
  errno = 0;
  const long long v = std::strtoll(s.c_str(), nullptr, 10);
  return errno == ERANGE ? (v < 0 ? -(1ll << 62) : (1ll << 62)) : v;
}

std::string line_text(int line) { return "line " + std::to_string(line); }

}  // namespace

ObjText scan_obj(std::string_view text, const gltf::Reporter& r) {
  ObjText out;
  for_each_line(text, [&](std::string_view raw, int line) {
    const std::string_view l = trim_front(raw);
    if (l.size() < 2) return;
    const auto is = [&](std::string_view kw) {
      return l.substr(0, kw.size()) == kw && l.size() > kw.size() && is_space(l[kw.size()]);
    };
    if (is("v")) {
      const std::vector<std::string_view> w = words(l.substr(2));
      for (std::size_t k = 0; k < w.size() && k < 3; ++k) {
        const std::string s(w[k]);
        const double v = std::strtod(s.c_str(), nullptr);
        if (!std::isfinite(v))
          r.fail(line_text(line) + ": vertex position " + std::to_string(out.positions + 1) + " has a non-finite coordinate (" +
                 escape_name(s) + ")");
      }
      ++out.positions;
    } else if (is("vt")) {
      ++out.texcoords;
    } else if (is("vn")) {
      ++out.normals;
    } else if (is("f")) {
      const std::vector<std::string_view> corners = words(l.substr(2));
      for (std::size_t c = 0; c < corners.size(); ++c) {
        std::string_view rest = corners[c];
        std::string_view parts[3];
        for (int k = 0; k < 3; ++k) {
          const std::size_t slash = rest.find('/');
          parts[k] = rest.substr(0, slash);
          if (slash == std::string_view::npos) break;
          rest.remove_prefix(slash + 1);
        }
        const char* names[3] = {"position", "texture coordinate", "normal"};
        const uint64_t counts[3] = {out.positions, out.texcoords, out.normals};
        for (int k = 0; k < 3; ++k) {
          if (k > 0 && parts[k].empty()) continue;  // "1//2", "1/2": that attribute is absent
          const long long idx = index_value(parts[k]);
          const long long n = static_cast<long long>(counts[k]);
          const long long resolved = idx > 0 ? idx - 1 : n + idx;
          if (idx == 0 || resolved < 0 || resolved >= n)
            r.fail(line_text(line) + ": face corner " + std::to_string(c + 1) + " refers to " + names[k] + " " +
                   escape_name(std::string(parts[k])) + ", out of range for the " + std::to_string(n) + " " + names[k] +
                   "s defined before it");
        }
      }
      if (corners.size() >= 3) ++out.faces;
    } else if (is("l") || is("p")) {
      ++out.lines_points;
    } else if (is("mtllib")) {
      for (std::string_view w : words(l.substr(7))) out.mtllibs.emplace_back(w);
    }
  });
  return out;
}

MtlText scan_mtl(std::string_view text) {
  MtlText out;
  MtlMaterialLines* current = nullptr;
  for_each_line(text, [&](std::string_view raw, int line) {
    const std::vector<std::string_view> w = words(trim_front(raw));
    if (w.empty()) return;
    if (w[0] == "newmtl") {
      std::string name;
      if (w.size() > 1) name = std::string(trim_front(raw).substr(6));
      // tinyobjloader takes the rest of the line, trailing blanks removed.
      while (!name.empty() && (is_space(name.back()) || name.back() == '\r')) name.pop_back();
      name = std::string(trim_front(name));
      current = &out.materials[name];
      current->newmtl = line;
    } else if (current != nullptr) {
      current->statements.emplace(std::string(w[0]), line);
    }
  });
  return out;
}

}  // namespace vsgl::obj
