#pragma once
// The quality report (DESIGN.md §11a): verdicts on the paper's quality claims
// (results/paper/paper_tables.json "claims": Fig. 1, Fig. 5, Fig. 6; and the flicker reduction of
// the paper's §1/§4) computed from a run_quality() document, and its markdown rendering.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/formats/quality_model.hpp"
#include "harness/quality/quality_run.hpp"

namespace vsgl {

// Adds "claims": [{claim, source, measure, fis_tok15, fis_modified, verdict}] to a run_quality()
// document. A verdict is "holds" or "does not hold" (measured), or "not measured here".
void add_claim_verdicts(nlohmann::json& result);

// Markdown: per view, fis_tok15 vs fis_modified (and the other generators) on every metric; the
// reference error, flicker and K sweep tables; the claims with verdicts; the pictures.
// Throws InputError naming a missing or mistyped field of the document.
std::string quality_markdown(const QualityModel& result, const std::vector<QualityPicture>& pictures);
std::string quality_markdown(const nlohmann::json& result, const std::vector<QualityPicture>& pictures);

}  // namespace vsgl
