#pragma once
// draw_ref_shadows of the 1994 paper's Figure 4 ("Refractive shadows",
// Figure 2, Plate 3): each light that reaches a ref face through it has a
// virtual light (ref_light: where the light seems to be for what lies
// beyond the face), which lights only the face's light volume — the pyramid
// from the virtual light through the face, beyond it (face_light_stencil) —
// and is shadowed in two ways: by objects standing in the light volume
// (CAN'T_INTERSECT: their volumes from the virtual light cannot cross the
// face), and by objects between the light and the face whose shadow falls on
// the face and is passed on into the volume (MUST_INTERSECT). So a mirror
// lights the room and a glass pane bends its shadow.
//
// - Mirror: the virtual light is the light reflected through the face's
//   plane; the light volume lies on the light's side.
// - Refracting face (the paper's change-of-medium model): the light moved
//   onto the refracted ray through the face centre (the ray from the light
//   to the centre as the incident ray: a point light has no view axis), to
//   its paraxial image: where that ray, extended back, meets the light's
//   perpendicular to the face, at the light's distance times
//   n_other / n_light; past the critical angle no light passes. The light
//   volume lies beyond the face.
#include <optional>
#include <vector>

#include "algorithms/ref_face.hpp"
#include "algorithms/shadow_pass.hpp"
#include "scene/scene.hpp"

namespace mpr {

//
// Light through several faces (1997 §4.2-4.3, algorithms/light_path.hpp):
// with render.light_bounces > 1 a virtual light that reaches another face
// has its own virtual light there. Its light volume is the intersection of
// the constituent light volumes of every face on its path, each stenciled
// (face_light_stencil once per face); its shadows are those of every
// stretch of the path, each caster carried through the faces after it.
struct ReflectedLight {
  int light = 0, face = 0;                // face: the last face of the path
  std::vector<int> path;                  // every face the light passed, in order (path.back() == face)
  PointLight virtualLight;                // ref position, colour x every face's reflectance or transmittance
  std::vector<VolumeGeometry> lightVolumes;  // the constituent light volumes, the last face's last
  std::vector<VolumeGeometry> shadows;    // from the virtual light: CAN'T_ and MUST_INTERSECT casters
};

// ref_light(light, ref_face): the virtual light's position, or nothing when
// the light does not reach beyond the face through it (a mirror lit from
// behind or in its plane, a light in a refracting face's plane or past its
// critical angle). Index of refraction 1 gives the light itself, exactly.
// A slab (a thickness) gives the light shifted sideways as its ray to the
// face's centre is (scene/slab_refraction.hpp).
std::optional<DVec3> refLightPosition(const RefFace& face, DVec3 light);

// The map that carries a MUST_INTERSECT caster to the object whose shadow
// from the virtual light `ref` crosses the face's plane where the caster's
// shadow from `light` does: the affine map fixing the plane pointwise and
// taking `light` to `ref`, P + (ref - light) dist(P) / dist(light), so lines
// through the light become lines through the virtual light. For a mirror it
// is the reflection itself (which is used, exactly); its determinant
// dist(ref) / dist(light) is negative for a mirror (the winding turns).
// For a slab (a thickness) it is the translation by ref - light: the light
// and everything in its path move by the slab's shift.
DVec3 transferThroughFace(const RefFace& face, DVec3 light, DVec3 ref, DVec3 p);

// Every light path with a virtual light (lightPaths, up to
// lightBounces(render) faces): light by light, each first face followed by
// the paths that go on from it. `image`: which image of an accumulation,
// for the shear of the light a frosted face passes on (1997 §3).
std::vector<ReflectedLight> reflectedLights(const Scene& scene, const std::vector<RefFace>& faces, int image = 0);

}  // namespace mpr
