#include "algorithms/shadow_pass.hpp"

#include "algorithms/image_samples.hpp"
#include "algorithms/pass_state.hpp"
#include "algorithms/ref_face.hpp"
#include "algorithms/shadow_geometry.hpp"
#include "algorithms/shadow_pivot.hpp"

namespace mpr {

ShadowRole shadowRole(const SceneObject& o, const Scene& scene) {
  const SceneMaterial& m = scene.materials[static_cast<std::size_t>(o.material)];
  if (!o.castsShadows) return ShadowRole::None;
  return isRefMaterial(m, scene.render) ? ShadowRole::SpecularFace : ShadowRole::Caster;
}

VolumeGeometry casterShadowVolume(const SceneObject& o, ShadowRole role, Vec3 light, const BoundingSphere& receivers) {
  // Glass has two sides: a refracting face lit from behind shadows the
  // direct light as one lit from the front does (issue 12, bug 1: the floor
  // beyond it got the direct light and the light passed through); so does
  // the back of a mirror.
  const bool specular = role == ShadowRole::SpecularFace;
  VolumeGeometry v = specular ? twoSidedShadowVolume(o, light, receivers) : objectShadowVolume(o, light, receivers);
  // A specular face is not in the depth buffer (the view through it is), so
  // a ray through it enters its volume by the light cap unseen, which z-pass
  // does not count: counted behind the surface with caps instead.
  v.alwaysZFail = specular;
  return v;
}

ShadowPass::ShadowPass(const Scene& scene, const RenderPlan& plan) : ShadowPass(scene, plan, false) {}

ShadowPass::ShadowPass(const Scene& scene, const RenderPlan& plan, bool pivotBase) : scene_(scene) {
  volumes_.resize(scene.lights.size());
  for (const PointLight& l : scene.lights) lightsAt_.push_back(l.position);
  if (!plan.shadows) return;
  const BoundingSphere bounds = sceneBoundingSphere(scene);
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    // darkness_levels (1994's second method): the volumes of every sample of
    // the light, all counted by one make_all_shadows (image_samples.hpp).
    const PointLight& light = scene.lights[l];
    const int samples = darknessLevelSamples(scene, light);
    for (int i = 0; i < samples; ++i) {
      const Vec3 at = samples > 1 ? lightSamplePosition(scene, light, i) : light.position;
      for (std::size_t oi = 0; oi < scene.objects.size(); ++oi) {
        const SceneObject& o = scene.objects[oi];
        const ShadowRole role = shadowRole(o, scene);
        if (role == ShadowRole::None) continue;
        VolumeGeometry v = casterShadowVolume(o, role, at, bounds);
        if (!v.closed && l == 0 && i == 0 && role == ShadowRole::Caster)
          warnings_.push_back("object '" + o.name + "' (line " + std::to_string(o.line) +
                              ") is not a closed mesh: its shadow volume is open and may count wrongly");
        v.objectIndex = static_cast<int>(oi);
        if (pivotBase && light.radius > 0.0f) {
          v.volume = pivotBaseVolume(v.volume, light.radius);
          setVolumeTriangles(v);
        }
        if (!v.volume.empty()) volumes_[l].push_back(std::move(v));
      }
    }
  }
}

ShadowPass::ShadowPass(const Scene& sampled, const ShadowPass& base)
    : scene_(sampled), volumes_(base.volumes_), lightsAt_(base.lightsAt_), warnings_(base.warnings_) {
  for (std::size_t l = 0; l < volumes_.size() && l < sampled.lights.size(); ++l) {
    const DVec3 jitter = DVec3(sampled.lights[l].position) - DVec3(lightsAt_[l]);
    if (jitter == DVec3(0.0)) continue;
    for (VolumeGeometry& v : volumes_[l]) {
      v.volume = pivotShadowVolume(v.volume, jitter);
      setVolumeTriangles(v);
    }
    lightsAt_[l] = sampled.lights[l].position;
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
                           bool alwaysZFail, bool volumeByVolume) {
  // Count only where the stencil holds a shadow value: the top bit
  // (SHAD_MIN) set, i.e. SHAD_MIN <= stored & SHAD_MIN.
  applyPassState(gl, withStencil(passes::kVolumeCount, {GL_LEQUAL, static_cast<GLint>(lv.shadMin), lv.shadMin,
                                                         lv.max, std::nullopt}));
  // Volumes the near plane cuts are counted behind the surface (z-fail);
  // the eye and the near rectangle are taken into the real scene, where the
  // volumes are.
  Camera projected = camera;
  projected.near = static_cast<float>(view.nearOf(camera));
  const std::array<Vec3, 4> near = nearRectangle(projected, view.world, aspect);
  const DVec3 eye = view.eye(camera);
  std::vector<const VolumeGeometry*> zpass, zfail;
  for (const VolumeGeometry* v : vols)
    (alwaysZFail || v->alwaysZFail || volumeNeedsZFail(*v, Vec3(eye), near) ? zfail : zpass).push_back(v);
  const GLenum up = inverted ? GL_DECR : GL_INCR;
  const GLenum down = inverted ? GL_INCR : GL_DECR;
  if (volumeByVolume) {
    // Each volume's increments then its decrements: the count in between
    // exceeds the pixel's final one by at most the front faces of one volume
    // the ray crosses, where all increments first would add those of every
    // volume the ray passes through (GL_INCR clamps at the maximum: the
    // decrements after it would then undercount).
    for (const VolumeGeometry* v : zpass) {
      gl.cullFace(GL_BACK);
      gl.stencilOp(GL_KEEP, GL_KEEP, up);
      drawTriangles(gl, v->sides);
      gl.cullFace(GL_FRONT);
      gl.stencilOp(GL_KEEP, GL_KEEP, down);
      drawTriangles(gl, v->sides);
    }
    for (const VolumeGeometry* v : zfail) {
      gl.cullFace(GL_FRONT);
      gl.stencilOp(GL_KEEP, up, GL_KEEP);
      drawTriangles(gl, v->sides), drawTriangles(gl, v->caps);
      gl.cullFace(GL_BACK);
      gl.stencilOp(GL_KEEP, down, GL_KEEP);
      drawTriangles(gl, v->sides), drawTriangles(gl, v->caps);
    }
    zpass.clear();
  }
  if (!zpass.empty()) {
    gl.cullFace(GL_BACK);
    gl.stencilOp(GL_KEEP, GL_KEEP, up);
    for (const VolumeGeometry* v : zpass) drawTriangles(gl, v->sides);
    gl.cullFace(GL_FRONT);
    gl.stencilOp(GL_KEEP, GL_KEEP, down);
    for (const VolumeGeometry* v : zpass) drawTriangles(gl, v->sides);
  }
  if (!zfail.empty() && !volumeByVolume) {
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
                                      const StencilLevels& lv, int exclude) {
  std::vector<const VolumeGeometry*> vols;
  for (const VolumeGeometry& v : volumes_[static_cast<std::size_t>(light)])
    if (v.objectIndex != exclude || exclude < 0) vols.push_back(&v);
  // darkness_levels counts S samples' volumes at once: volume by volume.
  const bool levels = darknessLevelSamples(scene_, scene_.lights[static_cast<std::size_t>(light)]) > 1;
  return countVolumes(gl, vols, view, camera,
                      static_cast<double>(scene_.render.width) / static_cast<double>(scene_.render.height), lv, false,
                      false, levels);
}

}  // namespace mpr
