#include "algorithms/shadow_geometry.hpp"

#include <utility>

#include "algorithms/silhouette.hpp"

namespace mpr {

void setVolumeTriangles(VolumeGeometry& v) {
  v.sides.clear();
  for (const auto& q : v.volume.sides) {
    v.sides.push_back({q[0], q[1], q[2]});
    v.sides.push_back({q[0], q[2], q[3]});
  }
  v.caps = v.volume.lightCap;
  v.caps.insert(v.caps.end(), v.volume.darkCap.begin(), v.volume.darkCap.end());
}

VolumeGeometry objectShadowVolume(const SceneObject& object, Vec3 light, const BoundingSphere& receivers) {
  VolumeGeometry v;
  v.object = object.name;
  v.volume = buildShadowVolume(object.mesh, light, receivers);
  v.closed = v.volume.casterClosed;
  setVolumeTriangles(v);
  return v;
}

VolumeGeometry twoSidedShadowVolume(const SceneObject& object, Vec3 light, const BoundingSphere& receivers) {
  const Mesh& m = object.mesh;
  for (const auto& t : m.triangles)
    if (triangleFacesLight(m.positions[t[0]], m.positions[t[1]], m.positions[t[2]], light))
      return objectShadowVolume(object, light, receivers);
  SceneObject turned = object;
  for (auto& t : turned.mesh.triangles) std::swap(t[1], t[2]);
  return objectShadowVolume(turned, light, receivers);
}

std::array<Vec3, 4> nearRectangle(const Camera& camera, const DMat4& world, double aspect) {
  std::array<Vec3, 4> corners = nearPlaneCorners(camera, aspect);
  const DMat4 back = glm::inverse(world);
  for (Vec3& c : corners) {
    const DVec4 p = back * DVec4(DVec3(c), 1.0);
    c = Vec3(DVec3(p) / p.w);
  }
  return corners;
}

bool volumeNeedsZFail(const VolumeGeometry& v, Vec3 eye, const std::array<Vec3, 4>& nearCorners) {
  return shadowVolumeTouchesNearRectangle(v.volume, nearCorners, eye);
}

}  // namespace mpr
