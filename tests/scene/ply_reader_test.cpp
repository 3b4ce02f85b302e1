// PLY files read by MPR (scene/ply_reader): ASCII and binary files of the
// shapes OpenMesh's reader handles give its mesh bit for bit; a malformed
// one is refused with its line and column (binary: byte) before anything is
// reserved for it.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "scene/mesh_file_test_helpers.hpp"
#include "scene/mesh_loader.hpp"
#include "scene/ply_reader.hpp"

// A namespace of its own: the suite is compiled in batches (unity builds).
namespace mpr::ply_reader_test {
namespace {

std::string errorOf(const std::string& bytes) {
  try {
    parsePly(bytes, "m.ply");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "no error";
}

// Writes values in one of PLY's three formats.
struct PlyWriter {
  explicit PlyWriter(std::string f) : format(std::move(f)) {}
  std::string format;  // ascii, binary_little_endian, binary_big_endian
  std::ostringstream out;
  bool firstOnLine = true;
  template <class T>
  void put(T v) {
    if (format == "ascii") {
      if (!firstOnLine) out << ' ';
      firstOnLine = false;
      if constexpr (std::is_floating_point_v<T>) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(v));
        out << buf;
      } else {
        out << static_cast<long long>(v);
      }
      return;
    }
    unsigned char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    if (format == "binary_big_endian") std::reverse(b, b + sizeof(T));
    out.write(reinterpret_cast<const char*>(b), sizeof(T));
  }
  void endItem() {
    if (format == "ascii") out << '\n';
    firstOnLine = true;
  }
};

TEST(PlyReader, RandomFilesAsOpenMeshReadsThem) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-50, 50);
  const char* formats[] = {"ascii", "binary_little_endian", "binary_big_endian"};
  for (int file = 0; file < 60; ++file) {
    PlyWriter w{formats[file % 3]};
    const bool doubles = file % 4 == 1, normals = file % 5 < 2, colours = file % 7 < 3, intCounts = file % 2 == 0;
    const int vertices = 4 + static_cast<int>(rng() % 40), faces = 1 + static_cast<int>(rng() % 40);
    std::ostringstream h;
    h << "ply\nformat " << w.format << " 1.0\ncomment random " << file << "\nelement vertex " << vertices << "\n";
    for (const char* axis : {"x", "y", "z"}) h << "property " << (doubles ? "double " : "float ") << axis << "\n";
    if (normals) h << "property float nx\nproperty float ny\nproperty float nz\n";
    if (colours) h << "property uchar red\nproperty uchar green\nproperty uchar blue\n";
    h << "element face " << faces << "\nproperty list " << (intCounts ? "int" : "uchar") << " "
      << (file % 3 == 0 ? "uint" : "int") << " vertex_indices\nend_header\n";
    for (int v = 0; v < vertices; ++v) {
      for (int c = 0; c < 3; ++c) doubles ? w.put(u(rng)) : w.put(static_cast<float>(u(rng)));
      if (normals) w.put(0.0f), w.put(0.0f), w.put(1.0f);
      if (colours) w.put<std::uint8_t>(200), w.put<std::uint8_t>(10), w.put<std::uint8_t>(3);
      w.endItem();
    }
    for (int f = 0; f < faces; ++f) {
      const int k = 3 + static_cast<int>(rng() % static_cast<unsigned>(std::min(4, vertices - 2)));
      std::vector<int> idx(static_cast<std::size_t>(vertices));
      for (int i = 0; i < vertices; ++i) idx[static_cast<std::size_t>(i)] = i;
      std::shuffle(idx.begin(), idx.end(), rng);
      intCounts ? w.put<std::int32_t>(k) : w.put<std::uint8_t>(static_cast<std::uint8_t>(k));
      for (int i = 0; i < k; ++i) w.put<std::int32_t>(idx[static_cast<std::size_t>(i)]);
      w.endItem();
    }
    const std::string path = writeFile("random" + std::to_string(file) + ".ply", h.str() + w.out.str());
    SCOPED_TRACE(path + "\n" + h.str());
    expectSameMesh(loadMeshFile(path), loadWithOpenMesh(path));
  }
}

const std::string kHead =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n";

TEST(PlyReader, ListsOtherThanCornersAreSkippedWhole) {
  const PolygonFile f = parsePly(
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty list uchar float weights\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n"
      "property list uchar float texcoord\nelement edge 5\nproperty int a\nend_header\n"
      "2 0.5 0.5 0 0 0\n0 1 0 0\n1 9 0 1 0\n3 0 1 2 6 0 0 1 0 0 1\n",
      "m.ply");
  ASSERT_EQ(f.points.size(), 3u);
  EXPECT_EQ(f.points[2], (std::array<float, 3>{0, 1, 0}));
  EXPECT_EQ(f.faces, (std::vector<std::vector<std::uint32_t>>{{0, 1, 2}}));
}

