#include "algorithms/shadow_pivot.hpp"

#include <algorithm>
#include <limits>

namespace mpr {

Vec3 pivotFarNode(Vec3 near, Vec3 far, Vec3 light, DVec3 jitter) {
  const double a1 = glm::length(DVec3(near) - DVec3(light));
  const double a2 = glm::length(DVec3(far) - DVec3(near));
  return Vec3(DVec3(far) - jitter * (a2 / a1));
}

ShadowVolume pivotShadowVolume(const ShadowVolume& base, DVec3 jitter) {
  ShadowVolume v = base;
  const Vec3 l = base.light;
  for (auto& q : v.sides) {
    q[2] = pivotFarNode(q[1], q[2], l, jitter);
    q[3] = pivotFarNode(q[0], q[3], l, jitter);
  }
  // darkCap[t] = {a', c', b'} of lightCap[t] = {a, b, c} (shadow_volume.cpp).
  for (std::size_t t = 0; t < v.darkCap.size(); ++t) {
    const VolumeTriangle& near = base.lightCap[t];
    VolumeTriangle& far = v.darkCap[t];
    far = {pivotFarNode(near[0], far[0], l, jitter), pivotFarNode(near[2], far[1], l, jitter),
           pivotFarNode(near[1], far[2], l, jitter)};
  }
  v.light = Vec3(DVec3(l) + jitter);
  return v;
}

ShadowVolume pivotBaseVolume(const ShadowVolume& volume, double r) {
  if (volume.empty() || !(r > 0.0)) return volume;
  double a1min = std::numeric_limits<double>::infinity();
  for (const VolumeTriangle& t : volume.lightCap)
    for (const Vec3& p : t) a1min = std::min(a1min, glm::length(DVec3(p) - DVec3(volume.light)));
  const double R0 = volume.extrusionRadius;
  const double R = r < a1min / 2.0 ? (R0 + r) / (1.0 - r / a1min) : 2.0 * (R0 + r);
  ShadowVolume v = volume;
  v.extrusionRadius = R;
  for (auto& q : v.sides) {
    q[2] = extrudeFromLight(q[1], volume.light, R);
    q[3] = extrudeFromLight(q[0], volume.light, R);
  }
  for (std::size_t t = 0; t < v.darkCap.size(); ++t) {
    const VolumeTriangle& n = volume.lightCap[t];
    v.darkCap[t] = {extrudeFromLight(n[0], volume.light, R), extrudeFromLight(n[2], volume.light, R),
                    extrudeFromLight(n[1], volume.light, R)};
  }
  return v;
}

}  // namespace mpr
