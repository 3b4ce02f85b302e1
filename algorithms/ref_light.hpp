#pragma once
// draw_ref_shadows of the 1994 paper's Figure 4, for mirrors: each light in
// front of a mirror face has a virtual light behind it (ref_light: the light
// reflected through the face's plane), which lights only the face's light
// volume — the pyramid from the virtual light through the face, beyond the
// face (face_light_stencil) — and is shadowed by the objects in front of
// the face, in two ways: standing in the reflected light (CAN'T_INTERSECT:
// their volumes from the virtual light cannot cross the face), and shadowing
// the face itself from the real light (MUST_INTERSECT: the face reflects that
// shadow, which is the volume of the object's mirror image from the virtual
// light). So a mirror lights the room (the paper's Figure 2, Plate 3).
#include <vector>

#include "algorithms/ref_face.hpp"
#include "algorithms/shadow_pass.hpp"
#include "scene/scene.hpp"

namespace mpr {

struct ReflectedLight {
  int light = 0, face = 0;
  PointLight virtualLight;                // reflected position, colour x reflectance
  VolumeGeometry lightVolume;             // the face's light volume
  std::vector<VolumeGeometry> shadows;    // from the virtual light: CAN'T_ and MUST_INTERSECT casters
};

// Every (light, mirror face) pair with the light strictly in front of the
// face, in light-then-face order.
std::vector<ReflectedLight> reflectedLights(const Scene& scene, const std::vector<RefFace>& faces);

// How many such pairs a scene has (the planner's count).
int reflectedLightCount(const Scene& scene, const std::vector<RefFace>& faces);

}  // namespace mpr
