#pragma once
// Reading a user's input file (a script, a scene, a mesh) without trusting
// it: only a regular file is read (a folder is not an empty input, and a FIFO
// or a device such as /dev/zero would block or never end), and only up to a
// size limit, checked before reading.
#include <cstdint>
#include <string>

namespace mpr {

// Why `path` cannot be read as an input of at most `maxBytes`, or empty.
// `what` names the input in the message ("the script", "the mesh file").
std::string inputFileProblem(const std::string& path, std::uint64_t maxBytes, const std::string& what);

// The file's bytes; throws std::runtime_error with inputFileProblem's
// message (or the system's) on failure.
std::string readInputFile(const std::string& path, std::uint64_t maxBytes, const std::string& what);

}  // namespace mpr
