#pragma once
// The geometry the shadow passes draw: one object's shadow volume for a
// point light (silhouette edges extruded away from the light, with caps),
// and the test that tells z-pass from z-fail (is the camera's near
// rectangle inside or across the volume?).
#include <array>

#include "algorithms/shadow_pass.hpp"
#include "algorithms/view_camera.hpp"
#include "scene/scene.hpp"

namespace mpr {

struct SceneBounds {
  DVec3 centre{0.0};
  double radius = 1.0;
};

// A sphere around every object of the scene (receivers lie inside it).
SceneBounds sceneBounds(const Scene& scene);

// The volume of `object`'s silhouette from `light`, extruded until it leaves
// `bounds`. Sides and caps are counter-clockwise seen from outside.
VolumeGeometry objectShadowVolume(const SceneObject& object, Vec3 light, const SceneBounds& bounds);

// The near-plane rectangle of `camera` (gluPerspective/gluLookAt) seen through
// `world` (a virtual view), in real-scene coordinates.
std::array<Vec3, 4> nearRectangle(const Camera& camera, const DMat4& world, int width, int height);

// True when z-pass counting could be wrong for this volume: the eye or a
// corner of the near rectangle lies inside it, or one of its faces crosses
// the near rectangle. Conservative: never false when it matters.
bool volumeNeedsZFail(const VolumeGeometry& volume, Vec3 eye, const std::array<Vec3, 4>& nearCorners);

// Ray-parity inside test for a closed volume.
bool pointInsideVolume(const VolumeGeometry& volume, DVec3 p);

}  // namespace mpr
