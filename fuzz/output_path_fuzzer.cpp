// The output checks and the one output writer (cli/output_set, issue 48):
// the input is a small program that lays out a sandbox folder (files,
// folders, links, dangling links, hard links) and names inputs, output files
// and output folders in it by any spelling. Whatever problem() accepts must
// then be written without touching an input (every input's bytes compared
// after the commit) and each output must hold its own bytes; what it
// refuses is refused before anything is written. Paths stay in the sandbox
// (no '..', no absolute paths, links only to names in it).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/output_set.hpp"

namespace fs = std::filesystem;

namespace {

// One folder for the process, emptied for each input, removed at exit.
struct Sandbox {
  fs::path root = fs::temp_directory_path() / ("mpr-output-fuzz-" + std::to_string(getpid()));
  ~Sandbox() {
    std::error_code ec;
    fs::remove_all(root, ec);
  }
};

const fs::path& sandbox() {
  static const Sandbox s;
  return s.root;
}

// A name in the sandbox: no '..', not absolute, not empty, short.
bool safe(const std::string& rel) {
  if (rel.empty() || rel.size() > 64 || rel.front() == '/' || rel.find('\0') != std::string::npos) return false;
  for (const fs::path& part : fs::path(rel))
    if (part == "..") return false;
  return true;
}

std::string contents(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::error_code ec;
  fs::remove_all(sandbox(), ec);
  fs::create_directories(sandbox());
  const fs::path& root = sandbox();
  std::istringstream text(std::string(reinterpret_cast<const char*>(data), size));
  mpr::cli::OutputSet outputs("fuzz");
  std::vector<std::string> inputs, files, folders;
  std::string line;
  for (int ops = 0; ops < 24 && std::getline(text, line); ++ops) {
    if (line.size() < 3 || line[1] != ' ') continue;
    const std::string arg = line.substr(2);
    const std::size_t space = arg.find(' ');
    const std::string a = arg.substr(0, space), b = space == std::string::npos ? "" : arg.substr(space + 1);
    if (!safe(a)) continue;
    switch (line[0]) {
      case 'f':  // a file
        fs::create_directories((root / a).parent_path(), ec);
        std::ofstream(root / a, std::ios::binary) << "in:" << a;
        break;
      case 'd':
        fs::create_directories(root / a, ec);
        break;
      case 'l':  // a link to a name in the sandbox (it may dangle)
        if (safe(b)) fs::create_symlink(root / b, root / a, ec);
        break;
      case 'h':
        if (safe(b)) fs::create_hard_link(root / b, root / a, ec);
        break;
      case 'i':
        if (fs::is_regular_file(root / a, ec)) inputs.push_back((root / a).string());
        break;
      case 'o':
        files.push_back((root / a).string());
        break;
      case 'D':
        folders.push_back((root / a).string());
        break;
      default:
        break;
    }
  }
  for (const std::string& in : inputs) outputs.addInput("the input", in);
  for (const std::string& f : files) outputs.addFile("-o", f);
  for (const std::string& d : folders) outputs.addFolder("--dump", d, {"color.npy"}, ".npy");
  std::map<std::string, std::string> before;
  for (const std::string& in : inputs) before[in] = contents(in);
  if (!outputs.problem().empty()) return 0;
  bool written = true;
  try {
    for (const std::string& f : files) outputs.write(f, "out:" + f);
    for (const std::string& d : folders) outputs.write((fs::path(d) / "color.npy").string(), "dump:" + d);
    outputs.commit();
  } catch (const std::runtime_error&) {
    written = false;  // a write refused (a name made unwritable, a full disk): the inputs still hold
  }
  for (const auto& [in, bytes] : before)
    if (contents(in) != bytes) std::abort();  // an accepted output replaced an input
  if (written) {
    for (const std::string& f : files)
      if (contents(f) != "out:" + f) std::abort();  // two outputs wrote one file
    for (const std::string& d : folders)
      if (contents(fs::path(d) / "color.npy") != "dump:" + d) std::abort();
  }
  return 0;
}
