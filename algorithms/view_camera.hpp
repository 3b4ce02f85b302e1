#pragma once
// A camera of the drawwindow recursion (1994 paper, Figure 4): the scene's
// camera, seen through the reflections (and refractions) of the faces the
// recursion passed. Geometry is drawn with the modelview gluLookAt * world,
// so `world` maps the real scene into the virtual one.
#include <glm/gtc/matrix_transform.hpp>

#include "util/vecmath.hpp"
#include "scene/scene.hpp"

namespace mpr {

struct ViewCamera {
  DMat4 world{1.0};        // real scene -> virtual scene
  bool mirrored = false;   // an odd number of reflections: the winding flips
  bool clip = false;       // keep world points with dot(clipPlane, (p, 1)) >= 0
  DVec4 clipPlane{0.0};
  int throughFace = -1;    // the ref face this view looks through (-1: the real camera)
  int level = 0;           // recursion level (REF_LEVEL) this view is drawn at
  // Refracted views: the projective map M3 (1994 eqs. 1-3, Appendix) from this
  // camera's normalised device coordinates onto the screen, in the paper's
  // row-vector convention; loaded before the projection as the 4x4 of (A5)
  // (with Z kept, see draw_window.cpp).
  bool mapped = false;
  DMat3 imageMap{1.0};
  // With Z kept, depth is divided by the map's w (its denominator); where
  // that is below 1 a point short of the far plane lands past it and is
  // clipped away (a pane turned -20 degrees showed black, issue 43). Z is
  // scaled by the smallest denominator over the face's image, so every
  // point inside the face keeps a depth within [-1, 1], in the same order.
  double depthScale = 1.0;
  // > 0: this view's near plane, in place of the camera's (a mirror's view:
  // draw_window.cpp, mirrorNear). The projection and the near rectangle the
  // shadow volumes' z-fail choice uses both take it.
  double near = 0.0;
  double nearOf(const Camera& c) const { return near > 0.0 ? near : static_cast<double>(c.near); }
  // Seen through a translucent face (1994 "Object attributes and
  // translucency"): linear fog from the face's distance (clear) to
  // fog_distance behind it (the material's colour).
  bool fog = false;
  Vec3 fogColor{0.0f};
  float fogStart = 0.0f, fogEnd = 1.0f;

  // The eye in real-scene coordinates: where the virtual camera sits.
  DVec3 eye(const Camera& c) const {
    const DVec4 e = glm::inverse(world) * DVec4(DVec3(c.position), 1.0);
    return DVec3(e) / e.w;
  }
};

// The reflection through the plane dot(n, x) = c (n of unit length):
// x -> x - 2 (dot(n, x) - c) n.
inline DMat4 reflectionMatrix(DVec3 n, double c) {
  DMat4 m(1.0);
  for (int col = 0; col < 3; ++col)
    for (int row = 0; row < 3; ++row) m[col][row] -= 2.0 * n[row] * n[col];
  for (int row = 0; row < 3; ++row) m[3][row] = 2.0 * c * n[row];
  return m;
}

}  // namespace mpr
