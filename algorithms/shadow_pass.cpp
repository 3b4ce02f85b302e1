#include "algorithms/shadow_pass.hpp"

#include "algorithms/pass_state.hpp"
#include "algorithms/ref_face.hpp"
#include "algorithms/shadow_geometry.hpp"

namespace mpr {

ShadowRole shadowRole(const SceneObject& o, const Scene& scene) {
  const SceneMaterial& m = scene.materials[static_cast<std::size_t>(o.material)];
  if (!isRefMaterial(m, scene.render)) return o.castsShadows ? ShadowRole::Caster : ShadowRole::None;
  return refracts(m.kind) ? ShadowRole::RefractingFace : ShadowRole::None;
}

ShadowPass::ShadowPass(const Scene& scene, const RenderPlan& plan) : scene_(scene) {
  volumes_.resize(scene.lights.size());
  if (!plan.shadows) return;
  const BoundingSphere bounds = sceneBoundingSphere(scene);
  for (std::size_t l = 0; l < scene.lights.size(); ++l)
    for (const SceneObject& o : scene.objects) {
      const ShadowRole role = shadowRole(o, scene);
      if (role == ShadowRole::None) continue;
      // Glass has two sides: a refracting face lit from behind shadows the
      // direct light as one lit from the front does (issue 12, bug 1: the
      // floor beyond it got the direct light and the light passed through).
      VolumeGeometry v = role == ShadowRole::RefractingFace
                             ? twoSidedShadowVolume(o, scene.lights[l].position, bounds)
                             : objectShadowVolume(o, scene.lights[l].position, bounds);
      if (!v.closed && l == 0 && role == ShadowRole::Caster)
        warnings_.push_back("object '" + o.name + "' (line " + std::to_string(o.line) +
                            ") is not a closed mesh: its shadow volume is open and may count wrongly");
      // A refracting face is not in the depth buffer (the view through it is),
      // so a ray through it enters its volume by the light cap unseen, which
      // z-pass does not count: counted behind the surface with caps instead.
      v.alwaysZFail = role == ShadowRole::RefractingFace;
      if (!v.volume.empty()) volumes_[l].push_back(std::move(v));
    }
}

namespace {

void drawTriangles(GLApi& gl, const std::vector<std::array<Vec3, 3>>& tris) {
  gl.begin(GL_TRIANGLES);
  for (const auto& t : tris)
    for (const Vec3& p : t) gl.vertex3f(p.x, p.y, p.z);
  gl.end();
}

}  // namespace

std::uint64_t countVolumes(GLApi& gl, const std::vector<const VolumeGeometry*>& vols, const ViewCamera& view,
                           const Camera& camera, double aspect, const StencilLevels& lv, bool inverted,
                           bool alwaysZFail) {
  // Count only where the stencil holds a shadow value: the top bit
  // (SHAD_MIN) set, i.e. SHAD_MIN <= stored & SHAD_MIN.
  applyPassState(gl, withStencil(passes::kVolumeCount, {GL_LEQUAL, static_cast<GLint>(lv.shadMin), lv.shadMin,
                                                         lv.max, std::nullopt}));
  // Volumes the near plane cuts are counted behind the surface (z-fail);
  // the eye and the near rectangle are taken into the real scene, where the
  // volumes are.
  const std::array<Vec3, 4> near = nearRectangle(camera, view.world, aspect);
  const DVec3 eye = view.eye(camera);
  std::vector<const VolumeGeometry*> zpass, zfail;
  for (const VolumeGeometry* v : vols)
    (alwaysZFail || v->alwaysZFail || volumeNeedsZFail(*v, Vec3(eye), near) ? zfail : zpass).push_back(v);
  const GLenum up = inverted ? GL_DECR : GL_INCR;
  const GLenum down = inverted ? GL_INCR : GL_DECR;
  if (!zpass.empty()) {
    gl.cullFace(GL_BACK);
    gl.stencilOp(GL_KEEP, GL_KEEP, up);
    for (const VolumeGeometry* v : zpass) drawTriangles(gl, v->sides);
    gl.cullFace(GL_FRONT);
    gl.stencilOp(GL_KEEP, GL_KEEP, down);
    for (const VolumeGeometry* v : zpass) drawTriangles(gl, v->sides);
  }
  if (!zfail.empty()) {
    gl.cullFace(GL_FRONT);
    gl.stencilOp(GL_KEEP, up, GL_KEEP);
    for (const VolumeGeometry* v : zfail) drawTriangles(gl, v->sides), drawTriangles(gl, v->caps);
    gl.cullFace(GL_BACK);
    gl.stencilOp(GL_KEEP, down, GL_KEEP);
    for (const VolumeGeometry* v : zfail) drawTriangles(gl, v->sides), drawTriangles(gl, v->caps);
  }
  gl.cullFace(GL_BACK);
  gl.stencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  applyPassState(gl, passes::kWritesOn);
  return zfail.size();
}

std::uint64_t ShadowPass::drawVolumes(GLApi& gl, int light, const ViewCamera& view, const Camera& camera,
                                      const StencilLevels& lv) {
  std::vector<const VolumeGeometry*> vols;
  for (const VolumeGeometry& v : volumes_[static_cast<std::size_t>(light)]) vols.push_back(&v);
  return countVolumes(gl, vols, view, camera,
                      static_cast<double>(scene_.render.width) / static_cast<double>(scene_.render.height), lv, false);
}

}  // namespace mpr
