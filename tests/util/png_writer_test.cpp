// util/png_writer against OpenImageIO's PNG writer (the image module, through
// encodePngBytes): byte for byte the same file for every image drawn here
// (sizes from 1x1 to past 600x400; noise, gradients, flat colour, sparse
// specks, rows stored top-down and bottom-up), so that a render's PNG did
// not change when it stopped loading the module; the file decodes to its
// pixels; writeImageFile's direct path writes the same bytes, to the
// temporary path it is given.
#include "util/png_writer.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <vector>

#include "util/image_io.hpp"

namespace mpr {
namespace {

std::vector<std::uint8_t> drawnImage(int kind, int w, int h, std::mt19937& rng) {
  std::vector<std::uint8_t> px(static_cast<std::size_t>(w) * h * 3);
  for (std::size_t k = 0; k < px.size(); ++k) {
    const std::size_t x = k / 3 % static_cast<std::size_t>(w), y = k / 3 / static_cast<std::size_t>(w), c = k % 3;
    switch (kind) {
      case 0: px[k] = static_cast<std::uint8_t>(rng()); break;
      case 1: px[k] = static_cast<std::uint8_t>(x * 255 / static_cast<std::size_t>(w) + c * 40); break;
      case 2: px[k] = static_cast<std::uint8_t>(c == 1 ? 200 : 17); break;
      case 3: px[k] = static_cast<std::uint8_t>(y * 7 + c * 50); break;
      default: px[k] = rng() % 16 == 0 ? static_cast<std::uint8_t>(rng()) : 30; break;
    }
  }
  return px;
}

TEST(PngWriter, SameBytesAsOpenImageIo) {
  std::mt19937 rng(1994);
  for (int round = 0; round < 60; ++round) {
    const int w = 1 + static_cast<int>(rng() % (round < 30 ? 40 : 640));
    const int h = 1 + static_cast<int>(rng() % (round < 30 ? 40 : 420));
    const int kind = round % 5;
    const std::vector<std::uint8_t> px = drawnImage(kind, w, h, rng);
    const std::ptrdiff_t row = static_cast<std::ptrdiff_t>(w) * 3;
    const std::string where = std::to_string(w) + "x" + std::to_string(h) + " kind " + std::to_string(kind);
    ASSERT_EQ(encodeRgbPng(w, h, px.data(), row), encodePngBytes(w, h, 3, px.data(), row)) << where;
    const std::uint8_t* bottom = px.data() + (static_cast<std::size_t>(h) - 1) * static_cast<std::size_t>(row);
    ASSERT_EQ(encodeRgbPng(w, h, bottom, -row), encodePngBytes(w, h, 3, bottom, -row)) << where << ", bottom-up";
  }
}

TEST(PngWriter, DecodesToItsPixelsAndWritesThroughWriteImageFile) {
  std::mt19937 rng(1997);
  const int w = 37, h = 23;
  const std::vector<std::uint8_t> px = drawnImage(0, w, h, rng);
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("mpr-png-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const std::string target = (dir / "image.PNG").string();
  {
    AtomicFile file(target);
    writeImageFile(file, w, h, 3, px.data(), w * 3);
    file.commit();
  }
  std::ifstream in(target, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  EXPECT_EQ(bytes.str(), encodeRgbPng(w, h, px.data(), w * 3));
  const DecodedImage decoded = readImageFile(target);
  EXPECT_EQ(decoded.width, w);
  EXPECT_EQ(decoded.height, h);
  EXPECT_EQ(decoded.channels, 3);
  EXPECT_EQ(decoded.bytes, px);
  std::filesystem::remove_all(dir);
}

TEST(PngWriter, NamesPngFiles) {
  EXPECT_TRUE(namesPngFile("out/a.png"));
  EXPECT_TRUE(namesPngFile("A.PNG"));
  EXPECT_FALSE(namesPngFile("a.png.exr"));
  EXPECT_FALSE(namesPngFile("png"));
  EXPECT_FALSE(namesPngFile("a.tif"));
}

}  // namespace
}  // namespace mpr
