// The GL plumbing under Figure 4 (draw_window.cpp keeps only the paper's
// routines): the view of a camera, lights, materials and drawing the
// scene's triangles, each step a typed GL call.
#include "algorithms/scene_gl.hpp"

#include <algorithm>

#include "algorithms/quad_to_quad.hpp"

namespace mpr {

SceneGL::SceneGL(const Scene& s, GLApi& gl, bool usesStencil) : s_(s), gl_(gl), usesStencil_(usesStencil) {}

// The view of `cam`: projection, modelview = lookAt * world, winding, clip plane.
void SceneGL::setupView(const ViewCamera& cam) {
  const Camera& c = s_.camera;
  const RefractionMap placement = s_.render.refractionMap;
  // The end-of-pipeline placement: the emulated 3x3 stage after the
  // perspective divide (depth kept exactly); off in every other view.
  std::optional<glm::mat3> windowMap;
  if (cam.mapped && placement == RefractionMap::EndOfPipeline) windowMap = glm::mat3(cam.imageMap);
  gl_.windowMap(windowMap);
  gl_.matrixMode(GL_PROJECTION);
  gl_.loadIdentity();
  if (sample_.pixelOffset != DVec2(0.0)) {
    // Antialiasing by accumulation: the whole image moved by a fraction of
    // a pixel in normalised device coordinates, after every other step
    // (Haeberli and Akeley 1990), so refracted views move with it.
    gl_.translated(2.0 * sample_.pixelOffset.x / s_.render.width, 2.0 * sample_.pixelOffset.y / s_.render.height, 0.0);
  }
  if (cam.mapped && placement != RefractionMap::EndOfPipeline) {
    // M3 as the user 4x4 of (A5), applied after the projection (it maps
    // normalised device coordinates, x and y over w). The paper zeroes Z
    // (projection_zeroed_z): every point then has the same depth, which
    // "precludes the use of the Z-buffer", and the projection becomes
    // singular, so the user clip plane at the face, which GL carries into
    // clip space through the inverse projection (as Mesa does), cannot be
    // used. MPR's default keeps Z: it is divided by the map's w, a positive
    // factor constant along each view ray, so the depth order and the
    // depth-equal light passes still hold; scaled by the least w over the
    // face's image (ViewCamera::depthScale) so that no depth inside the
    // face passes the far plane.
    Mat4 m = quadToQuadMatrix4(cam.imageMap);
    if (placement == RefractionMap::ProjectionKeptZ) m[2][2] = static_cast<float>(cam.depthScale);
    gl_.multMatrixf(&m[0][0]);  // column by column, as GL reads it
  }
  gl_.perspective(static_cast<double>(c.fovY), aspect(), cam.nearOf(c), static_cast<double>(c.far));
  if (sample_.lens != DVec2(0.0)) {
    // Depth of field: the eye moved to the lens point (a, b) in eye space and
    // the frustum sheared so that the plane at the focal distance f stays
    // where it was: x' = x - a - a z / f (z = -f: x' = x), y likewise. On the
    // projection stack, so lighting and fog see the unmoved eye space.
    const double f = sample_.focalDistance, a = sample_.lens.x, b = sample_.lens.y;
    const double shear[16] = {1, 0, 0, 0, 0, 1, 0, 0, -a / f, -b / f, 1, 0, -a, -b, 0, 1};
    gl_.multMatrixd(shear);
  }
  gl_.matrixMode(GL_MODELVIEW);
  gl_.loadIdentity();
  gl_.lookAt(static_cast<double>(c.position.x), static_cast<double>(c.position.y), static_cast<double>(c.position.z), static_cast<double>(c.lookAt.x), static_cast<double>(c.lookAt.y), static_cast<double>(c.lookAt.z), static_cast<double>(c.up.x), static_cast<double>(c.up.y), static_cast<double>(c.up.z));
  if (cam.world != DMat4(1.0)) {
    const DMat4& w = cam.world;
    gl_.multMatrixd(&w[0][0]);
  }
  gl_.frontFace(cam.mirrored ? GL_CW : GL_CCW);
  if (cam.clip && !(cam.mapped && placement == RefractionMap::ProjectionZeroedZ)) {
    // The plane is given in the coordinates geometry is drawn in (the real
    // scene's), so GL transforms it into the virtual view with the modelview.
    gl_.clipPlane(GL_CLIP_PLANE0, &cam.clipPlane[0]);
    gl_.enable(GL_CLIP_PLANE0);
  } else if (usesStencil_) {
    gl_.disable(GL_CLIP_PLANE0);
  }
}

void SceneGL::setLight(int index, const PointLight& l) {
  const GLenum n = lightName(index);
  gl_.lightfv(n, GL_POSITION, glFloats(l.position.x, l.position.y, l.position.z, 1.0f).data());
  gl_.lightfv(n, GL_DIFFUSE, glFloats(l.color.x, l.color.y, l.color.z, 1.0f).data());
  gl_.lightfv(n, GL_SPECULAR, glFloats(l.color.x, l.color.y, l.color.z, 1.0f).data());
  gl_.lightf(n, GL_CONSTANT_ATTENUATION, l.attenuation.x);
  gl_.lightf(n, GL_LINEAR_ATTENUATION, l.attenuation.y);
  gl_.lightf(n, GL_QUADRATIC_ATTENUATION, l.attenuation.z);
}

GLenum SceneGL::lightName(int i) { return GL_LIGHT0 + static_cast<GLenum>(i); }

double SceneGL::aspect() const { return static_cast<double>(s_.render.width) / static_cast<double>(s_.render.height); }

// Ambient and up to eight lights in one pass (GL's own sum).
void SceneGL::enableAllLights() {
  gl_.enable(GL_LIGHTING);
  gl_.lightModelfv(GL_LIGHT_MODEL_AMBIENT, glFloats(s_.ambient.x, s_.ambient.y, s_.ambient.z, 1.0f).data());
  const int lights = std::min(kMaxGLLights, static_cast<int>(s_.lights.size()));
  for (int i = 0; i < lights; ++i) {
    gl_.enable(lightName(i));
    setLight(i, s_.lights[static_cast<std::size_t>(i)]);
  }
}
void SceneGL::disableExtraLights() {
  const int lights = std::min(kMaxGLLights, static_cast<int>(s_.lights.size()));
  for (int i = 1; i < lights; ++i) gl_.disable(lightName(i));
}
void SceneGL::setFullMaterial(const SceneMaterial& m) {
  const Vec3 d = m.diffuse;
  gl_.materialfv(GL_FRONT_AND_BACK, GL_AMBIENT, glFloats(d.x, d.y, d.z, 1.0f).data());
  gl_.materialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, glFloats(d.x, d.y, d.z, 1.0f).data());
  gl_.materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, glFloats(m.specular.x, m.specular.y, m.specular.z, 1.0f).data());
  gl_.materialfv(GL_FRONT_AND_BACK, GL_EMISSION, glFloats(m.emission.x, m.emission.y, m.emission.z, 1.0f).data());
  gl_.materialf(GL_FRONT_AND_BACK, GL_SHININESS, m.shininess);
}

