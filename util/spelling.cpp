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

namespace {

// The edit distance when it is below `limit`, else `limit`: only the band
// |i - j| < limit of the table can hold smaller values (Ukkonen), so the cost
// is O(length x limit), not O(length^2), and a 1 MB unknown name or 20 000
// long candidates cost milliseconds.
std::size_t boundedEditDistance(std::string_view a, std::string_view b, std::size_t limit, bool ignoreCase) {
  if (limit == 0) return 0;
  const std::size_t diff = a.size() > b.size() ? a.size() - b.size() : b.size() - a.size();
  if (diff >= limit) return limit;
  auto same = [&](char x, char y) {
    return ignoreCase ? std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y))
                      : x == y;
  };
  const std::size_t inf = limit;
  std::vector<std::size_t> prev(b.size() + 1, inf), cur(b.size() + 1, inf);
  for (std::size_t j = 0; j <= std::min(b.size(), limit); ++j) prev[j] = std::min(j, inf);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    const std::size_t lo = i >= limit ? i - limit + 1 : 1;
    const std::size_t hi = std::min(b.size(), i + limit - 1);
    // Cells left of the band hold values of two rows ago: the one the band reads is reset.
    cur[0] = i < limit ? i : inf;
    if (lo > 1) cur[lo - 1] = inf;
    std::size_t rowMin = lo == 1 ? cur[0] : inf;
    for (std::size_t j = lo; j <= hi; ++j) {
      const std::size_t v = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (same(a[i - 1], b[j - 1]) ? 0 : 1)});
      cur[j] = std::min(v, inf);
      rowMin = std::min(rowMin, cur[j]);
    }
    if (rowMin >= limit) return limit;
    prev.swap(cur);
  }
  return std::min(prev[b.size()], limit);
}

}  // namespace

std::string closestMatch(std::string_view name, const std::vector<std::string_view>& candidates, std::size_t limit,
                         bool ignoreCase) {
  std::string best;
  std::size_t bestD = limit;
  for (std::string_view c : candidates) {
    const std::size_t d = boundedEditDistance(name, c, bestD, ignoreCase);
    if (d < bestD) {
      bestD = d;
      best = std::string(c);
    }
  }
  return best;
}

}  // namespace mpr
