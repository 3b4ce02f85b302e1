#pragma once
// A bounding volume hierarchy over every triangle of a scene, for the
// reference ray tracer. Our own rather than Embree's: the reference must give
// the same bytes on every run, build and thread count, which needs control
// over the build order and the hit tie-breaks, and MPR's scenes have at most
// tens of thousands of triangles, where a plain binned-SAH tree is fast
// enough and adds no dependency.
#include <cstdint>
#include <limits>
#include <vector>

#include "util/vecmath.hpp"
#include "scene/scene.hpp"

namespace mpr {

struct Ray {
  DVec3 origin{0.0};
  DVec3 direction{0.0, 0.0, -1.0};  // not necessarily unit; t is in its units
};

// The triangle, with its corners in double (the scene's floats, widened).
struct BvhTriangle {
  DVec3 p0, e1, e2;           // p1 = p0 + e1, p2 = p0 + e2
  std::uint32_t object = 0;   // index into Scene::objects
  std::uint32_t triangle = 0; // index into that object's mesh.triangles
  bool twoSided = false;      // refracting materials: never skipped as a back face
};

struct Hit {
  double t = std::numeric_limits<double>::infinity();
  double b1 = 0.0, b2 = 0.0;   // barycentrics of corners 1 and 2 (corner 0: 1 - b1 - b2)
  std::uint32_t id = 0;        // index into Bvh::triangles()
  bool frontFacing = true;     // the ray meets the counter-clockwise side
  bool found() const { return t < std::numeric_limits<double>::infinity(); }
};

// Which triangles a closest-hit query may report.
enum class Facing { Both, FrontOnly };

class Bvh {
 public:
  explicit Bvh(const Scene& scene);

  // The nearest hit with t in (tMin, tMax); back faces skipped under FrontOnly
  // (the pipeline culls them: GL_CULL_FACE with CCW fronts), except those of
  // two-sided (refracting) triangles.
  Hit closest(const Ray& ray, double tMin, double tMax, Facing facing) const;
  // Whether any triangle, either side, is hit with t in (tMin, tMax).
  bool occluded(const Ray& ray, double tMin, double tMax) const;

  const std::vector<BvhTriangle>& triangles() const { return tris_; }
  std::size_t nodeCount() const { return nodes_.size(); }

  struct Node {
    DVec3 lo, hi;
    std::uint32_t first = 0;  // leaf: first triangle; inner: second child (first child is next)
    std::uint32_t count = 0;  // 0: inner node
    std::uint8_t axis = 0;    // inner: split axis, to visit the nearer child first
  };

 private:
  std::vector<BvhTriangle> tris_;
  std::vector<Node> nodes_;
};

}  // namespace mpr