void SceneGL::setMaterial(const SceneMaterial& m, bool ambientPass) {
  const Vec3 d = m.diffuse;
  // The ambient pass carries ambient and emission; light passes diffuse and specular.
  if (ambientPass) {
    gl_.materialfv(GL_FRONT_AND_BACK, GL_AMBIENT, glFloats(d.x, d.y, d.z, 1.0f).data());
    gl_.materialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, glFloats(0.0f, 0.0f, 0.0f, 1.0f).data());
    gl_.materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, glFloats(0.0f, 0.0f, 0.0f, 1.0f).data());
    gl_.materialfv(GL_FRONT_AND_BACK, GL_EMISSION, glFloats(m.emission.x, m.emission.y, m.emission.z, 1.0f).data());
  } else {
    gl_.materialfv(GL_FRONT_AND_BACK, GL_AMBIENT, glFloats(0.0f, 0.0f, 0.0f, 1.0f).data());
    gl_.materialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, glFloats(d.x, d.y, d.z, 1.0f).data());
    gl_.materialfv(GL_FRONT_AND_BACK, GL_SPECULAR, glFloats(m.specular.x, m.specular.y, m.specular.z, 1.0f).data());
    gl_.materialfv(GL_FRONT_AND_BACK, GL_EMISSION, glFloats(0.0f, 0.0f, 0.0f, 1.0f).data());
    gl_.materialf(GL_FRONT_AND_BACK, GL_SHININESS, m.shininess);
  }
}

void SceneGL::drawTriangles(const Mesh& mesh, const std::vector<std::uint8_t>* skip, bool turned) {
  const auto skipped = [&](std::size_t t) { return skip && (*skip)[t] != 0; };
  bool any = false;
  for (std::size_t t = 0; t < mesh.triangles.size() && !any; ++t) any = !skipped(t);
  if (!any) return;
  gl_.begin(GL_TRIANGLES);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (skipped(t)) continue;
    const auto& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = tri[static_cast<std::size_t>(turned ? (3 - k) % 3 : k)];
      const Vec3 n = turned ? -mesh.normals[v] : mesh.normals[v], p = mesh.positions[v];
      gl_.normal3f(n.x, n.y, n.z);
      gl_.vertex3f(p.x, p.y, p.z);
    }
  }
  gl_.end();
}

void SceneGL::drawPolygon(const RefFace& face, bool withNormal, bool fromBehind) {
  // From behind (glass has two sides), the polygon turned round: reversed
  // corners, so it stays front-facing under GL_CULL_FACE, and the normal
  // of the side the eye sees, so the light on that side lights it.
  const DVec3 n = fromBehind ? -face.normal : face.normal;
  const std::size_t k = face.polygon.size();
  gl_.begin(GL_POLYGON);
  for (std::size_t i = 0; i < k; ++i) {
    const Vec3& p = face.polygon[fromBehind ? (k - i) % k : i];
    if (withNormal) gl_.normal3f(static_cast<float>(n.x), static_cast<float>(n.y), static_cast<float>(n.z));
    gl_.vertex3f(p.x, p.y, p.z);
  }
  gl_.end();
}

}  // namespace mpr
