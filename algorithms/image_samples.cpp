#include "algorithms/image_samples.hpp"

#include <numbers>
#include <algorithm>
#include <cmath>

namespace mpr {
namespace {


double radicalInverse(int base, int i) {
  double inv = 1.0 / base, f = inv, r = 0.0;
  for (int k = i; k > 0; k /= base, f *= inv) r += f * (k % base);
  return r;
}

// Shirley and Chiu's concentric map of the unit square onto the unit disc
// (areas kept: stratified points stay stratified).
DVec2 concentricDisc(DVec2 u) {
  const double a = 2.0 * u.x - 1.0, b = 2.0 * u.y - 1.0;
  if (a == 0.0 && b == 0.0) return DVec2(0.0);
  double r, phi;
  if (std::abs(a) > std::abs(b)) r = a, phi = std::numbers::pi / 4.0 * (b / a);
  else r = b, phi = std::numbers::pi / 2.0 - std::numbers::pi / 4.0 * (a / b);
  return r * DVec2(std::cos(phi), std::sin(phi));
}

// Point i of n of the unit square, (i + 1/2) / n across, the radical
// inverse of i in `base` up (its first point, 0, moved to the middle row).
DVec2 tablePoint(int i, int n, int base) { return DVec2((i + 0.5) / n, std::fmod(radicalInverse(base, i) + 0.5 / n, 1.0)); }

DVec3 sceneCentre(const Scene& s) {
  DVec3 lo(1e300), hi(-1e300);
  for (const SceneObject& o : s.objects)
    for (const Vec3& p : o.mesh.positions) lo = glm::min(lo, DVec3(p)), hi = glm::max(hi, DVec3(p));
  return lo.x <= hi.x ? 0.5 * (lo + hi) : DVec3(0.0);
}

bool hasAreaLight(const Scene& s) {
  return std::any_of(s.lights.begin(), s.lights.end(), [](const PointLight& l) { return l.radius > 0.0f; });
}

}  // namespace

int accumulatedImages(const Scene& s) {
  // darkness_levels sums its light samples inside each image (the levels).
  const int lightSamples =
      hasAreaLight(s) && s.render.softShadowMethod != SoftShadowMethod::DarknessLevels ? s.render.softShadowSamples : 1;
  int frosted = 1;
  if (s.render.frosted)
    for (const SceneObject& o : s.objects) {
      const SceneMaterial& m = s.materials[static_cast<std::size_t>(o.material)];
      if (m.kind == MaterialKind::Frosted || (m.kind == MaterialKind::Mirror && m.roughness > 0.0f))
        frosted = std::max(frosted, m.samples);
    }
  return std::max({s.render.antialiasSamples, lightSamples, frosted});
}

DVec2 frostedShear(double m, int samples, int i, int base) {
  if (samples <= 1 || !(m > 0.0)) return DVec2(0.0);
  const DVec2 u = tablePoint(i % samples, samples, base);
  // Box-Muller: u.x in (0, 1) (the table's cells are centred), a normal pair.
  const double r = std::sqrt(-2.0 * std::log(u.x)), a = 2.0 * std::numbers::pi * u.y;
  return m * r * DVec2(std::cos(a), std::sin(a));
}

DMat4 shearAboutFace(DVec3 centre, DVec3 normal, DVec2 shear) {
  const DVec3 n = glm::normalize(normal);
  const DVec3 helper = std::abs(n.x) < 0.9 ? DVec3(1.0, 0.0, 0.0) : DVec3(0.0, 1.0, 0.0);
  const DVec3 t = glm::normalize(glm::cross(helper, n)), b = glm::cross(n, t);
  DMat4 frame(1.0);  // face frame -> world: columns t, b, n, centre
  frame[0] = DVec4(t, 0.0);
  frame[1] = DVec4(b, 0.0);
  frame[2] = DVec4(n, 0.0);
  frame[3] = DVec4(centre, 1.0);
  DMat4 s(1.0);
  s[2][0] = shear.x;  // x' = x + X z
  s[2][1] = shear.y;  // y' = y + Y z
  return frame * s * glm::inverse(frame);
}

ViewSample viewSample(const Scene& s, int i, int n) {
  ViewSample v;
  v.image = i;
  v.images = n;
  const int a = s.render.antialiasSamples;
  const Camera& c = s.camera;
  v.focalDistance = c.focalDistance > 0.0f ? c.focalDistance : glm::length(DVec3(c.lookAt) - DVec3(c.position));
  if (n <= 1 || a <= 1) return v;
  const DVec2 u = tablePoint(i % a, a, 2);
  v.pixelOffset = u - DVec2(0.5);
  if (c.aperture > 0.0f) v.lens = static_cast<double>(c.aperture) * concentricDisc(u);
  return v;
}

Vec3 lightSamplePosition(const Scene& s, const PointLight& l, int i) {
  const int k = s.render.softShadowSamples;
  if (k <= 1 || !(l.radius > 0.0f)) return l.position;
  const DVec2 d = concentricDisc(tablePoint(i % k, k, 3));
  // The disc facing the scene: its axes perpendicular to light -> centre.
  DVec3 axis = sceneCentre(s) - DVec3(l.position);
  if (glm::dot(axis, axis) == 0.0) axis = DVec3(0.0, -1.0, 0.0);
  axis = glm::normalize(axis);
  const DVec3 helper = std::abs(axis.x) < 0.9 ? DVec3(1.0, 0.0, 0.0) : DVec3(0.0, 1.0, 0.0);
  const DVec3 u = glm::normalize(glm::cross(axis, helper)), v = glm::cross(axis, u);
  return Vec3(DVec3(l.position) + static_cast<double>(l.radius) * (d.x * u + d.y * v));
}

int darknessLevelSamples(const Scene& s, const PointLight& l) {
  return s.render.softShadowMethod == SoftShadowMethod::DarknessLevels && l.radius > 0.0f ? s.render.softShadowSamples
                                                                                           : 1;
}

Scene lightSampleScene(const Scene& s, int i, int n) {
  Scene out = s;
  if (n <= 1 || s.render.softShadowSamples <= 1 || s.render.softShadowMethod == SoftShadowMethod::DarknessLevels)
    return out;
  for (PointLight& l : out.lights) l.position = lightSamplePosition(s, l, i);
  return out;
}

}  // namespace mpr
