#pragma once
// Camera rays of the scene camera, the same view the pipeline draws:
// gluPerspective(fovY, width / height, near, far) after gluLookAt(position,
// lookAt, up). Window pixel (x, y) (y up, row 0 the bottom) has its centre at
// (x + 0.5, y + 0.5).
#include <cmath>

#include "reference/bvh.hpp"
#include "reference/sampler.hpp"
#include "scene/scene.hpp"

namespace mpr {

struct CameraRays {
  DVec3 eye, forward, right, up;  // gluLookAt's f, s and u
  double tanHalfY = 1.0, aspect = 1.0, near = 0.1, far = 100.0;
  double aperture = 0.0, focal = 1.0;  // a thin lens (camera.aperture, focal_distance)
  int width = 1, height = 1;

  CameraRays(const Camera& c, int w, int h)
      : eye(c.position), width(w), height(h) {
    forward = glm::normalize(DVec3(c.lookAt) - eye);
    right = glm::normalize(glm::cross(forward, DVec3(c.up)));
    up = glm::cross(right, forward);
    tanHalfY = std::tan(static_cast<double>(c.fovY) * 3.14159265358979323846 / 360.0);
    aspect = static_cast<double>(w) / static_cast<double>(h);
    near = c.near, far = c.far;
    aperture = c.aperture;
    focal = c.focalDistance > 0.0f ? c.focalDistance : glm::length(DVec3(c.lookAt) - eye);
  }

  // The ray through window position (wx, wy), unit direction; with an
  // aperture, from the lens point `lens` (the unit square, mapped onto the
  // lens disc) through the point the pinhole ray meets the focal plane (the
  // plane at `focal` along the axis): the thin lens the pipeline's sheared
  // frusta approximate with a few images.
  Ray through(double wx, double wy, DVec2 lens = DVec2(0.5)) const {
    const double ndcX = 2.0 * wx / width - 1.0, ndcY = 2.0 * wy / height - 1.0;
    const DVec3 d = glm::normalize(forward + right * (ndcX * tanHalfY * aspect) + up * (ndcY * tanHalfY));
    if (!(aperture > 0.0)) return {eye, d};
    const DVec3 focus = eye + d * (focal / glm::dot(d, forward));
    const DVec2 l = aperture * concentricDisc(lens);
    const DVec3 origin = eye + right * l.x + up * l.y;
    return {origin, glm::normalize(focus - origin)};
  }

  // GL clips at the near and far planes, which lie across the camera axis:
  // along a unit ray they are at near / cos and far / cos of its angle to it.
  double nearAlong(const Ray& r) const { return near / glm::dot(r.direction, forward); }
  double farAlong(const Ray& r) const { return far / glm::dot(r.direction, forward); }
};

}  // namespace mpr
