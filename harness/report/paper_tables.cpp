#include "harness/report/paper_tables.hpp"

#include <cmath>
#include <string>

#include "harness/core/path_text.hpp"
#include "harness/core/error.hpp"
#include "harness/core/json_reader.hpp"
#include "harness/core/printable_text.hpp"

namespace vsgl {
namespace {

using nlohmann::json;

constexpr std::size_t kClaimCount = 6;

class PaperReader {
 public:
  explicit PaperReader(std::string what) : what_(std::move(what)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& problem) const {
    throw InputError(what_ + ": " + (key.empty() ? "" : "key " + quoted_text(key) + " ") + problem);
  }
  const json& member(const json& object, const std::string& parent, const std::string& key) const {
    const std::string path = join(parent, key);
    const auto it = object.find(key);
    if (it == object.end()) fail(path, "is missing");
    return *it;
  }
  const json& object(const json& parent_object, const std::string& parent, const std::string& key) const {
    const json& v = member(parent_object, parent, key);
    if (!v.is_object()) fail(join(parent, key), std::string("is ") + v.type_name() + ", expected an object");
    return v;
  }
  void number(const json& v, const std::string& path) const {
    if (!v.is_number()) fail(path, std::string("is ") + v.type_name() + ", expected a number");
    const double x = v.get<double>();
    if (!std::isfinite(x) || x < 0.0) fail(path, "is " + v.dump() + ", expected a finite non-negative number");
  }
  void string(const json& v, const std::string& path) const {
    if (!v.is_string()) fail(path, std::string("is ") + v.type_name() + ", expected a string");
  }
  static std::string join(const std::string& parent, const std::string& key) {
    return parent.empty() ? key : parent + "." + key;
  }

 private:
  std::string what_;
};

void check_timing_table(const PaperReader& r, const json& table, const std::string& path) {
  for (const auto& [generator, entry] : table.items()) {
    const std::string gp = PaperReader::join(path, generator);
    if (!entry.is_object()) r.fail(gp, std::string("is ") + entry.type_name() + ", expected an object");
    for (const char* view : {"camera_view", "light_view"}) {
      const json& phases = r.object(entry, gp, view);
      const std::string vp = PaperReader::join(gp, view);
      if (phases.empty()) r.fail(vp, "holds no phase");
      for (const auto& [phase, ms] : phases.items()) r.number(ms, PaperReader::join(vp, phase));
    }
    r.number(r.member(entry, gp, "total"), PaperReader::join(gp, "total"));
  }
}

}  // namespace

void check_paper_tables(const json& doc, const std::string& what) {
  const PaperReader r(what);
  if (!doc.is_object()) r.fail("", std::string("is a JSON ") + doc.type_name() + ", expected an object");
  if (const auto it = doc.find("source"); it != doc.end()) r.string(*it, "source");
  r.string(r.member(r.object(doc, "", "setup"), "setup", "gpu"), "setup.gpu");
  const json& tables = r.object(doc, "", "tables");
  check_timing_table(r, r.object(tables, "tables", "1"), "tables.1");
  check_timing_table(r, r.object(tables, "tables", "2"), "tables.2");
  const json& table3 = r.object(tables, "tables", "3");
  for (const auto& [generator, entry] : table3.items()) {
    const std::string gp = "tables.3." + generator;
    if (!entry.is_object()) r.fail(gp, std::string("is ") + entry.type_name() + ", expected an object");
    for (const char* key : {"shaders", "dispatch_calls", "lines_of_code"})
      r.number(r.member(entry, gp, key), PaperReader::join(gp, key));
  }
  const json& claims = r.member(doc, "", "claims");
  if (!claims.is_array()) r.fail("claims", std::string("is ") + claims.type_name() + ", expected an array");
  if (claims.size() != kClaimCount)
    r.fail("claims", "holds " + std::to_string(claims.size()) + " claims, expected the paper's " +
                         std::to_string(kClaimCount));
  for (std::size_t i = 0; i < claims.size(); ++i) r.string(claims[i], "claims[" + std::to_string(i) + "]");
}


nlohmann::json load_paper_tables(const std::filesystem::path& path) {
  nlohmann::json doc = read_json_file(path, "the paper's tables", " (use --paper FILE)");
  check_paper_tables(doc, path_text(path));
  return doc;
}

std::optional<double> paper_number(const nlohmann::json& paper, std::initializer_list<std::string> path) {
  const nlohmann::json* node = &paper;
  for (const auto& key : path) {
    if (!node->is_object() || !node->contains(key)) return std::nullopt;
    node = &(*node)[key];
  }
  if (!node->is_number()) return std::nullopt;
  return node->get<double>();
}

std::optional<double> paper_total(const nlohmann::json& paper, int table, const std::string& g) {
  return paper_number(paper, {"tables", std::to_string(table), g, "total"});
}

std::optional<double> paper_view_total(const nlohmann::json& paper, int table, const std::string& g,
                                       const std::string& view) {
  const std::string key = std::to_string(table);
  if (!paper.contains("tables") || !paper["tables"].contains(key) || !paper["tables"][key].contains(g)) return std::nullopt;
  const auto& v = paper["tables"][key][g];
  if (!v.contains(view) || !v[view].is_object()) return std::nullopt;
  double sum = 0;
  for (const auto& [_, ms] : v[view].items()) sum += ms.get<double>();
  return sum;
}

}  // namespace vsgl
