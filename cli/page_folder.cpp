#include "cli/page_folder.hpp"

#include <fcntl.h>
#include <stdio.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>
#include <system_error>

#include "cli/output_set.hpp"
#include "util/atomic_file.hpp"
#include "util/signal_cleanup.hpp"

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

// ".DIR.WHAT-RANDOM": a hidden name beside the folder, not guessable.
std::string siblingName(const fs::path& dir, const std::string& what) {
  std::random_device rd;
  std::string name = ".";
  name += dir.filename().string();
  name += '.';
  name += what;
  name += '-';
  name += std::to_string(rd());
  return name;
}

std::runtime_error pageError(const fs::path& target, const std::string& step, int err) {
  return std::runtime_error("cannot " + step + " " + target.string() + ": " + std::strerror(err));
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
  // Every step is relative to the parent folder, opened once (and created,
  // like any output's, without following a link: cli/output_set), and the
  // page is filled through the new folder's own descriptor: another process
  // that can write beside the page cannot redirect a file by swapping a name.
  OutputSet parent("page");
  const int parentFd = parent.createFolder(target.parent_path().string());
  std::string tmpName;
  for (int attempt = 0;; ++attempt) {
    tmpName = siblingName(target, "new");
    if (::mkdirat(parentFd, tmpName.c_str(), 0777) == 0) break;
    if (errno != EEXIST || attempt == 100) throw pageError(target, "write", errno);
  }
  // An interrupt removes the half-made page (util/signal_cleanup).
  SignalCleanup cleanup(parentFd, tmpName, SignalCleanup::Kind::Folder);
  const int tmpFd = ::openat(parentFd, tmpName.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  const std::string name = target.filename().string();
  try {
    if (tmpFd < 0) throw pageError(target, "write", errno);
    for (const auto& [file, bytes] : files) {
      AtomicFile f(tmpFd, file, (target / file).string());
      f.write(bytes);
      f.commit();
    }
    AtomicFile marker(tmpFd, kMarker, (target / kMarker).string());
    marker.write(markerText(generator, files));
    marker.commit();
    // The hidden name must still hold the folder this process filled.
    struct stat mine {}, named {};
    if (::fstat(tmpFd, &mine) != 0 || ::fstatat(parentFd, tmpName.c_str(), &named, AT_SYMLINK_NOFOLLOW) != 0 ||
        mine.st_dev != named.st_dev || mine.st_ino != named.st_ino)
      throw std::runtime_error("cannot write " + target.string() + ": its new folder was replaced while it was written");
    struct stat st {};
    if (::fstatat(parentFd, name.c_str(), &st, AT_SYMLINK_NOFOLLOW) == 0) {
      // Checked again: the folder may have changed while the page was made.
      std::error_code ec;
      if (!S_ISDIR(st.st_mode) || (!fs::is_empty(target, ec) && !holdsPage(target, generator)))
        throw std::runtime_error(quotedPath(target.string(), "changed while the page was made and is no longer an earlier page"));
      // The new page and the earlier one trade places in one step; the
      // earlier one, now under the hidden name, is removed.
      if (::renameat2(parentFd, tmpName.c_str(), parentFd, name.c_str(), RENAME_EXCHANGE) != 0) {
        if (errno != EINVAL) throw pageError(target, "replace", errno);
        // A file system without the exchange: the earlier page aside, the
        // new one in, the earlier one under the hidden name again.
        const std::string old = siblingName(target, "old");
        if (::renameat(parentFd, name.c_str(), parentFd, old.c_str()) != 0) throw pageError(target, "replace", errno);
        if (::renameat(parentFd, tmpName.c_str(), parentFd, name.c_str()) != 0) {
          const int e = errno;
          ::renameat(parentFd, old.c_str(), parentFd, name.c_str());  // put the earlier page back
          throw pageError(target, "replace", e);
        }
        ::renameat(parentFd, old.c_str(), parentFd, tmpName.c_str());
      }
    } else if (::renameat2(parentFd, tmpName.c_str(), parentFd, name.c_str(), RENAME_NOREPLACE) != 0) {
      throw pageError(target, "write", errno);
    }
  } catch (...) {
    if (tmpFd >= 0) ::close(tmpFd);
    removeFlatFolder(parentFd, tmpName.c_str());
    cleanup.release();
    throw;
  }
  ::close(tmpFd);
  removeFlatFolder(parentFd, tmpName.c_str());  // the earlier page, if any
  cleanup.release();
  parent.commit();  // the folders made above the page stay
}

}  // namespace mpr::cli
