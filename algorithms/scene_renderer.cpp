#include "algorithms/scene_renderer.hpp"

namespace mpr {
namespace {

void setCamera(const Scene& s, GLCommandStream& gl) {
  const Camera& c = s.camera;
  gl.call(GLCall::Viewport, {0, 0, s.render.width, s.render.height});
  gl.call(GLCall::MatrixMode, {"GL_PROJECTION"});
  gl.call(GLCall::LoadIdentity, {});
  gl.call(GLCall::Perspective, {static_cast<double>(c.fovY),
                                static_cast<double>(s.render.width) / static_cast<double>(s.render.height),
                                static_cast<double>(c.near), static_cast<double>(c.far)});
  gl.call(GLCall::MatrixMode, {"GL_MODELVIEW"});
  gl.call(GLCall::LoadIdentity, {});
  gl.call(GLCall::LookAt, {static_cast<double>(c.position.x), static_cast<double>(c.position.y),
                           static_cast<double>(c.position.z), static_cast<double>(c.lookAt.x),
                           static_cast<double>(c.lookAt.y), static_cast<double>(c.lookAt.z),
                           static_cast<double>(c.up.x), static_cast<double>(c.up.y), static_cast<double>(c.up.z)});
}

void setMaterial(const SceneMaterial& m, GLCommandStream& gl, bool ambientPass) {
  const Vec3 d = m.diffuse;
  // The ambient pass carries ambient and emission; light passes diffuse and specular.
  if (ambientPass) {
    gl.call(GLCall::Materialfv, {"GL_FRONT_AND_BACK", "GL_AMBIENT", d.x, d.y, d.z, 1.0f});
    gl.call(GLCall::Materialfv, {"GL_FRONT_AND_BACK", "GL_DIFFUSE", 0.0f, 0.0f, 0.0f, 1.0f});
    gl.call(GLCall::Materialfv, {"GL_FRONT_AND_BACK", "GL_SPECULAR", 0.0f, 0.0f, 0.0f, 1.0f});
    gl.call(GLCall::Materialfv, {"GL_FRONT_AND_BACK", "GL_EMISSION", m.emission.x, m.emission.y, m.emission.z, 1.0f});
  } else {
    gl.call(GLCall::Materialfv, {"GL_FRONT_AND_BACK", "GL_AMBIENT", 0.0f, 0.0f, 0.0f, 1.0f});
    gl.call(GLCall::Materialfv, {"GL_FRONT_AND_BACK", "GL_DIFFUSE", d.x, d.y, d.z, 1.0f});
    gl.call(GLCall::Materialfv, {"GL_FRONT_AND_BACK", "GL_SPECULAR", m.specular.x, m.specular.y, m.specular.z, 1.0f});
    gl.call(GLCall::Materialfv, {"GL_FRONT_AND_BACK", "GL_EMISSION", 0.0f, 0.0f, 0.0f, 1.0f});
    gl.call(GLCall::Materialf, {"GL_FRONT_AND_BACK", "GL_SHININESS", m.shininess});
  }
}

void drawObjects(const Scene& s, GLCommandStream& gl, bool ambientPass) {
  for (const SceneObject& o : s.objects) {
    setMaterial(s.materials[static_cast<std::size_t>(o.material)], gl, ambientPass);
    gl.call(GLCall::Begin, {"GL_TRIANGLES"});
    for (const auto& t : o.mesh.triangles)
      for (std::uint32_t v : t) {
        const Vec3 n = o.mesh.normals[v], p = o.mesh.positions[v];
        gl.call(GLCall::Normal3f, {n.x, n.y, n.z});
        gl.call(GLCall::Vertex3f, {p.x, p.y, p.z});
      }
    gl.call(GLCall::End, {});
  }
}

}  // namespace

void renderScene(const Scene& s, GLCommandStream& gl, const std::function<void(const RenderProgress&)>& progress) {
  const int passes = 1 + static_cast<int>(s.lights.size());
  auto report = [&](int k, const std::string& label) {
    if (progress) progress({k, passes, label});
  };

  gl.pass("ambient", "ambient: every object lit by the scene ambient only");
  report(1, "ambient");
  gl.call(GLCall::Disable, {"GL_DITHER"});
  gl.call(GLCall::ClearColor, {0.0f, 0.0f, 0.0f, 1.0f});
  gl.call(GLCall::ClearDepth, {1.0});
  gl.call(GLCall::ClearStencil, {0});
  gl.call(GLCall::Clear, {"GL_COLOR_BUFFER_BIT|GL_DEPTH_BUFFER_BIT|GL_STENCIL_BUFFER_BIT"});
  setCamera(s, gl);
  gl.call(GLCall::Enable, {"GL_DEPTH_TEST"});
  gl.call(GLCall::DepthFunc, {"GL_LEQUAL"});
  gl.call(GLCall::Enable, {"GL_CULL_FACE"});
  gl.call(GLCall::Enable, {"GL_LIGHTING"});
  gl.call(GLCall::LightModelfv, {"GL_LIGHT_MODEL_AMBIENT", s.ambient.x, s.ambient.y, s.ambient.z, 1.0f});
  drawObjects(s, gl, true);

  // 1997 paper, section 7.2: each light is added in its own pass, on the
  // pixels the ambient pass left visible (depth equal), with additive blending.
  gl.call(GLCall::LightModelfv, {"GL_LIGHT_MODEL_AMBIENT", 0.0f, 0.0f, 0.0f, 1.0f});
  gl.call(GLCall::Enable, {"GL_LIGHT0"});
  gl.call(GLCall::DepthFunc, {"GL_EQUAL"});
  gl.call(GLCall::DepthMask, {"GL_FALSE"});
  gl.call(GLCall::Enable, {"GL_BLEND"});
  gl.call(GLCall::BlendFunc, {"GL_ONE", "GL_ONE"});
  for (std::size_t i = 0; i < s.lights.size(); ++i) {
    const PointLight& l = s.lights[i];
    gl.pass("light", "light " + std::to_string(i) + ": diffuse and specular, added where depth is equal");
    report(static_cast<int>(i) + 2, "light " + std::to_string(i));
    gl.call(GLCall::Lightfv, {"GL_LIGHT0", "GL_POSITION", l.position.x, l.position.y, l.position.z, 1.0f});
    gl.call(GLCall::Lightfv, {"GL_LIGHT0", "GL_DIFFUSE", l.color.x, l.color.y, l.color.z, 1.0f});
    gl.call(GLCall::Lightfv, {"GL_LIGHT0", "GL_SPECULAR", l.color.x, l.color.y, l.color.z, 1.0f});
    gl.call(GLCall::Lightf, {"GL_LIGHT0", "GL_CONSTANT_ATTENUATION", l.attenuation.x});
    gl.call(GLCall::Lightf, {"GL_LIGHT0", "GL_LINEAR_ATTENUATION", l.attenuation.y});
    gl.call(GLCall::Lightf, {"GL_LIGHT0", "GL_QUADRATIC_ATTENUATION", l.attenuation.z});
    drawObjects(s, gl, false);
  }
  gl.call(GLCall::Disable, {"GL_BLEND"});
  gl.call(GLCall::DepthMask, {"GL_TRUE"});
  gl.call(GLCall::DepthFunc, {"GL_LESS"});
  gl.finish();
}

}  // namespace mpr
