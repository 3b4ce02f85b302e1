#pragma once
// Small double-precision value types for the shadow geometry: a plane, a
// bounding sphere, the reflection through a plane. Double, not float: these
// decide sides and intersections; only what the pipeline draws is float.
#include <cmath>
#include <vector>

#include <glm/glm.hpp>

#include "util/vecmath.hpp"

namespace mpr {

// The plane dot(normal, x) + d = 0, normal of unit length. The same four
// numbers are a glClipPlane equation: it keeps the side with
// signedDistance >= 0.
struct Plane {
  DVec3 normal{0.0, 0.0, 1.0};
  double d = 0.0;

  double signedDistance(DVec3 p) const { return glm::dot(normal, p) + d; }
  double signedDistance(Vec3 p) const { return signedDistance(DVec3(p)); }
  DVec4 equation() const { return DVec4(normal, d); }
  Plane flipped() const { return Plane{-normal, -d}; }

  // Through `point` with the (not necessarily unit) normal `n`; a zero
  // normal gives the default plane rather than NaN.
  static Plane throughPoint(DVec3 n, DVec3 point) {
    const double len = glm::length(n);
    if (!(len > 0.0)) return Plane{};
    const DVec3 u = n / len;
    return Plane{u, -glm::dot(u, point)};
  }
};

// The plane of a polygon wound counter-clockwise seen from its front: the
// Newell normal (robust for slightly non-planar or nearly collinear
// corners) through the centroid, as the loader's face checks use.
inline Plane planeOfPolygon(const std::vector<Vec3>& polygon) {
  DVec3 newell(0.0), centroid(0.0);
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const DVec3 a(polygon[i]), b(polygon[(i + 1) % polygon.size()]);
    newell += DVec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    centroid += a;
  }
  if (!polygon.empty()) centroid /= static_cast<double>(polygon.size());
  return Plane::throughPoint(newell, centroid);
}

// The mirror image of p in the plane: p - 2 dist(p) n. Used for the virtual
// light (the paper's ref_light) and virtual cameras.
inline DVec3 reflectPoint(DVec3 p, const Plane& plane) {
  return p - 2.0 * plane.signedDistance(p) * plane.normal;
}
inline Vec3 reflectPoint(Vec3 p, const Plane& plane) { return Vec3(reflectPoint(DVec3(p), plane)); }

// A sphere that encloses every receiver of a shadow (the shadow volumes are
// extruded until they leave it).
struct BoundingSphere {
  DVec3 centre{0.0};
  double radius = 0.0;
  bool contains(DVec3 p) const { return glm::length(p - centre) <= radius; }
};

}  // namespace mpr
