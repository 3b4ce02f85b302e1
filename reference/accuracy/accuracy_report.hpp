#pragma once
// What `mpr accuracy` found, and its forms: results.csv and results.json
// (one row per setting), report.html (opens from file://: images beside the
// reference, difference images, the sortable table, the plot).
#include <string>
#include <vector>

#include "reference/accuracy/image_error.hpp"

namespace mpr {

struct AccuracyRow {
  std::string label;                 // "scene", "render.recursion_depth=3", "single pass"
  std::vector<std::string> values;   // one per AccuracyReport::keys: the value this row rendered with
  double seconds = 0.0, estimatedSeconds = 0.0;
  std::uint64_t views = 0, lightPasses = 0, shadowPasses = 0, glCalls = 0, fragments = 0;
  ImageError error;
  std::string image, difference;     // paths relative to the report folder
};

struct AccuracyReport {
  std::string scene;
  int width = 0, height = 0, repeat = 0;
  std::vector<std::string> keys;     // the varied keys, by full name
  std::vector<AccuracyRow> rows;     // in sweep order
  AccuracyRow singlePass;            // every multi-pass effect off
  std::string reference;             // how the reference was made (or the file it came from)
  std::string referenceImage;        // relative path
  double referenceSeconds = 0.0;     // 0 when read from a file
};

// The rows on the Pareto front of (seconds, rms): no other row is at least
// as fast and as accurate and better in one. Indices into `rows`.
std::vector<std::size_t> paretoFront(const std::vector<AccuracyRow>& rows);

std::string resultsCsv(const AccuracyReport& r);
std::string resultsJson(const AccuracyReport& r);
std::string reportHtml(const AccuracyReport& r, const std::string& plotSvg);

}  // namespace mpr
