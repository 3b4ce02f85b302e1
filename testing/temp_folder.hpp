#pragma once
// A fresh folder under /tmp for one test, removed with everything in it
// when the test ends.
#include <stdlib.h>

#include <cstddef>
#include <filesystem>
#include <iterator>
#include <string>

namespace mpr::testing {

struct TempFolder {
  explicit TempFolder(const std::string& prefix = "mpr-test") {
    std::string t = "/tmp/" + prefix + "-XXXXXX";
    if (mkdtemp(t.data()) != nullptr) path = t;
  }
  ~TempFolder() {
    std::error_code ignored;
    if (!path.empty()) std::filesystem::remove_all(path, ignored);
  }
  // How many entries a folder holds (a test's count of what a run left).
  static std::size_t entryCount(const std::filesystem::path& dir) {
    return static_cast<std::size_t>(
        std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()));
  }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;
  std::filesystem::path path;
};

}  // namespace mpr::testing
