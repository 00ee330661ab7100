#include "harness/report/paper_tables.hpp"

#include "harness/core/error.hpp"
#include "harness/core/json_reader.hpp"

namespace vsgl {

nlohmann::json load_paper_tables(const std::filesystem::path& path) {
  const nlohmann::json doc = read_json_file(path, "the paper's tables", " (use --paper FILE)");
  if (!doc.is_object()) throw InputError(path.string() + ": the paper's tables are not a JSON object");
  for (const char* t : {"1", "2", "3"})
    if (!doc.contains("tables") || !doc["tables"].contains(t))
      throw InputError(path.string() + ": lacks tables." + t);
  if (!doc.contains("claims") || !doc["claims"].is_array()) throw InputError(path.string() + ": lacks the claims list");
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
