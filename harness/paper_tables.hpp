#pragma once
// The paper's numbers, results/paper/paper_tables.json (or --paper FILE): Tables 1-3 of
// Tokuyoshi 2016, its setup and its claims. Read by `tables` (the paper's value beside every
// measured one) and `dashboard` (the paper's bars).
#include <filesystem>

#include <nlohmann/json.hpp>

namespace vsgl {

// Loads and validates the file, so that every reader of the document may rely on its shape:
// an object with "source" (a string, optional), "setup" (an object with "gpu", a string),
// "tables" with "1" and "2" (generator -> {"camera_view": {phase: ms}, "light_view": {phase: ms},
// "total": ms}; the paper's four generators with exactly their three phases) and "3"
// (generator -> {"shaders", "dispatch_calls", "lines_of_code"}), every number finite and
// non-negative, and "claims", an array of the paper's 6 claims as strings. Throws InputError
// naming the file, the key (escaped, harness/printable_text.hpp) and the problem.
nlohmann::json load_paper_tables(const std::filesystem::path& path);

// The same checks on a parsed document; `what` names it in messages.
void check_paper_tables(const nlohmann::json& doc, const std::string& what);

}  // namespace vsgl
