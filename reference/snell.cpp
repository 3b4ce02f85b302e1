#include "reference/snell.hpp"

#include <cmath>

#include "scene/slab_refraction.hpp"

namespace mpr {

std::optional<DVec3> refractDirection(DVec3 d, DVec3 n, double eta) {
  const double cosI = std::min(1.0, -glm::dot(d, n));
  const double sin2T = eta * eta * std::max(0.0, 1.0 - cosI * cosI);
  if (sin2T >= 1.0) return std::nullopt;
  return glm::normalize(eta * d + (eta * cosI - std::sqrt(1.0 - sin2T)) * n);
}

std::optional<DVec3> snellCrossing(const SpecularFace& face, DVec3 a, DVec3 b) {
  const double sa = face.side(a), sb = face.side(b);
  if (!((sa > 0.0 && sb < 0.0) || (sa < 0.0 && sb > 0.0))) return std::nullopt;
  const double na = sa > 0.0 ? 1.0 : face.ior, nb = sa > 0.0 ? face.ior : 1.0;
  const double ha = std::fabs(sa), hb = std::fabs(sb);
  const DVec3 a0 = a - sa * face.normal, b0 = b - sb * face.normal;  // feet on the plane
  const double dist = glm::length(b0 - a0);
  if (!(dist > 0.0)) return a0;  // along the normal: straight through
  const DVec3 u = (b0 - a0) / dist;
  // g(x) = n_a sin(theta_a) - n_b sin(theta_b) at X = a0 + x u rises from
  // g(0) <= 0 to g(dist) >= 0, strictly: exactly one root. Newton's method
  // kept inside the bracket, bisecting whenever a step would leave it
  // (Numerical Recipes' rtsafe), until a step is below 1e-14 of the span
  // (Newton's last steps square the error: the root is good to ~1e-15).
  const auto g = [&](double x, double& slope) {
    const double ra = std::sqrt(x * x + ha * ha), y = dist - x, rb = std::sqrt(y * y + hb * hb);
    slope = na * ha * ha / (ra * ra * ra) + nb * hb * hb / (rb * rb * rb);
    return na * x / ra - nb * y / rb;
  };
  double lo = 0.0, hi = dist;
  double x = dist * ha / (ha + hb);  // the straight line's crossing: exact when n_a = n_b
  const double tolerance = 1e-14 * std::max(1.0, dist);
  for (int i = 0; i < 100; ++i) {
    double slope = 0.0;
    const double v = g(x, slope);
    if (v == 0.0) break;
    if (v < 0.0) lo = x;
    else hi = x;
    double next = x - v / slope;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    const double step = std::fabs(next - x);
    x = next;
    if (step < tolerance || hi - lo < tolerance) break;
  }
  return a0 + x * u;
}

std::optional<DVec3> slabCrossing(const SpecularFace& face, DVec3 a, DVec3 b) {
  const double sa = face.side(a);
  if (!((sa > 0.0 && face.side(b) < 0.0) || (sa < 0.0 && face.side(b) > 0.0))) return std::nullopt;
  const auto crossing = [&](DVec3 target) -> std::optional<DVec3> {
    const double st = face.side(target);
    if (!((sa > 0.0 && st < 0.0) || (sa < 0.0 && st > 0.0))) return std::nullopt;
    return a + (target - a) * (sa / (sa - st));
  };
  std::optional<DVec3> x = crossing(b);
  const double tolerance = 1e-13 * std::max(1.0, glm::length(b - a));
  for (int i = 0; i < 100 && x; ++i) {
    const DVec3 shift = slabShift(glm::normalize(*x - a), face.normal, face.ior, face.thickness);
    const std::optional<DVec3> next = crossing(b - shift);
    if (!next) return std::nullopt;
    const double step = glm::length(*next - *x);
    x = next;
    if (step < tolerance) return x;
  }
  return std::nullopt;
}

}  // namespace mpr