// The shapes that made OpenMesh ask for gigabytes: a negative or huge list
// count, read as an unsigned int.
TEST(PlyReader, RefusesMalformedFilesWithLineAndColumn) {
  EXPECT_EQ(errorOf(kHead + "0 0 0\n1 0 0\n0 1 0\n-3 0 1 2\n"),
            "mesh file 'm.ply' line 13 column 1: a list's length is a plain number up to the vertex count 3, not '-3'");
  EXPECT_EQ(errorOf(kHead + "0 0 0\n1 0 0\n0 1 0\n4294967295 0 1 2\n"),
            "mesh file 'm.ply' line 13 column 1: a list's length is a plain number up to the vertex count 3, not "
            "'4294967295'");
  EXPECT_EQ(errorOf(kHead + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"),
            "mesh file 'm.ply' line 13 column 7: a vertex index is a plain number below 3, not '3'");
  EXPECT_EQ(errorOf(kHead + "0 0 0\n1 inf 0\n0 1 0\n3 0 1 2\n"),
            "mesh file 'm.ply' line 11 column 3: 'inf' is not a finite decimal number");
  EXPECT_EQ(errorOf(kHead + "0 0 0\n1 0 0\n0 1 0\n3 0 1\n"), "mesh file 'm.ply' line 14 column 1: the file ends inside face 0 of 1");
  EXPECT_EQ(errorOf("ply\nformat ascii 1.0\nelement vertex 2000000000\nproperty float x\nproperty float y\n"
                    "property float z\nend_header\n0 0 0\n"),
            "mesh file 'm.ply' line 8 column 1: claims 2000000000 vertices and 0 faces, more than its 115 bytes can hold");
  EXPECT_EQ(errorOf("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n"),
            "mesh file 'm.ply' line 6 column 1: its vertex element has no 'z' property");
  EXPECT_EQ(errorOf("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_headeaaaa\n"),
            "mesh file 'm.ply' line 5 column 1: has a header line PLY does not know: 'end_headeaaaa'");
  EXPECT_EQ(errorOf("ply\nformat ascii 1.0\nelement vertex 1\n"),
            "mesh file 'm.ply' line 3 column 1: has no end_header line closing its header");
  EXPECT_EQ(errorOf("ply\nformat ascii 1.0\nelement face 1\nproperty list float int vertex_indices\nend_header\n"),
            "mesh file 'm.ply' line 4 column 1: a list's count must have an integer type: 'property list float int "
            "vertex_indices'");
  EXPECT_EQ(errorOf("plyx\n"), "mesh file 'm.ply' line 1 column 1: does not start with ply");

  // Issue 48: an element other than vertex and face that the bytes cannot
  // hold is named, not reported as the vertex and face counts.
  const std::string edges = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                            "property float z\nelement edge 2000000000\nproperty int a\nelement face 1\n"
                            "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  EXPECT_EQ(errorOf(edges), "mesh file 'm.ply' line 12 column 1: its element 'edge' claims 2000000000 items, more than "
                            "its " + std::to_string(edges.size()) + " bytes can hold after the elements before it");
  const std::string first = "ply\nformat ascii 1.0\nelement material 4000000000\nelement vertex 3\nproperty float x\n"
                            "property float y\nproperty float z\nend_header\n0 0 0\n";
  EXPECT_EQ(errorOf(first), "mesh file 'm.ply' line 9 column 1: its element 'material' claims 4000000000 items, more "
                            "than its " + std::to_string(first.size()) + " bytes can hold");

  // Binary: a uint count of 2^32 - 1 corners.
  std::string b = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                  "property float z\nelement face 1\nproperty list uint int vertex_indices\nend_header\n";
  const std::size_t body = b.size();
  b += std::string(36, '\0');
  b += std::string("\xff\xff\xff\xff", 4) + std::string(12, '\0');
  EXPECT_EQ(errorOf(b), "mesh file 'm.ply' byte " + std::to_string(body + 36) +
                            ": face 0 has a list of 4294967295 values, more than its vertices or the file holds");
  EXPECT_EQ(errorOf(b.substr(0, body + 30)),
            "mesh file 'm.ply' line 10 column 1: claims 3 vertices and 1 faces, more than its " +
                std::to_string(body + 30) + " bytes can hold");
}

}  // namespace
}  // namespace mpr::ply_reader_test
