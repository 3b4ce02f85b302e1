// Reference images on disk: quantised as the pipeline quantises, read back.
#include "reference/reference_image.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace mpr {
namespace {

ReferenceImage twoByTwo() {
  ReferenceImage im;
  im.width = 2, im.height = 2;
  // Bottom row first. 0.5 * 255 = 127.5 rounds to even (128); 2.5 / 255 * 255
  // rounds as float arithmetic gives it; out of range clamps.
  im.rgb = {0.0f, 0.5f, 1.0f, -1.0f, 2.0f, 0.25f, 0.1f, 0.2f, 0.3f, 1.0f, 1.0f, 1.0f};
  return im;
}

TEST(ReferenceImage, QuantisesAsThePipeline) {
  const std::vector<std::uint8_t> q = quantiseToRgb8(twoByTwo());
  // 0.5 * 255 = 127.5: ties to even, 128; 0.25 * 255 = 63.75: 64; 0.1 * 255 = 25.5 (in float
  // 25.500000372529): 26; 0.2 * 255 = 51.000001: 51; 0.3 * 255 = 76.5 (76.499999): 76.
  EXPECT_EQ(q, (std::vector<std::uint8_t>{0, 128, 255, 0, 255, 64, 26, 51, 76, 255, 255, 255}));
}

TEST(ReferenceImage, PngAndExrRoundTrip) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "mpr_reference_image_test";
  std::filesystem::create_directories(dir);
  const ReferenceImage im = twoByTwo();
  writeReferenceImage(im, (dir / "x.png").string());
  writeReferenceImage(im, (dir / "x.exr").string());
  const ReferenceImage png = readReferenceImage((dir / "x.png").string());
  const ReferenceImage exr = readReferenceImage((dir / "x.exr").string());
  ASSERT_EQ(png.width, 2);
  ASSERT_EQ(png.height, 2);
  const std::vector<std::uint8_t> q = quantiseToRgb8(im);
  for (std::size_t i = 0; i < q.size(); ++i) {
    EXPECT_FLOAT_EQ(png.rgb[i], q[i] / 255.0f) << i;  // rows in the same order
    EXPECT_FLOAT_EQ(exr.rgb[i], im.rgb[i]) << i;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mpr
