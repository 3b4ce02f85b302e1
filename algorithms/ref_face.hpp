#pragma once
// The specular faces of a scene (the 1994 paper's "ref faces"): every polygon
// of an object whose material is a mirror or refracts, with its plane.
#include <vector>

#include "algorithms/plane.hpp"
#include "algorithms/view_camera.hpp"
#include "scene/scene.hpp"

namespace mpr {

// Refracting materials: the recursion looks through them with a refracted
// camera, and their light goes on through a refracted light volume.
inline bool refracts(MaterialKind k) {
  return k == MaterialKind::Refractive || k == MaterialKind::Translucent || k == MaterialKind::Frosted;
}

struct RefFace {
  int object = 0;              // index into Scene::objects
  std::vector<Vec3> polygon;   // world space, counter-clockwise seen from the front
  DVec3 normal{0.0};           // unit, pointing to the front (the side that reflects)
  double offset = 0.0;         // the plane: dot(normal, x) = offset
  DVec3 centre{0.0};
  MaterialKind kind = MaterialKind::Mirror;
  double ior = 1.0;            // refractive faces
  double thickness = 0.0;      // > 0: a slab (in-out refraction, scene/slab_refraction.hpp)
  bool refracts() const { return mpr::refracts(kind); }
  float fogDistance = 1.0f;    // translucent and frosted faces
  float shear = 0.0f;          // frosted faces: the stochastic shear's multiplier m (1997 §3)
  Vec3 color{0.0f};            // the material's diffuse colour (translucent fog colour)

  // > 0 in front of the face, < 0 behind it.
  double side(DVec3 p) const { return glm::dot(normal, p) - offset; }
  Plane plane() const { return Plane{normal, -offset}; }
};

// The materials whose faces the recursion looks through: mirrors (when
// reflections are on) and refracting faces (when refractions are on).
// Frosted glass (1997 §3) refracts like glass, its view sheared
// stochastically about the face normal, one shear per accumulated image.
inline bool isRefMaterial(const SceneMaterial& m, const RenderSettings& r) {
  return (m.kind == MaterialKind::Mirror && r.reflections) || (m.kind == MaterialKind::Refractive && r.refractions) ||
         (m.kind == MaterialKind::Translucent && r.translucency) || (m.kind == MaterialKind::Frosted && r.frosted);
}

// Every polygon of every ref object, in scene order (Newell normals; the
// loader has already refused non-planar and zero-area specular faces).
std::vector<RefFace> findRefFaces(const Scene& scene);

}  // namespace mpr
