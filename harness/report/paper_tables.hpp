#pragma once
// The paper's numbers (results/paper/paper_tables.json): Tables 1-3 and its claims, loaded once and
// looked up by path; a number the paper does not give is nullopt, never a made-up value.
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace vsgl {

// Loads and validates the file, so that every reader of the document may rely on its shape:
// an object with "source" (a string, optional), "setup" (an object with "gpu", a string),
// "tables" with "1" and "2" (generator -> {"camera_view": {phase: ms}, "light_view": {phase: ms},
// "total": ms}) and "3" (generator -> {"shaders", "dispatch_calls", "lines_of_code"}), every
// number finite and non-negative, and "claims", an array of the paper's 6 claims as strings.
// Throws InputError naming the file, the key (escaped, core/printable_text.hpp) and the problem.
nlohmann::ordered_json load_paper_tables(const std::filesystem::path& path);

// The paper's tables from `file` (--paper), or without one the copy of kPaperTablesFile built into
// the program (core/embedded_files.hpp), checked the same way.
inline constexpr const char* kPaperTablesFile = "results/paper/paper_tables.json";
nlohmann::ordered_json paper_tables_or_built_in(const std::optional<std::filesystem::path>& file);

// The same checks on a parsed document; `what` names it in messages.
void check_paper_tables(const nlohmann::ordered_json& doc, const std::string& what);

// The number at `path` (e.g. {"tables", "1", <a generator id>, "total"}), if the paper gives one.
std::optional<double> paper_number(const nlohmann::ordered_json& paper, std::initializer_list<std::string> path);
std::optional<double> paper_total(const nlohmann::ordered_json& paper, int table, const std::string& g);
// The paper's per-view total: the sum of its three phases (the paper prints only the grand total).
std::optional<double> paper_view_total(const nlohmann::ordered_json& paper, int table, const std::string& g,
                                       const std::string& view);

}  // namespace vsgl
