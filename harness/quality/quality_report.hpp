#pragma once
// The quality report (DESIGN.md §11a): the markdown rendering of a run_quality() document with its
// claims (quality_claims.hpp).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/formats/quality_model.hpp"
#include "harness/quality/quality_run.hpp"

namespace vsgl {

// Markdown: per view, fis_tok15 vs fis_modified (and the other generators) on every metric; the
// reference error, per-frame error, flicker and K sweep tables; the claims with verdicts; the pictures.
// Throws InputError naming a missing or mistyped field of the document.
std::string quality_markdown(const QualityModel& result, const std::vector<QualityPicture>& pictures);
std::string quality_markdown(const nlohmann::ordered_json& result, const std::vector<QualityPicture>& pictures);

}  // namespace vsgl
