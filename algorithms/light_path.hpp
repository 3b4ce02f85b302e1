#pragma once
// Light through several specular faces (1997 §4.2-4.3, Fig. 5-6; the "2+
// bounces" column of Table 2): a light reflected by a mirror face, or
// refracted through a glass face, is a virtual light; the virtual light may
// reach another face and have a virtual light of its own, and so on. A
// light path is that sequence of faces. "With each specular-specular
// transport the light volume is bent by each specular face with which it
// interacts ... Furthermore, the light volume is reduced by each of the
// specular faces": the light that left the last face is the intersection of
// the constituent light volumes, each face of the path carried into the
// space the last virtual light lights (its aperture), all seen from that
// last virtual light (exact for mirrors, paraxial for refraction).
#include <cstddef>
#include <vector>

#include "algorithms/ref_face.hpp"
#include "scene/scene.hpp"

namespace mpr {

struct LightPath {
  int light = 0;
  std::vector<int> faces;            // indices into the ref faces, in the order the light meets them
  std::vector<DVec3> lights;         // lights[0] the light, lights[i] its virtual light after faces[i - 1]
  // The faces carried into the last virtual light's space, each the polygon
  // the light leaves (a slab's shifted by its thickness): light volume i is
  // the shadow volume of apertures[i] from lights.back().
  std::vector<std::vector<DVec3>> apertures;

  DVec3 virtualLight() const { return lights.back(); }
};

// transferThroughFace of each face of the path from `from` (0-based) to the
// end, applied in the light's order: a point of the space the light crosses
// before faces[from] carried into the last virtual light's space.
DVec3 carryAlongPath(const LightPath& path, const std::vector<RefFace>& faces, std::size_t from, DVec3 p);

// Whether an odd number of the path's faces from `from` on are mirrors (a
// carried object's winding turns).
bool carryTurnsWinding(const LightPath& path, const std::vector<RefFace>& faces, std::size_t from);

// How far the light leaves face f shifted, coming from `from` and seeming
// to come from `to` after it: a slab's shift (to - from), else nothing.
DVec3 leavingShift(const RefFace& f, DVec3 from, DVec3 to);

// Every light path of at most `bounces` faces, light by light, each path
// followed by its extensions (depth first, faces in scene order). A path
// goes on to face g when g is not its last face, the virtual light reaches
// beyond g (refLightPosition) and some area of g lies inside every
// constituent light volume (clipped against each, exactly in double). At
// most `limit` paths are returned; `overLimit` says whether more exist.
std::vector<LightPath> lightPaths(const Scene& scene, const std::vector<RefFace>& faces, int bounces,
                                  std::size_t limit, bool* overLimit = nullptr);

// The light bounces a render follows: render.light_bounces, or by default
// render.shadow_recursion_depth, at least 1.
int lightBounces(const RenderSettings& render);

// The most light paths a render takes; past it the planner refuses the scene.
inline constexpr std::size_t kMaxLightPaths = 4096;

}  // namespace mpr
