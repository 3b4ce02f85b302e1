#pragma once
// The planar specular faces the reference's light paths go through: every
// polygon of every mirror and refracting object (the 1994 paper's "ref
// faces"), with its plane, in double. The reference keeps its own list (it
// must not depend on algorithms/): it takes every specular kind, whatever the
// scene's render switches say, because physics has no switches.
#include <vector>

#include "util/vecmath.hpp"
#include "scene/scene.hpp"

namespace mpr {

struct SpecularFace {
  int object = 0;
  MaterialKind kind = MaterialKind::Mirror;
  std::vector<DVec3> polygon;  // counter-clockwise seen from the front
  DVec3 normal{0.0};           // unit, to the front
  double offset = 0.0;         // the plane: dot(normal, x) = offset
  DVec3 centre{0.0};
  double radius = 0.0;         // of the sphere about `centre` holding the polygon
  double weight = 1.0;         // reflectance (mirror) or transmittance
  double ior = 1.0;
  double thickness = 0.0;      // > 0: a slab, rays shifted, not turned (scene/slab_refraction.hpp)
  double shear = 0.0;          // frosted: the Gaussian slope its transmission scatters by (1997 §3)
  int dropAxis = 2;            // the normal's largest axis, dropped for 2-D tests

  bool mirror() const { return kind == MaterialKind::Mirror; }
  double side(DVec3 p) const { return glm::dot(normal, p) - offset; }
  DVec3 reflect(DVec3 p) const { return p - 2.0 * side(p) * normal; }
  // Whether `p` (on the plane) lies inside the polygon (even-odd rule).
  bool contains(DVec3 p) const;
  // The crossing of segment a -> b with the plane, a and b strictly on
  // opposite sides; false when there is none.
  bool crossing(DVec3 a, DVec3 b, DVec3& x) const;
};

// Light through a refracting face: the 1994 "change of medium" model. A face
// is one interface; from its front a ray passes from air into the material,
// eta = n_from / n_to = 1 / ior; from behind, eta = ior.
inline bool refractingKind(MaterialKind k) {
  return k == MaterialKind::Refractive || k == MaterialKind::Translucent || k == MaterialKind::Frosted;
}

// Every polygon of every object with a mirror or refracting material, in
// scene order (Newell normals, as the loader's planarity checks use).
std::vector<SpecularFace> findSpecularFaces(const Scene& scene);

}  // namespace mpr
