#pragma once
// The paper's numbers (results/paper/paper_tables.json): Tables 1-3 and its claims, loaded once and
// looked up by path; a number the paper does not give is nullopt, never a made-up value.
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace vsgl {

// Loads the paper's numbers; throws InputError naming the file when it is missing, not JSON, or
// lacks tables 1-3 or the claims.
nlohmann::json load_paper_tables(const std::filesystem::path& path);

// The number at `path` (e.g. {"tables", "1", "fis_tok15", "total"}), if the paper gives one.
std::optional<double> paper_number(const nlohmann::json& paper, std::initializer_list<std::string> path);
std::optional<double> paper_total(const nlohmann::json& paper, int table, const std::string& g);
// The paper's per-view total: the sum of its three phases (the paper prints only the grand total).
std::optional<double> paper_view_total(const nlohmann::json& paper, int table, const std::string& g,
                                       const std::string& view);

}  // namespace vsgl
