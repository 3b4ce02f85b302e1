#pragma once
// What the shadow passes draw of shadow_volume.hpp's volumes: the triangles
// of one object's volume for a light (silhouette edges from OpenMesh
// half-edge connectivity, extruded away from the light, with caps), and the
// z-pass / z-fail choice for a view (is the near rectangle in or across it?).
#include <array>

#include "algorithms/shadow_pass.hpp"
#include "algorithms/shadow_volume.hpp"
#include "algorithms/view_camera.hpp"
#include "scene/scene.hpp"

namespace mpr {

// The triangles the passes draw (sides as two triangles each, both caps),
// from v.volume.
void setVolumeTriangles(VolumeGeometry& v);

// `object`'s volume from `light`, extruded until it leaves `receivers`.
VolumeGeometry objectShadowVolume(const SceneObject& object, Vec3 light, const BoundingSphere& receivers);
// The same for a two-sided object (glass): when no triangle faces the light
// (an open face lit from behind), the volume of its triangles turned round.
VolumeGeometry twoSidedShadowVolume(const SceneObject& object, Vec3 light, const BoundingSphere& receivers);

// The near-plane rectangle of `camera` seen through `world` (a virtual view),
// in real-scene coordinates.
std::array<Vec3, 4> nearRectangle(const Camera& camera, const DMat4& world, double aspect);

// True when z-pass counting could be wrong for this volume (conservative).
bool volumeNeedsZFail(const VolumeGeometry& volume, Vec3 eye, const std::array<Vec3, 4>& nearCorners);

}  // namespace mpr
