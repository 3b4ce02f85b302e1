#pragma once
// The GL plumbing of the 1994 algorithm: view set-up, lights, materials and
// geometry, as typed GL calls. Figure 4's routines (draw_window.cpp) call it.
#include <cstdint>
#include <vector>

#include "algorithms/image_samples.hpp"
#include "algorithms/ref_face.hpp"
#include "algorithms/view_camera.hpp"
#include "pipeline/gl/gl_api.hpp"
#include "scene/scene.hpp"

namespace mpr {

class SceneGL {
 public:
  static constexpr int kMaxGLLights = 8;

  // `usesStencil`: the render uses the stencil (shadows or reflections), so
  // the clip plane is switched off explicitly in views without one.
  SceneGL(const Scene& scene, GLApi& gl, bool usesStencil);

  // The image of an accumulation being drawn: its sub-pixel offset and lens
  // point move every view's projection (default: none).
  void setViewSample(const ViewSample& sample) { sample_ = sample; }
  // The view of `cam`: projection (with a refracted view's image map),
  // modelview = lookAt * world, winding, clip plane.
  void setupView(const ViewCamera& cam);
  // GL light `index` as the scene's point light.
  void setLight(int index, const PointLight& light);
  // Ambient and up to eight lights in one pass (GL's own sum), and back to light 0 alone.
  void enableAllLights();
  void disableExtraLights();
  // Every term of a material; or the ambient pass's terms (ambient, emission)
  // or a light pass's (diffuse, specular).
  void setFullMaterial(const SceneMaterial& m);
  void setMaterial(const SceneMaterial& m, bool ambientPass);
  // The mesh's triangles but those `skip` marks (one entry per triangle;
  // null: none), turned round when `turned`: reversed corners, so a
  // triangle seen from behind is front-facing under GL_CULL_FACE (and one
  // seen from the front is culled), and negated normals, so the light on
  // the side the eye sees lights it. Nothing is drawn when all are skipped.
  void drawTriangles(const Mesh& mesh, const std::vector<std::uint8_t>* skip = nullptr, bool turned = false);
  void drawPolygon(const RefFace& face, bool withNormal, bool fromBehind = false);
  double aspect() const;

 private:
  static GLenum lightName(int i);
  const Scene& s_;
  GLApi& gl_;
  bool usesStencil_;
  ViewSample sample_;
};

}  // namespace mpr
