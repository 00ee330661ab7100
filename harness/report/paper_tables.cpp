#include "harness/report/paper_tables.hpp"

#include <string>

#include "harness/core/path_text.hpp"
#include "harness/core/json_reader.hpp"
#include "harness/core/sorted_json.hpp"

namespace vsgl {
namespace {

using json = nlohmann::ordered_json;

constexpr std::size_t kClaimCount = 6;

// A number of the paper's: finite and non-negative.
void paper_value(const JsonReader& r, const json& value, const std::string& path) { (void)r.non_negative(value, path); }

void string_value(const JsonReader& r, const json& value, const std::string& path) {
  if (!value.is_string()) r.wrong_type(value, path, "a string");
}

void check_timing_table(const JsonReader& r, const json& table, const std::string& path) {
  for (const auto& [generator, entry] : table.items()) {
    const std::string gp = r.child(path, generator);
    if (!entry.is_object()) r.wrong_type(entry, gp, "an object");
    for (const char* view : {"camera_view", "light_view"}) {
      const json& phases = r.object(entry, gp, view);
      const std::string vp = r.child(gp, view);
      if (phases.empty()) r.fail(vp, "holds no phase");
      for (const auto& [phase, ms] : phases.items()) paper_value(r, ms, r.child(vp, phase));
    }
    paper_value(r, r.member(entry, gp, "total"), r.child(gp, "total"));
  }
}

}  // namespace

void check_paper_tables(const json& doc, const std::string& what) {
  const JsonReader r(what, JsonPathStyle::kDottedKey);
  if (!doc.is_object()) r.wrong_type(doc, "", "an object");
  (void)r.optional_string(doc, "", "source");
  (void)r.string(r.object(doc, "", "setup"), "setup", "gpu");
  const json& tables = r.object(doc, "", "tables");
  check_timing_table(r, r.object(tables, "tables", "1"), "tables.1");
  check_timing_table(r, r.object(tables, "tables", "2"), "tables.2");
  const json& table3 = r.object(tables, "tables", "3");
  for (const auto& [generator, entry] : table3.items()) {
    const std::string gp = r.child("tables.3", generator);
    if (!entry.is_object()) r.wrong_type(entry, gp, "an object");
    for (const char* key : {"shaders", "dispatch_calls", "lines_of_code"})
      paper_value(r, r.member(entry, gp, key), r.child(gp, key));
  }
  const json& claims = r.array(doc, "", "claims");
  if (claims.size() != kClaimCount)
    r.fail("claims", "holds " + std::to_string(claims.size()) + " claims, expected the paper's " +
                         std::to_string(kClaimCount));
  for (std::size_t i = 0; i < claims.size(); ++i) string_value(r, claims[i], r.element("claims", i));
}

nlohmann::ordered_json load_paper_tables(const std::filesystem::path& path) {
  nlohmann::ordered_json doc = read_json_file(path, "the paper's tables", " (use --paper FILE)");
  check_paper_tables(doc, path_text(path));
  return doc;
}

std::optional<double> paper_number(const nlohmann::ordered_json& paper, std::initializer_list<std::string> path) {
  const nlohmann::ordered_json* node = &paper;
  for (const auto& key : path) {
    if (!node->is_object() || !node->contains(key)) return std::nullopt;
    node = &(*node)[key];
  }
  if (!node->is_number()) return std::nullopt;
  return node->get<double>();
}

std::optional<double> paper_total(const nlohmann::ordered_json& paper, int table, const std::string& g) {
  return paper_number(paper, {"tables", std::to_string(table), g, "total"});
}

std::optional<double> paper_view_total(const nlohmann::ordered_json& paper, int table, const std::string& g,
                                       const std::string& view) {
  const std::string key = std::to_string(table);
  if (!paper.contains("tables") || !paper["tables"].contains(key) || !paper["tables"][key].contains(g)) return std::nullopt;
  const auto& v = paper["tables"][key][g];
  if (!v.contains(view) || !v[view].is_object()) return std::nullopt;
  // Summed in the phases' sorted order, the order every committed table's sums were made in
  // (floating-point addition is not associative: another order may change the last digit).
  const nlohmann::ordered_json phases = sorted_keys(v[view]);
  double sum = 0;
  for (const auto& [_, ms] : phases.items()) sum += ms.get<double>();
  return sum;
}

}  // namespace vsgl
