#pragma once
// In-out refraction (1997 §2: "an entry refraction and an exit refraction,
// producing a refracted ray parallel to the incident ray"): a refracting
// face with a `thickness` T stands for a slab of the material, air on both
// sides. A ray through it leaves in its own direction, shifted sideways by
// T sin(theta_i - theta_t) / cos(theta_t). The face as modelled is where
// the shift is applied (the slab thin in position, T in its shift); the
// pipeline's view through it and its light through it are shifted, not
// turned, and the reference shifts its rays alike. Without a thickness a
// face stays the 1994 change of medium.
#include <algorithm>
#include <cmath>

#include "util/vecmath.hpp"

namespace mpr {

// The sideways shift of unit direction `d` through a slab of index `ior`
// and thickness T whose faces have normal `normal` (either way round): the
// entry-to-exit path (T / cos(theta_t)) t less its part along d, so
// perpendicular to d; on the far side of the entry plane or in it.
inline DVec3 slabShift(DVec3 d, DVec3 normal, double ior, double thickness) {
  const DVec3 m = glm::dot(d, normal) < 0.0 ? normal : -normal;  // against the ray
  const double cosI = std::min(1.0, -glm::dot(d, m));
  const double eta = 1.0 / ior;
  const double cosT = std::sqrt(std::max(0.0, 1.0 - eta * eta * (1.0 - cosI * cosI)));
  if (!(cosT > 0.0)) return DVec3(0.0);
  const DVec3 t = eta * d + (eta * cosI - cosT) * m;  // the refracted ray inside, unit
  const DVec3 path = (thickness / cosT) * t;
  return path - glm::dot(path, d) * d;
}

}  // namespace mpr
