// The error measure on small hand-made images, every value computed by hand.
#include "reference/accuracy/image_error.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace mpr {
namespace {

Rgb8Image greys(std::initializer_list<int> values, int width) {
  Rgb8Image im{width, static_cast<int>(values.size()) / width, {}};
  for (int v : values)
    for (int c = 0; c < 3; ++c) im.rgb.push_back(static_cast<std::uint8_t>(v));
  return im;
}

TEST(ImageError, LuminanceIsRec709OnLinearEightBitValues) {
  EXPECT_DOUBLE_EQ(luminance(0, 255, 0), 0.7152);
  EXPECT_DOUBLE_EQ(luminance(255, 0, 0), 0.2126);
  EXPECT_DOUBLE_EQ(luminance(0, 0, 255), 0.0722);
  EXPECT_NEAR(luminance(51, 51, 51), 0.2, 1e-15);  // 51 / 255
}

// Reference greys 51, 102, 153, 102: luminance 0.2, 0.4, 0.6, 0.4, range 0.4.
// The image differs in the last pixel only, 112 instead of 102: by 10/255.
// RMS = sqrt((10/255)^2 / 4) = 5/255; over the range: 5/255/0.4 = 4.90196 %.
// Largest: 10/255/0.4 = 9.80392 %. Over 5 % of the range (0.02): 1 of 4 pixels.
TEST(ImageError, RmsOverTheReferencesLuminanceRange) {
  const Rgb8Image ref = greys({51, 102, 153, 102}, 2), im = greys({51, 102, 153, 112}, 2);
  const ImageError e = compareLuminance(im, ref);
  EXPECT_NEAR(e.rmsPercent, 500.0 / 102.0, 1e-9);
  EXPECT_NEAR(e.maxErrorPercent, 1000.0 / 102.0, 1e-9);
  EXPECT_DOUBLE_EQ(e.shareOver5Percent, 25.0);
  EXPECT_NEAR(e.referenceMin, 0.2, 1e-12);
  EXPECT_NEAR(e.referenceMax, 0.6, 1e-12);
}

// Black and white reference (range 1); the image's black pixel is 51 (0.2):
// RMS = sqrt(0.2^2 / 2) = 14.1421 %, largest 20 %, half the pixels over 5 %.
TEST(ImageError, FullRange) {
  const ImageError e = compareLuminance(greys({51, 255}, 2), greys({0, 255}, 2));
  EXPECT_NEAR(e.rmsPercent, 100.0 * std::sqrt(0.02), 1e-9);
  EXPECT_NEAR(e.maxErrorPercent, 20.0, 1e-9);
  EXPECT_DOUBLE_EQ(e.shareOver5Percent, 50.0);
}

// Exactly 5 % of the range is not "more than 5 %": range 0.4 (greys 0 and
// 102), a difference of 0.02 is 5.1 of 255; 5/255 = 0.0196 is under, 6/255 over.
TEST(ImageError, TheFivePercentShareIsStrict) {
  EXPECT_DOUBLE_EQ(compareLuminance(greys({5, 102}, 2), greys({0, 102}, 2)).shareOver5Percent, 0.0);
  EXPECT_DOUBLE_EQ(compareLuminance(greys({6, 102}, 2), greys({0, 102}, 2)).shareOver5Percent, 50.0);
}

TEST(ImageError, IdenticalImagesHaveNoError) {
  const Rgb8Image a = greys({10, 20, 30, 40, 50, 60}, 3);
  const ImageError e = compareLuminance(a, a);
  EXPECT_EQ(e.rmsPercent, 0.0);
  EXPECT_EQ(e.maxErrorPercent, 0.0);
  EXPECT_EQ(e.shareOver5Percent, 0.0);
}

// A flat reference has no range: the whole scale (1) stands in for it.
// 0.2 off on every pixel: 20 %.
TEST(ImageError, AFlatReferenceUsesTheWholeScale) {
  EXPECT_NEAR(compareLuminance(greys({51, 51}, 2), greys({0, 0}, 2)).rmsPercent, 20.0, 1e-9);
}

TEST(ImageError, SizesMustAgree) {
  EXPECT_THROW(compareLuminance(greys({1, 2}, 2), greys({1, 2}, 1)), std::invalid_argument);
  EXPECT_THROW(compareLuminance(Rgb8Image{}, Rgb8Image{}), std::invalid_argument);
}

// Brighter pixels turn red, darker blue, at full scale 10 % of the range
// (range 1 here: 0.1 = 25.5 of 255); agreeing pixels stay mid grey.
TEST(ImageError, DifferenceImageColours) {
  const Rgb8Image d = luminanceDifferenceImage(greys({0, 255, 51, 255}, 2), greys({0, 255, 0, 255}, 2));
  EXPECT_EQ(d.rgb[0], 128); EXPECT_EQ(d.rgb[1], 128); EXPECT_EQ(d.rgb[2], 128);
  EXPECT_EQ(d.rgb[6], 255); EXPECT_EQ(d.rgb[7], 0); EXPECT_EQ(d.rgb[8], 0);  // 0.2 over: saturated red
  const Rgb8Image dark = luminanceDifferenceImage(greys({0, 255}, 2), greys({51, 255}, 2));
  EXPECT_EQ(dark.rgb[0], 0); EXPECT_EQ(dark.rgb[1], 0); EXPECT_EQ(dark.rgb[2], 255);
}

}  // namespace
}  // namespace mpr
