#pragma once
// The stepper page's own files (web/: index.html, stepper.css, stepper.js),
// embedded at build time so `mpr step --html` works without a source tree.
#include <string_view>
#include <utility>
#include <vector>

namespace mpr::cli {

// (file name, contents) for every file of web/, in name order.
const std::vector<std::pair<std::string_view, std::string_view>>& webAssets();

}  // namespace mpr::cli
