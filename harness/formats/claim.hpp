#pragma once
// One of the paper's claims judged on a run: one type for the table, sweep and quality documents,
// which write it each in its own layout (the keys differ; a committed file's keys never change).
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "harness/core/claim_verdict.hpp"

namespace vsgl {

class JsonReader;  // core/json_reader.hpp

// How the table and sweep documents word an inconclusive verdict's reason: this note, or one that
// starts with the prefix and says why (e.g. too few rounds). Their "holds" is null both for an
// inconclusive verdict and for none, so the prefix is what tells the two apart on reading.
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
  // none: not measured here; `note` says why. Read back from a document, whose keys carry no rule
  // of their own, the verdict's rule is the criterion, and its interval the one `measured` holds
  // (the quality document's "interval", the table's "ci_low_us" and "ci_high_us"), if any.
  std::optional<ClaimVerdict> verdict;
  std::string note;          // why there is no verdict; "" when there is one (its reason says the rest)
  bool informative = false;  // a CPU device's timing: says nothing of a GPU's
};

// "holds", "does not hold", "inconclusive" or "not measured".
std::string claim_verdict(const Claim& claim);
// The verdict in words, as the quality document states it: "holds", "does not hold", else the
// inconclusive verdict's reason or the note.
std::string stated_verdict(const Claim& claim);
// What a reader is told beside the verdict: the verdict's reason, or the note when there is none.
const std::string& claim_note(const Claim& claim);

// The table's and the sweep's two fields of a verdict. "holds": true, false, or null for an
// inconclusive verdict and for none; "note": claim_note. Throws std::invalid_argument for a claim
// with both a verdict and a note or neither, or an inconclusive reason without kInconclusivePrefix.
nlohmann::ordered_json claim_holds_json(const Claim& claim);
// Reads them back: a verdict when `holds` is set or the note starts with kInconclusivePrefix (its
// rule the claim's criterion and its interval from `measured`, so set those first), else no
// verdict and the note.
void set_verdict(Claim& claim, std::optional<bool> holds, const std::string& note);

// How a document writes a claim. The sweep document writes its claims' shared fields itself
// (formats/sweep_model.cpp), between its own keys in the order its committed files have.
enum class ClaimLayout {
  // The table's: {id, claim, criterion, measured, holds, note, informative_only}. holds: true,
  // false, or null (inconclusive, its note starting with kInconclusivePrefix; or no verdict).
  kTable,
  // The quality document's: {claim, source, measure, verdict} and the members of `measured` beside
  // them. verdict: "holds", "does not hold", the note of a claim not measured (it starts with
  // "not measured"), or else an inconclusive verdict's reason ("reference not converged ...",
  // "inconclusive: ...", "no clear difference (within 1%)" in older files); the quality document
  // has no id and no informative flag.
  kQuality,
};

// Throws std::invalid_argument for a claim the layout cannot hold, that is one it would not read
// back the same: a quality claim with an id, a measured that is not an object, a member of
// measured named as one of the layout's keys, a claim with both a verdict and a note or neither,
// a held or refuted quality claim with a reason, or an inconclusive reason the layout would read
// as something else.
nlohmann::ordered_json to_json(const Claim& claim, ClaimLayout layout);
// `value` is what to_json writes, at `path`. Throws InputError naming the pointer of a missing or
// mistyped field.
Claim claim_from_json(const JsonReader& reader, const nlohmann::ordered_json& value, const std::string& path,
                      ClaimLayout layout);

}  // namespace vsgl
