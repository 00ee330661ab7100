#pragma once
// One of the paper's claims judged on a run: one type for the table, sweep and quality documents,
// which write it each in its own layout (the keys differ; a committed file's keys never change).
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace vsgl {

class JsonReader;  // core/json_reader.hpp

// A claim whose interval straddles its bound is neither held nor refuted: holds = none with this
// note (or one that starts with the prefix and says why, e.g. too few rounds).
inline constexpr const char* kInconclusivePrefix = "inconclusive";
inline constexpr const char* kInconclusiveNote = "inconclusive at this noise";

struct Claim {
  std::string id;         // "overhead_5us", "pdf_independence", ...; "" where the document has none (quality)
  std::string text;       // the paper's sentence
  std::string source;     // where the paper says it ("paper §3 (Eq. 2-3)"); "" where the document does not say
  std::string criterion;  // what is measured, and the rule the verdict follows
  // The numbers judged, as the judging code wrote them (table, quality). The sweep keeps its own
  // typed (SweepClaim::measures, formats/sweep_model.hpp) and leaves this empty.
  nlohmann::ordered_json measured = nlohmann::ordered_json::object();
  std::optional<bool> holds;  // none: not measured, inconclusive, or no clear verdict; `note` says which
  std::string note;
  bool informative = false;  // a CPU device's timing: says nothing of a GPU's
};

// "holds", "does not hold", "inconclusive" (the note starts with kInconclusivePrefix) or "not measured".
std::string claim_verdict(const Claim& claim);
// The verdict in words, as the quality document states it: "holds", "does not hold", else the note.
std::string stated_verdict(const Claim& claim);

// How a document writes a claim. The sweep document writes its claims' shared fields itself
// (formats/sweep_model.cpp), between its own keys in the order its committed files have.
enum class ClaimLayout {
  // The table's: {id, claim, criterion, measured, holds (null: none), note, informative_only}.
  kTable,
  // The quality document's: {claim, source, measure, verdict} and the members of `measured` beside
  // them. verdict: "holds", "does not hold", or else the note ("no clear difference (within 1%)",
  // "not measured here", ...); the quality document has no id and no informative flag.
  kQuality,
};

// Throws std::invalid_argument for a claim the layout cannot hold (a quality claim with an id, a
// measured that is not an object, or a member of measured named as one of the layout's keys).
nlohmann::ordered_json to_json(const Claim& claim, ClaimLayout layout);
// `value` is what to_json writes, at `path`. Throws InputError naming the pointer of a missing or
// mistyped field.
Claim claim_from_json(const JsonReader& reader, const nlohmann::ordered_json& value, const std::string& path,
                      ClaimLayout layout);

}  // namespace vsgl
