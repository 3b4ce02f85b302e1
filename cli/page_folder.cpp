#include "cli/page_folder.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

namespace mpr::cli {
namespace fs = std::filesystem;

namespace {

// "'DIR' why": built by appending, as GCC 12 warns falsely (-Wrestrict) on operator+ chains.
std::string quoted(const std::string& path, std::string_view why) {
  std::string o = "'";
  o += path;
  o += "' ";
  o += why;
  return o;
}

bool holdsPage(const fs::path& dir, std::string_view generator, std::string_view page) {
  std::ifstream in(dir / fs::path(page), std::ios::binary);
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  std::string meta = "<meta name=\"generator\" content=\"";
  meta += generator;
  meta += "\">";
  return head.find(meta) != std::string::npos;
}

// A name beside `dir` that nothing uses yet.
fs::path sibling(const fs::path& dir, const std::string& what) {
  std::string name = ".";
  name += dir.filename().string();
  name += '.';
  name += what;
  name += '-';
  name += std::to_string(getpid());
  const fs::path base = dir.parent_path() / name;
  fs::path p = base;
  for (int i = 1; fs::exists(fs::symlink_status(p)); ++i) p = fs::path(base.string() + '-' + std::to_string(i));
  return p;
}

}  // namespace

std::string pageFolderProblem(const std::string& dir, std::string_view generator, std::string_view page) {
  std::error_code ec;
  const fs::path p = fs::path(dir).lexically_normal();
  if (p.empty() || p.filename().empty() || p.filename() == "." || p.filename() == "..")
    return quoted(dir, "does not name a folder to write (give a new folder's name, e.g. out/page)");
  const fs::file_status st = fs::status(p, ec);
  if (fs::exists(st)) {
    if (!fs::is_directory(st)) return quoted(dir, "exists and is not a folder");
    if (!fs::is_empty(p, ec) && !holdsPage(p, generator, page))
      return quoted(dir, "is a folder with other files in it; give a new or empty folder (an earlier page there is replaced)");
  }
  // The nearest existing ancestor must be a folder (the rest is created).
  for (fs::path a = fs::absolute(p, ec).parent_path(); !a.empty(); a = a.parent_path()) {
    const fs::file_status as = fs::status(a, ec);
    if (!fs::exists(as)) {
      if (a == a.parent_path()) break;
      continue;
    }
    if (!fs::is_directory(as)) return quoted(a.string(), "is not a folder");
    break;
  }
  return "";
}

void writePageFolder(const std::string& dir, const std::vector<PageFile>& files) {
  const fs::path target = fs::absolute(fs::path(dir).lexically_normal());
  fs::create_directories(target.parent_path());
  const fs::path tmp = sibling(target, "new");
  try {
    fs::create_directory(tmp);
    for (const auto& [name, bytes] : files) {
      std::ofstream out(tmp / name, std::ios::binary);
      out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
      out.close();
      if (!out) throw std::runtime_error("cannot write " + (tmp / name).string());
    }
    if (fs::exists(fs::symlink_status(target))) {
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
