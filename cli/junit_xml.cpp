#include "cli/junit_xml.hpp"

#include <algorithm>

namespace mpr::cli {
namespace {

std::string escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      default: o += c;
    }
  }
  return o;
}

}  // namespace

std::string junitXml(const std::string& suite, const std::vector<JUnitCase>& cases) {
  const auto failures = std::count_if(cases.begin(), cases.end(),
                                      [](const JUnitCase& c) { return c.outcome == JUnitCase::Outcome::Failed; });
  const std::string counts = " tests=\"" + std::to_string(cases.size()) + "\" failures=\"" + std::to_string(failures) +
                             "\" errors=\"0\"";
  std::string o = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  o += "<testsuites name=\"" + escape(suite) + "\"" + counts + ">\n";
  o += "  <testsuite name=\"" + escape(suite) + "\"" + counts + " skipped=\"0\">\n";
  for (const JUnitCase& c : cases) {
    o += "    <testcase name=\"" + escape(c.name) + "\" classname=\"" + escape(c.classname) + "\"";
    if (c.outcome == JUnitCase::Outcome::Passed) {
      o += "/>\n";
      continue;
    }
    o += ">\n      <failure type=\"probe\" message=\"" + escape(c.message) + "\">" + escape(c.text) +
         "</failure>\n    </testcase>\n";
  }
  o += "  </testsuite>\n</testsuites>\n";
  return o;
}

}  // namespace mpr::cli
