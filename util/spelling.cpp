#include "util/spelling.hpp"

#include <algorithm>
#include <cctype>

namespace mpr {

std::size_t editDistance(std::string_view a, std::string_view b, bool ignoreCase) {
  auto same = [&](char x, char y) {
    return ignoreCase ? std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y))
                      : x == y;
  };
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j)
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (same(a[i - 1], b[j - 1]) ? 0 : 1)});
    prev.swap(cur);
  }
  return prev[b.size()];
}

std::string closestMatch(std::string_view name, const std::vector<std::string_view>& candidates, std::size_t limit,
                         bool ignoreCase) {
  std::string best;
  std::size_t bestD = limit;
  for (std::string_view c : candidates) {
    const std::size_t d = editDistance(name, c, ignoreCase);
    if (d < bestD) {
      bestD = d;
      best = std::string(c);
    }
  }
  return best;
}

}  // namespace mpr
