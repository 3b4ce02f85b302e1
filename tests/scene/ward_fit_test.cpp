// The 1997 paper's eq. (6) repeated: Phong's k cos(delta)^E fitted by least
// squares (chi-square with unit errors) to the "partial Gaussian" of eq. (5),
//   cos(ti) exp(-tan^2(delta) / alpha^2) / (4 pi alpha^2 sqrt(cos(ti) cos(tr))),
// with E = c1 / alpha^2 and k = c2 E, the paper's two parameters c1 = 1.999
// and c2 = 0.0398 (scene/ward_fit.hpp).
//
// What the paper leaves out is the fitted variable and its samples. The
// setting that reproduces both published numbers: the light along the normal
// (ti = 0), the viewer swept in its plane over tr = 0, 1, ..., 89 degrees
// (delta = tr / 2), every sample weighted alike. Then for alpha from 0.03 to
// 0.05 the fit gives c1 = 1.999 and c2 = 0.0398 to the printed digits, and as
// alpha -> 0 it tends to c1 = 2, c2 = 1 / (8 pi) = 0.03979, which is the
// leading term of exp(-tan^2 d / a^2) = cos(d)^(2 / a^2) (1 + O(d^4 / a^2)).
// The fit over delta alone (without eq. 5's 1 / sqrt(cos tr)) always gives
// c1 > 2: the published 1.999 < 2 needs the view factor. The published
// chi-square, 8.003e-5, depends on the unstated sample count and units and is
// not reproduced: this setting's sum is 4.5e-4 at alpha = 0.04 (90 samples).
#include "scene/ward_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "scene/scene_loader.hpp"

// A namespace of its own: the suite is compiled in batches (unity builds).
namespace mpr::ward_fit_test {
namespace {

struct Sample {
  double cosDelta;
  double target;  // eq. (5) with rho_s = 1
};

struct Fit {
  double c1, c2, chiSquare;
};

double eq5(double thetaI, double thetaR, double delta, double alpha) {
  const double t = std::tan(delta);
  return std::cos(thetaI) * std::exp(-t * t / (alpha * alpha)) /
         (std::sqrt(std::cos(thetaI) * std::cos(thetaR)) * 4.0 * std::numbers::pi * alpha * alpha);
}

// The light along the normal, the viewer at tr = 0, 1/perDegree, ... up to
// 90 degrees (not included) in its plane.
std::vector<Sample> normalIncidence(double alpha, int perDegree = 1) {
  std::vector<Sample> s;
  for (int step = 0; step < 90 * perDegree; ++step) {
    const double tr = step * std::numbers::pi / (180.0 * perDegree);
    s.push_back({std::cos(tr / 2.0), eq5(0.0, tr, tr / 2.0, alpha)});
  }
  return s;
}

// eq. (3) without the view factor, over delta = 0..89 half degrees.
std::vector<Sample> deltaAlone(double alpha) {
  std::vector<Sample> s;
  for (int half = 0; half < 90; ++half) {
    const double d = half * std::numbers::pi / 360.0;
    const double t = std::tan(d);
    s.push_back({std::cos(d), std::exp(-t * t / (alpha * alpha)) / (4.0 * std::numbers::pi * alpha * alpha)});
  }
  return s;
}

// For a given c1 the best c2 is linear least squares; c1 by golden section.
Fit fitPhong(const std::vector<Sample>& samples, double alpha) {
  const auto at = [&](double c1) {
    const double e = c1 / (alpha * alpha);
    double gy = 0.0, gg = 0.0;
    for (const Sample& s : samples) {
      const double g = e * std::pow(s.cosDelta, e);
      gy += g * s.target;
      gg += g * g;
    }
    const double c2 = gy / gg;
    double chi = 0.0;
    for (const Sample& s : samples) {
      const double r = s.target - c2 * e * std::pow(s.cosDelta, e);
      chi += r * r;
    }
    return Fit{c1, c2, chi};
  };
  double lo = 1.5, hi = 2.5;
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  while (hi - lo > 1e-10) {
    const double a = hi - g * (hi - lo), b = lo + g * (hi - lo);
    if (at(a).chiSquare < at(b).chiSquare) hi = b; else lo = a;
  }
  return at((lo + hi) / 2.0);
}

double rounded(double v, int decimals) {
  const double p = std::pow(10.0, decimals);
  return std::round(v * p) / p;
}

TEST(WardFit, NormalIncidenceReproducesThePublishedParameters) {
  for (const double alpha : {0.03, 0.04, 0.05}) {
    const Fit f = fitPhong(normalIncidence(alpha), alpha);
    EXPECT_EQ(rounded(f.c1, 3), kWardFitExponent) << "alpha " << alpha << " c1 " << f.c1;
    EXPECT_EQ(rounded(f.c2, 4), kWardFitScale) << "alpha " << alpha << " c2 " << f.c2;
  }
}

// Each fit is closer to 2 the smaller alpha; the limit is the leading term,
// exponent 2 / alpha^2 and peak 1 / (4 pi alpha^2): c1 = 2, c2 = 1 / (8 pi),
// approached as alpha^2 (the next terms of both sides are O(d^4 / a^2)).
// Sampled every tenth of a degree, so that even alpha = 0.01 (0.57 degrees)
// has a dozen samples across its peak. The published digits hold at this
// sampling too for alpha = 0.03 .. 0.05.
TEST(WardFit, SmallAlphaTendsToTheLeadingTerm) {
  double previous = 0.0;
  for (const double alpha : {0.2, 0.1, 0.05, 0.02, 0.01}) {
    const Fit f = fitPhong(normalIncidence(alpha, 10), alpha);
    EXPECT_LT(f.c1, 2.0) << alpha;
    EXPECT_GT(f.c1, previous) << alpha;
    previous = f.c1;
    if (alpha >= 0.03 && alpha <= 0.05) {
      EXPECT_EQ(rounded(f.c1, 3), kWardFitExponent) << alpha;
    }
  }
  const Fit f = fitPhong(normalIncidence(0.01, 10), 0.01);
  EXPECT_NEAR(f.c1, 2.0, 1e-4);
  EXPECT_NEAR(f.c2, 1.0 / (8.0 * std::numbers::pi), 5e-6);
  EXPECT_EQ(rounded(1.0 / (8.0 * std::numbers::pi), 4), kWardFitScale);
}

// Without eq. (5)'s view factor the Gaussian falls faster than any cos^E
// that matches its top (tan^2 d > d^2 > -2 ln cos d): the fit's c1 exceeds 2,
// so the published 1.999 is not a fit over delta alone.
TEST(WardFit, DeltaAloneOvershoots) {
  for (const double alpha : {0.05, 0.1, 0.2, 0.3}) {
    const Fit f = fitPhong(deltaAlone(alpha), alpha);
    EXPECT_GT(f.c1, 2.0) << alpha;
  }
}

// The loader applies eq. (6): E = 1.999 / alpha^2, specular 0.0398 E rho_s.
TEST(WardFit, RoughnessBecomesTheFittedPhongTerm) {
  const Scene s = loadSceneText("materials:\n  m: {specular: [0.5, 0.5, 0.5], roughness: 0.25}\nobjects: [{primitive: box, material: m}]\n",
                                "s.yaml");
  const SceneMaterial& m = s.materials.at(1);
  EXPECT_EQ(m.shininess, static_cast<float>(1.999 / 0.0625));
  EXPECT_EQ(m.specular.x, 0.5f * static_cast<float>(0.0398 * (1.999 / 0.0625)));
  EXPECT_EQ(m.wardSpecular.x, 0.5f);
}

}  // namespace
}  // namespace mpr::ward_fit_test
