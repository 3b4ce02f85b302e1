#include "reference/accuracy/image_error.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mpr {
namespace {

std::vector<double> luminances(const Rgb8Image& im) {
  std::vector<double> y(static_cast<std::size_t>(im.width) * im.height);
  for (std::size_t i = 0; i < y.size(); ++i) y[i] = luminance(im.rgb[3 * i], im.rgb[3 * i + 1], im.rgb[3 * i + 2]);
  return y;
}

void checkComparable(const Rgb8Image& a, const Rgb8Image& b) {
  if (a.width <= 0 || a.height <= 0) throw std::invalid_argument("cannot compare an empty image");
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument("image is " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                                ", the reference " + std::to_string(b.width) + "x" + std::to_string(b.height));
  const std::size_t n = 3 * static_cast<std::size_t>(a.width) * a.height;
  if (a.rgb.size() != n || b.rgb.size() != n) throw std::invalid_argument("image data does not match its size");
}

double rangeOf(const std::vector<double>& y, double& lo, double& hi) {
  const auto [mn, mx] = std::minmax_element(y.begin(), y.end());
  lo = *mn;
  hi = *mx;
  return hi > lo ? hi - lo : 1.0;
}

}  // namespace

double luminance(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  return (0.2126 * r + 0.7152 * g + 0.0722 * b) / 255.0;
}

ImageError compareLuminance(const Rgb8Image& image, const Rgb8Image& reference) {
  checkComparable(image, reference);
  const std::vector<double> y = luminances(image), yr = luminances(reference);
  ImageError e;
  const double range = rangeOf(yr, e.referenceMin, e.referenceMax);
  // Summed in pixel order: the same images give the same bytes of the report.
  double sumSq = 0.0, maxAbs = 0.0;
  std::size_t over = 0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    const double d = std::abs(y[i] - yr[i]);
    sumSq += d * d;
    maxAbs = std::max(maxAbs, d);
    if (d > 0.05 * range) ++over;
  }
  e.rmsPercent = 100.0 * std::sqrt(sumSq / static_cast<double>(y.size())) / range;
  e.maxErrorPercent = 100.0 * maxAbs / range;
  e.shareOver5Percent = 100.0 * static_cast<double>(over) / static_cast<double>(y.size());
  return e;
}

Rgb8Image luminanceDifferenceImage(const Rgb8Image& image, const Rgb8Image& reference, double fullScalePercent) {
  checkComparable(image, reference);
  const std::vector<double> y = luminances(image), yr = luminances(reference);
  double lo = 0.0, hi = 0.0;
  const double full = rangeOf(yr, lo, hi) * fullScalePercent / 100.0;
  Rgb8Image d{image.width, image.height, std::vector<std::uint8_t>(image.rgb.size())};
  for (std::size_t i = 0; i < y.size(); ++i) {
    const double t = std::clamp((y[i] - yr[i]) / full, -1.0, 1.0);
    const auto towards = [&](double to) { return static_cast<std::uint8_t>(std::lround(128.0 + (to - 128.0) * std::abs(t))); };
    // Brighter: towards red (255, 0, 0); darker: towards blue (0, 0, 255).
    d.rgb[3 * i] = towards(t > 0 ? 255.0 : 0.0);
    d.rgb[3 * i + 1] = towards(0.0);
    d.rgb[3 * i + 2] = towards(t > 0 ? 0.0 : 255.0);
  }
  return d;
}

}  // namespace mpr
