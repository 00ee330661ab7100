#include "harness/core/line_diff.hpp"

#include <algorithm>

namespace vsgl {

LineDiff diff_lines(const std::vector<std::string>& from, const std::vector<std::string>& to) {
  // Length of the longest common subsequence, one row of the table at a time.
  std::vector<uint32_t> previous(to.size() + 1, 0), current(to.size() + 1, 0);
  for (const std::string& a : from) {
    for (std::size_t j = 0; j < to.size(); ++j)
      current[j + 1] = a == to[j] ? previous[j] + 1 : std::max(previous[j + 1], current[j]);
    std::swap(previous, current);
  }
  const uint32_t common = previous[to.size()];
  return LineDiff{static_cast<uint32_t>(from.size()) - common, static_cast<uint32_t>(to.size()) - common};
}

}  // namespace vsgl
