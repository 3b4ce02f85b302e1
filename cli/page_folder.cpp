#include "cli/page_folder.hpp"

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>
#include <system_error>

#include "util/atomic_file.hpp"

namespace mpr::cli {
namespace fs = std::filesystem;

namespace {

// The marker MPR writes into every page folder: the generator on the first
// line, then every file it wrote. A folder is an earlier page only when the
// marker says so and holds nothing else: a lookalike index.html is not
// enough, and no file of the user's is ever removed.
constexpr const char* kMarker = ".mpr-page";

std::string markerText(std::string_view generator, const std::vector<PageFile>& files) {
  std::string m(generator);
  m += '\n';
  for (const auto& f : files) {
    m += f.first;
    m += '\n';
  }
  return m;
}

bool holdsPage(const fs::path& dir, std::string_view generator) {
  std::error_code ec;
  if (!fs::is_regular_file(fs::symlink_status(dir / kMarker, ec))) return false;
  std::ifstream in(dir / kMarker, std::ios::binary);
  std::string text(1 << 16, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  std::vector<std::string> lines;
  for (std::size_t a = 0, b; a < text.size(); a = b + 1) {
    b = text.find('\n', a);
    if (b == std::string::npos) return false;  // cut short: not ours
    lines.push_back(text.substr(a, b - a));
  }
  if (lines.empty() || lines[0] != generator) return false;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (name == kMarker) continue;
    if (std::find(lines.begin() + 1, lines.end(), name) == lines.end()) return false;
    if (!fs::is_regular_file(e.symlink_status(ec))) return false;
  }
  return !ec;
}

// A name beside `dir` that nothing uses yet (random, so not guessable).
fs::path sibling(const fs::path& dir, const std::string& what) {
  std::random_device rd;
  for (;;) {
    std::string name = ".";
    name += dir.filename().string();
    name += '.';
    name += what;
    name += '-';
    name += std::to_string(rd());
    const fs::path p = dir.parent_path() / name;
    if (!fs::exists(fs::symlink_status(p))) return p;
  }
}

}  // namespace

std::string pageFolderProblem(const std::string& dir, std::string_view generator) {
  std::error_code ec;
  const fs::path p = fs::path(dir).lexically_normal();
  if (p.empty() || p.filename().empty() || p.filename() == "." || p.filename() == "..")
    return quotedPath(dir, "does not name a folder to write (give a new folder's name, e.g. out/page)");
  const fs::file_status st = fs::symlink_status(p, ec);
  if (fs::exists(st)) {
    if (!fs::is_directory(st)) return quotedPath(dir, "exists and is not a folder");
    if (!fs::is_empty(p, ec) && !holdsPage(p, generator))
      return quotedPath(dir, "is a folder with other files in it; give a new or empty folder (an earlier page MPR wrote, "
                         "with its .mpr-page marker and nothing else, is replaced)");
  }
  // The nearest existing ancestor must be a folder (the rest is created).
  return existingAncestorProblem(fs::absolute(p, ec).parent_path());
}

void writePageFolder(const std::string& dir, std::string_view generator, const std::vector<PageFile>& files) {
  const fs::path target = fs::absolute(fs::path(dir).lexically_normal());
  fs::create_directories(target.parent_path());
  const fs::path tmp = sibling(target, "new");
  try {
    if (!fs::create_directory(tmp)) throw std::runtime_error("cannot create " + tmp.string() + ": it exists");
    for (const auto& [name, bytes] : files) writeFileAtomically((tmp / name).string(), bytes);
    writeFileAtomically((tmp / kMarker).string(), markerText(generator, files));
    if (fs::exists(fs::symlink_status(target))) {
      // Checked again: the folder may have changed while the page was made.
      std::error_code ec;
      if (!fs::is_directory(fs::symlink_status(target)) || (!fs::is_empty(target, ec) && !holdsPage(target, generator)))
        throw std::runtime_error(quotedPath(target.string(), "changed while the page was made and is no longer an earlier page"));
      const fs::path old = sibling(target, "old");
      fs::rename(target, old);
      try {
        fs::rename(tmp, target);
      } catch (...) {
        std::error_code ec;
        fs::rename(old, target, ec);  // put the earlier page back
        throw;
      }
      fs::remove_all(old);
    } else {
      fs::rename(tmp, target);
    }
  } catch (const fs::filesystem_error& e) {
    std::error_code ec;
    fs::remove_all(tmp, ec);
    throw std::runtime_error(e.what());
  } catch (...) {
    std::error_code ec;
    fs::remove_all(tmp, ec);
    throw;
  }
}

}  // namespace mpr::cli
