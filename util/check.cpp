#include "util/check.hpp"

#include <cstdio>
#include <cstdlib>

namespace mpr::detail {

void checkFailed(const char* file, int line, const char* expression, const std::string& operands) {
  std::fprintf(stderr, "%s:%d: internal check failed: %s%s%s\n", file, line, expression, operands.empty() ? "" : " ",
               operands.c_str());
  std::abort();
}

}  // namespace mpr::detail
