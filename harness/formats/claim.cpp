#include "harness/formats/claim.hpp"

#include <stdexcept>

#include "harness/core/json_reader.hpp"

namespace vsgl {
namespace {

using ojson = nlohmann::ordered_json;

constexpr const char* kHolds = "holds";
constexpr const char* kDoesNotHold = "does not hold";

ojson table_json(const Claim& c) {
  return ojson{{"id", c.id},
               {"claim", c.text},
               {"criterion", c.criterion},
               {"measured", c.measured},
               {"holds", c.holds ? ojson(*c.holds) : ojson(nullptr)},
               {"note", c.note},
               {"informative_only", c.informative}};
}

Claim read_table(const JsonReader& r, const ojson& c, const std::string& p) {
  if (!c.is_object()) r.wrong_type(c, p, "an object");
  Claim claim;
  claim.id = r.string(c, p, "id");
  claim.text = r.string(c, p, "claim");
  claim.criterion = r.string(c, p, "criterion");
  claim.measured = r.object(c, p, "measured");
  if (!r.member(c, p, "holds").is_null()) claim.holds = r.boolean(c, p, "holds");
  claim.note = r.string(c, p, "note");
  claim.informative = r.boolean(c, p, "informative_only");
  return claim;
}

// The quality document's own keys; every other member of a claim is one of its measured numbers.
constexpr const char* kQualityKeys[] = {"claim", "source", "measure", "verdict"};

bool is_quality_key(const std::string& key) {
  for (const char* k : kQualityKeys)
    if (key == k) return true;
  return false;
}

ojson quality_json(const Claim& c) {
  if (!c.id.empty() || c.informative) throw std::invalid_argument("a quality claim has no id and no informative flag");
  if (!c.measured.is_object()) throw std::invalid_argument("a quality claim's measured numbers are an object");
  if (c.holds ? !c.note.empty() : c.note.empty())
    throw std::invalid_argument("a quality claim has a verdict or a note that says why not, never both");
  ojson o{{"claim", c.text}, {"source", c.source}, {"measure", c.criterion}, {"verdict", stated_verdict(c)}};
  for (const auto& [key, value] : c.measured.items()) {
    if (is_quality_key(key)) throw std::invalid_argument("a quality claim's measured number is named " + key);
    o[key] = value;
  }
  return o;
}

Claim read_quality(const JsonReader& r, const ojson& c, const std::string& p) {
  if (!c.is_object()) r.wrong_type(c, p, "an object");
  Claim claim;
  claim.text = r.string(c, p, "claim");
  claim.source = r.string(c, p, "source");
  claim.criterion = r.string(c, p, "measure");
  const std::string verdict = r.string(c, p, "verdict");
  if (verdict == kHolds) claim.holds = true;
  else if (verdict == kDoesNotHold) claim.holds = false;
  else if (verdict.empty()) r.fail(r.child(p, "verdict"), "is empty");
  else claim.note = verdict;
  for (const auto& [key, value] : c.items())
    if (!is_quality_key(key)) claim.measured[key] = value;
  return claim;
}

}  // namespace

std::string claim_verdict(const Claim& c) {
  if (c.holds) return *c.holds ? kHolds : kDoesNotHold;
  return c.note.rfind(kInconclusivePrefix, 0) == 0 ? "inconclusive" : "not measured";
}

std::string stated_verdict(const Claim& c) {
  if (c.holds) return *c.holds ? kHolds : kDoesNotHold;
  return c.note;
}

nlohmann::ordered_json to_json(const Claim& claim, ClaimLayout layout) {
  return layout == ClaimLayout::kTable ? table_json(claim) : quality_json(claim);
}

Claim claim_from_json(const JsonReader& reader, const nlohmann::ordered_json& value, const std::string& path,
                      ClaimLayout layout) {
  return layout == ClaimLayout::kTable ? read_table(reader, value, path) : read_quality(reader, value, path);
}

}  // namespace vsgl
