#include "scene/camera_origin.hpp"

#include <algorithm>
#include <cmath>

namespace mpr {

DVec3 loadingOrigin(DVec3 eye) {
  const double far = std::max({std::fabs(eye.x), std::fabs(eye.y), std::fabs(eye.z)});
  return far > kFarFromOrigin ? eye : DVec3(0.0);
}

void moveOriginToCamera(Scene& s) {
  if (s.camera.position == Vec3(0.0f)) return;
  const DVec3 shift(s.camera.position);
  const auto relative = [&shift](Vec3 p) { return Vec3(DVec3(p) - shift); };
  for (SceneObject& o : s.objects)
    for (Vec3& p : o.mesh.positions) p = relative(p);
  s.camera.position = relative(s.camera.position);
  s.camera.lookAt = relative(s.camera.lookAt);
  for (PointLight& l : s.lights) l.position = relative(l.position);
  s.origin += shift;
}

}  // namespace mpr
