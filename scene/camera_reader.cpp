// The scene's camera: section: the viewer, and the narrowest field of view
// that renders correctly (kMinFieldOfView).
#include <sstream>
#include <string>

#include "scene/camera_origin.hpp"
#include "scene/scene_loader.hpp"
#include "scene/scene_section_readers.hpp"

namespace mpr {
namespace {

// (0, 180) as the format says, as the float the camera keeps: 180 (or a
// number that rounds to it) projects the scene onto the window's centre
// (cot 90 degrees is 6e-17), and below kMinFieldOfView float clipping
// leaves bands of the window empty (1e-50 is 0 as a float, and
// gluPerspective then does nothing; 1e-8 drew black bands).
float fieldOfView(const SceneNodeReader& in, const YAML::Node& n) {
  const double v = in.number(n, "camera.fov");
  std::ostringstream min;
  min << kMinFieldOfView;
  if (!(v >= kMinFieldOfView))
    in.fail(n, "camera.fov must be at least " + min.str() + " degrees (narrower, float rounding in clipping leaves bands of the window empty), not " +
                   n.Scalar());
  if (v >= 180.0) in.fail(n, "camera.fov must be below 180, not " + n.Scalar());
  const float f = static_cast<float>(v);
  if (f >= 180.0f) in.fail(n, "camera.fov must be below 180, not " + n.Scalar() + " (180 as a float)");
  return f;
}

}  // namespace

DVec3 readCamera(const SceneNodeReader& in, const YAML::Node& n, Camera& c) {
  in.checkKeys(n, scene_format::kCameraKeys, "camera");
  const DVec3 eye = n["position"] ? in.dvec3(n["position"], "camera.position") : DVec3(c.position);
  const DVec3 origin = loadingOrigin(eye);
  c.position = Vec3(eye - origin);
  if (n["look_at"]) c.lookAt = Vec3(in.dvec3(n["look_at"], "camera.look_at") - origin);
  else c.lookAt = Vec3(DVec3(c.lookAt) - origin);
  if (n["up"]) c.up = in.vec3(n["up"], "camera.up");
  if (n["fov"]) c.fovY = fieldOfView(in, n["fov"]);
  if (n["near"]) c.near = static_cast<float>(in.number(n["near"], "camera.near", 0.0, 1e30, true));
  if (n["far"]) c.far = static_cast<float>(in.number(n["far"], "camera.far", 0.0, 1e30, true));
  if (n["aperture"]) c.aperture = static_cast<float>(in.number(n["aperture"], "camera.aperture", 0.0, 1e6));
  if (n["focal_distance"])
    c.focalDistance = static_cast<float>(in.number(n["focal_distance"], "camera.focal_distance", 0.0, 1e30, true));
  // The distance in focus is a lens's: a pinhole (aperture 0, the pipeline's
  // and the reference's alike) has everything in focus.
  if (n["focal_distance"] && !(c.aperture > 0.0f) && !in.givenBySet(n["focal_distance"]) &&
      !(n["aperture"] && in.givenBySet(n["aperture"])))
    in.fail(n["focal_distance"], "camera.focal_distance is the distance a lens keeps in focus, and camera.aperture is 0 "
                                 "(a pinhole: everything is in focus); give aperture above 0 for depth of field");
  const YAML::Node at = n["far"] ? n["far"] : n;
  if (!(c.far > c.near)) in.fail(at, "camera.far must be greater than camera.near");
  if (c.position == c.lookAt) in.fail(n["look_at"] ? n["look_at"] : n, "camera.look_at must differ from camera.position");
  const Vec3 f = c.lookAt - c.position;
  const Vec3 side = glm::cross(f, c.up);
  if (glm::dot(side, side) == 0.0f) in.fail(n["up"] ? n["up"] : n, "camera.up must not be parallel to the view direction");
  return origin;
}

}  // namespace mpr
