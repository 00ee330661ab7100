#pragma once
// How many lines two texts differ by, as a line diff counts them (DESIGN.md §10: the lines in
// which the two FIS generators differ, Table 3). Lines are compared as given; the longest common
// subsequence of the two sequences is what they share, the rest was removed or added.
#include <cstdint>
#include <string>
#include <vector>

namespace vsgl {

struct LineDiff {
  uint32_t removed = 0;  // lines of `from` outside the common subsequence
  uint32_t added = 0;    // lines of `to` outside it
  uint32_t differing() const { return removed + added; }
};

LineDiff diff_lines(const std::vector<std::string>& from, const std::vector<std::string>& to);

}  // namespace vsgl
