#pragma once
// Snell's law for the reference, both ways round: the direction a ray takes
// through an interface, and the point where light from A must cross a plane
// to reach B.
#include <cmath>
#include <optional>

#include "util/vecmath.hpp"
#include "reference/specular_face.hpp"

namespace mpr {

// The refracted direction of unit `d` at a surface with unit normal `n` on
// the incident side (dot(d, n) < 0), eta = n_incident / n_transmitted;
// nothing past the critical angle (total internal reflection).
std::optional<DVec3> refractDirection(DVec3 d, DVec3 n, double eta);

// A unit vector perpendicular to unit n: with cross(n, it), the tangents a
// rough face (frosted glass, a glossy mirror) tilts directions along.
inline DVec3 perpendicular(DVec3 n) {
  const DVec3 a = std::fabs(n.x) < 0.9 ? DVec3(1.0, 0.0, 0.0) : DVec3(0.0, 1.0, 0.0);
  return glm::normalize(glm::cross(n, a));
}

// The point X on the face's plane where a path a -> X -> b obeys Snell's law
// (n_a sin(theta_a) = n_b sin(theta_b), in the plane of incidence spanned by
// the normal and a, b), a and b on opposite sides, the media by the change
// of medium model (front: air, behind: the face's ior). Nothing when a and b
// are on the same side. X is not checked against the polygon.
std::optional<DVec3> snellCrossing(const SpecularFace& face, DVec3 a, DVec3 b);

// The same for a slab (face.thickness > 0, scene/slab_refraction.hpp): the
// point X on the plane where light from a enters so that, shifted sideways
// by the slab and going on parallel to a -> X, it reaches b. Fixed-point
// iteration from the straight line's crossing: X = the plane's crossing of
// a -> b - shift(X - a), to 1e-13 of the distance (the shift changes slowly
// with the angle: a contraction for slabs thin against the distances);
// nothing when a and b are on one side or it does not settle in 100 steps.
std::optional<DVec3> slabCrossing(const SpecularFace& face, DVec3 a, DVec3 b);

}  // namespace mpr
