#pragma once
// The folder a stepper page is written to. The files are written to a fresh
// folder beside it and renamed into place at the end, so a failed or
// interrupted run leaves no half page: either the old folder or the new one.
// An existing folder is only replaced when it is empty or holds an earlier
// page: the marker file .mpr-page that MPR writes (naming the generator and
// every file), and nothing else; never a user's other files.
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace mpr::cli {

using PageFile = std::pair<std::string, std::string>;  // name in the folder, bytes

// Why `dir` cannot take the page, or empty when it can. An earlier page is
// recognised only by its marker (written by `generator`, e.g. "mpr step").
std::string pageFolderProblem(const std::string& dir, std::string_view generator);

// Writes every file and the marker, then puts the folder in place. Throws
// std::runtime_error.
void writePageFolder(const std::string& dir, std::string_view generator, const std::vector<PageFile>& files);

}  // namespace mpr::cli
