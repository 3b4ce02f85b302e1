#pragma once
// "Did you mean" for user input: the closest candidate by edit distance.
#include <string>
#include <string_view>
#include <vector>

namespace mpr {

// Levenshtein distance; `ignoreCase` compares ASCII letters case-insensitively.
std::size_t editDistance(std::string_view a, std::string_view b, bool ignoreCase = false);

// The candidate closest to `name` if it is fewer than `limit` edits away, else "".
std::string closestMatch(std::string_view name, const std::vector<std::string_view>& candidates, std::size_t limit,
                         bool ignoreCase = false);

}  // namespace mpr
