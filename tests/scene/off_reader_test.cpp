// OFF files read by MPR (scene/off_reader): a well-formed file gives the mesh
// OpenMesh's own reader gives, bit for bit; a malformed one is refused with
// its line and column, before anything is reserved for it.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "scene/mesh_file_test_helpers.hpp"
#include "scene/mesh_loader.hpp"
#include "scene/off_reader.hpp"

// A namespace of its own: the suite is compiled in batches (unity builds).
namespace mpr::off_reader_test {
namespace {

using namespace std::string_literals;

std::string errorOf(const std::string& text) {
  try {
    parseOff(text, "m.off");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "no error";
}

TEST(OffReader, SampleMeshesAsOpenMeshReadsThem) {
  for (const char* file : {"scenes/meshes/bottle.off", "tests/conformance/scenes/torus.off"}) {
    SCOPED_TRACE(file);
    const std::string path = std::string(MPR_SOURCE_DIR) + "/" + file;
    expectSameMesh(loadMeshFile(path), loadWithOpenMesh(path));
  }
}

// Random well-formed files: coordinates spelt every way a stream reads
// (signs, no leading digit, exponents, more digits than a float holds),
// faces of 3 to 6 corners, some of them non-manifold (OpenMesh's importer
// then duplicates vertices: the same importer runs on both sides); NOFF with
// normals, COFF with vertex and face colours. (Comments, and colours after a
// plain OFF face, OpenMesh's reader misreads: CountsOnTheOffLine... below.)
TEST(OffReader, RandomFilesAsOpenMeshReadsThem) {
  std::mt19937 rng(7);
  auto coordinate = [&]() {
    std::uniform_real_distribution<double> u(-50, 50);
    char buf[64];
    switch (rng() % 5) {
      case 0: std::snprintf(buf, sizeof buf, "%.17g", u(rng)); break;
      case 1: std::snprintf(buf, sizeof buf, "%+.3e", u(rng)); break;
      case 2: std::snprintf(buf, sizeof buf, "%d", static_cast<int>(u(rng))); break;
      case 3: std::snprintf(buf, sizeof buf, ".%u", static_cast<unsigned>(rng() % 1000)); break;
      default: std::snprintf(buf, sizeof buf, "%.9gE-2", u(rng)); break;
    }
    return std::string(buf);
  };
  for (int file = 0; file < 60; ++file) {
    const char* kind = file % 3 == 0 ? "OFF" : file % 3 == 1 ? "NOFF" : "COFF";
    const int vertices = 4 + static_cast<int>(rng() % 40), faces = 1 + static_cast<int>(rng() % 40);
    std::ostringstream s;
    s << kind << "\n" << vertices << ' ' << faces << " 0\n";
    for (int v = 0; v < vertices; ++v) {
      s << coordinate() << ' ' << coordinate() << "\t" << coordinate();
      if (kind[0] == 'N') s << " 0 0 1";
      if (kind[0] == 'C' && rng() % 2) s << " 0.5 0.25 1";
      s << "\n";
    }
    for (int f = 0; f < faces; ++f) {
      const int k = 3 + static_cast<int>(rng() % static_cast<unsigned>(std::min(4, vertices - 2)));
      std::vector<int> idx(static_cast<std::size_t>(vertices));
      for (int i = 0; i < vertices; ++i) idx[static_cast<std::size_t>(i)] = i;
      std::shuffle(idx.begin(), idx.end(), rng);
      s << k;
      for (int i = 0; i < k; ++i) s << ' ' << idx[static_cast<std::size_t>(i)];
      if (kind[0] == 'C' && rng() % 2) s << " 255 0 0";
      s << "\n";
    }
    const std::string path = writeFile("random" + std::to_string(file) + ".off", s.str());
    SCOPED_TRACE(s.str());
    expectSameMesh(loadMeshFile(path), loadWithOpenMesh(path));
  }
}

TEST(OffReader, BinaryAsOpenMeshReadsIt) {
  std::string b = "OFF BINARY\n";
  auto u32 = [&](std::uint32_t v) {
    for (int i = 0; i < 4; ++i) b.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
  };
  auto f32 = [&](float f) {
    std::uint32_t v;
    std::memcpy(&v, &f, 4);
    u32(v);
  };
  u32(4), u32(2), u32(0);
  for (float c : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 1.f, 1.f, 0.25f, 0.f, 1.f, 0.5f}) f32(c);
  u32(3), u32(0), u32(1), u32(2);
  u32(3), u32(0), u32(2), u32(3);
  const std::string path = writeFile("binary.off", b);
  const Mesh m = loadMeshFile(path);
  EXPECT_EQ(m.positions.size(), 4u);
  EXPECT_EQ(m.faces, (std::vector<std::vector<std::uint32_t>>{{0, 1, 2}, {0, 2, 3}}));
  EXPECT_EQ(m.positions[3], Vec3(0, 1, 0.5f));
  expectSameMesh(m, loadWithOpenMesh(path));

  std::string huge = b.substr(0, b.size() - 32);  // the faces go; one claims 2^32 - 1 corners
  b = huge;
  u32(0xffffffffu), u32(0);
  EXPECT_EQ(errorOf(b), "mesh file 'm.off' byte 71: face 0 claims 4294967295 vertices; a face has 1 to 4 and the file "
                        "must hold them");
  EXPECT_EQ(errorOf(huge.substr(0, 40)), "mesh file 'm.off' byte 11: claims 4 vertices and 2 faces, more than its 40 "
                                         "bytes can hold");
  EXPECT_EQ(errorOf("OFF BINARY\n\1\0\0"), "mesh file 'm.off' byte 11: the file ends inside the vertex count");
  EXPECT_EQ(errorOf("COFF BINARY\n"), "mesh file 'm.off' line 1 column 6: only a plain 'OFF BINARY' line is read in binary");
}

TEST(OffReader, CountsOnTheOffLineAndCommentsAnywhere) {
  const PolygonFile m = parseOff("# made by hand\nOFF 3 1 0 # counts here\n0 0 0\n1 0 0 # x\n\n0 1 0\n3 0 1 2\n", "m.off");
  ASSERT_EQ(m.points.size(), 3u);
  EXPECT_EQ(m.points[1], (std::array<float, 3>{1, 0, 0}));
  EXPECT_EQ(m.faces, (std::vector<std::vector<std::uint32_t>>{{0, 1, 2}}));
  const PolygonFile split = parseOff("OFF 3\n1\n0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "m.off");
  EXPECT_EQ(split.faces.size(), 1u);
}

// The file mesh_fuzzer found: a face line "1 0 1-3 ..." that OpenMesh's
// token stream read so that "-3" became the next face's 2^32 - 3 corners.
TEST(OffReader, RefusesMalformedFilesWithLineAndColumn) {
  const std::string found = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 0 1\n3 0 2 3\n1 0 0 4 3\n1 0 1-3  2 1 3\n3 0 3 2\n3 0 2 3 0(2 3\n";
  EXPECT_EQ(parseOff(found, "m.off").faces, (std::vector<std::vector<std::uint32_t>>{{0}, {0}, {0, 3, 2}, {0, 2, 3}}));
  EXPECT_EQ(loadMeshFile(writeFile("found.off", found)).faces.size(), 2u);  // the importer drops 1-corner faces
  EXPECT_EQ(errorOf("OFF\n4 1 0\n0 0 0\n1 0 0\n0 0 1\n0 1 0\n3 0 1-3 2\n"),
            "mesh file 'm.off' line 7 column 5: a vertex index is a plain number below 4, not '1-3'");
  EXPECT_EQ(errorOf("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n-3 0 1 2\n"),
            "mesh file 'm.off' line 6 column 1: a face starts with its vertex count, 1 to 3, not '-3'");
  EXPECT_EQ(errorOf("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2 2\n"),
            "mesh file 'm.off' line 6 column 1: a face starts with its vertex count, 1 to 3, not '4'");
  EXPECT_EQ(errorOf("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1\n"),
            "mesh file 'm.off' line 6 column 1: a face of 3 vertices needs 3 indices; the line has 2");
  EXPECT_EQ(errorOf("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"),
            "mesh file 'm.off' line 6 column 7: a vertex index is a plain number below 3, not '3'");
  EXPECT_EQ(errorOf("OFF\n3 1 0\n0 0 0\n1 0x1p3 0\n0 1 0\n3 0 1 2\n"),
            "mesh file 'm.off' line 4 column 3: '0x1p3' is not a finite decimal number");
  EXPECT_EQ(errorOf("OFF\n3 1 0\n0 0 0\n1 1e39 0\n0 1 0\n3 0 1 2\n"),
            "mesh file 'm.off' line 4 column 3: '1e39' is not a finite decimal number");
  EXPECT_EQ(errorOf("OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n"),
            "mesh file 'm.off' line 4 column 3: 'nan' is not a finite decimal number");
  EXPECT_EQ(errorOf("OFF\n3 1 0\n0 0 0\n1 0\n"), "mesh file 'm.off' line 4 column 1: a vertex needs three numbers (x y z)");
  EXPECT_EQ(errorOf("OFF\n3 1 0\n0 0 0\n1 0 0\n"), "mesh file 'm.off' line 4 column 1: the file ends after 2 of its 3 vertices");
  EXPECT_EQ(errorOf("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
            "mesh file 'm.off' line 6 column 1: the file ends after 1 of its 2 faces");
  EXPECT_EQ(errorOf("OFF\n2000000000 2000000000 0\n"),
            "mesh file 'm.off' line 2 column 1: claims 2000000000 vertices and 2000000000 faces, more than its 28 bytes "
            "can hold");
  EXPECT_EQ(errorOf("OFF\n3 -1 0\n"), "mesh file 'm.off' line 2 column 3: the face count '-1' is not a plain number below 2^32");
  EXPECT_EQ(errorOf("OFF\n3 1 0 7\n"), "mesh file 'm.off' line 2 column 7: '7' follows the three counts on their line");
  EXPECT_EQ(errorOf("OFF\n3 1\n"), "mesh file 'm.off' line 2 column 1: has no edge count after OFF");
  EXPECT_EQ(errorOf("OFF\n"), "mesh file 'm.off' line 1 column 1: has no vertex and face counts after OFF");
  EXPECT_EQ(errorOf(""), "mesh file 'm.off' line 1 column 1: is empty: an OFF file starts with OFF");
  EXPECT_EQ(errorOf("\0OFF\n"s), "mesh file 'm.off' line 1 column 1: does not start with OFF (or STOFF, COFF, NOFF)");
  EXPECT_EQ(errorOf("4OFF\n"), "mesh file 'm.off' line 1 column 1: 4OFF and nOFF (vertices of other than three "
                               "coordinates) are not supported");
}

}  // namespace
}  // namespace mpr::off_reader_test
