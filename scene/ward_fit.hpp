// The 1997 paper's eq. (6): Phong's cos(delta)^E fitted to the Gaussian of
// Ward's isotropic BRDF (eq. 5) by a two-parameter chi-square fit,
//   0.0398 (1.999 / alpha^2) rho_s cos(delta)^(1.999 / alpha^2).
// A `roughness` alpha becomes this exponent and scale (material_reader.cpp);
// tests/scene/ward_fit_test.cpp repeats the fit and says what it reproduces.
#pragma once

namespace mpr {

// E = kWardFitExponent / alpha^2.
inline constexpr double kWardFitExponent = 1.999;
// The specular scale: kWardFitScale * E * rho_s.
inline constexpr double kWardFitScale = 0.0398;

}  // namespace mpr
