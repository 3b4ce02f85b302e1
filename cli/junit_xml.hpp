#pragma once
// JUnit XML for CI systems (the element and attribute set of Jenkins'
// junit-4 schema that CI readers require: testsuites, testsuite with name
// and tests, testcase with name and classname, failure and error).
#include <string>
#include <vector>

namespace mpr::cli {

struct JUnitCase {
  std::string name;       // the script's file name
  std::string classname;  // its folder, dotted
  enum class Outcome { Passed, Failed } outcome = Outcome::Passed;
  std::string message;    // the failure's first line
  std::string text;       // the failure's whole explanation
};

std::string junitXml(const std::string& suite, const std::vector<JUnitCase>& cases);

}  // namespace mpr::cli
