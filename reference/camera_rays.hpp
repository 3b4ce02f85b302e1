#pragma once
// Camera rays of the scene camera, the same view the pipeline draws:
// gluPerspective(fovY, width / height, near, far) after gluLookAt(position,
// lookAt, up). Window pixel (x, y) (y up, row 0 the bottom) has its centre at
// (x + 0.5, y + 0.5).
#include <cmath>

#include "reference/bvh.hpp"
#include "scene/scene.hpp"

namespace mpr {

struct CameraRays {
  DVec3 eye, forward, right, up;  // gluLookAt's f, s and u
  double tanHalfY = 1.0, aspect = 1.0, near = 0.1, far = 100.0;
  int width = 1, height = 1;

  CameraRays(const Camera& c, int w, int h)
      : eye(c.position), width(w), height(h) {
    forward = glm::normalize(DVec3(c.lookAt) - eye);
    right = glm::normalize(glm::cross(forward, DVec3(c.up)));
    up = glm::cross(right, forward);
    tanHalfY = std::tan(static_cast<double>(c.fovY) * 3.14159265358979323846 / 360.0);
    aspect = static_cast<double>(w) / static_cast<double>(h);
    near = c.near, far = c.far;
  }

  // The ray through window position (wx, wy), unit direction.
  Ray through(double wx, double wy) const {
    const double ndcX = 2.0 * wx / width - 1.0, ndcY = 2.0 * wy / height - 1.0;
    return {eye, glm::normalize(forward + right * (ndcX * tanHalfY * aspect) + up * (ndcY * tanHalfY))};
  }

  // GL clips at the near and far planes, which lie across the camera axis:
  // along a unit ray they are at near / cos and far / cos of its angle to it.
  double nearAlong(const Ray& r) const { return near / glm::dot(r.direction, forward); }
  double farAlong(const Ray& r) const { return far / glm::dot(r.direction, forward); }
};

}  // namespace mpr
