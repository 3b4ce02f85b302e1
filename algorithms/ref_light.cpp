#include "algorithms/ref_light.hpp"

#include <cmath>
#include <utility>

#include "algorithms/shadow_geometry.hpp"
#include "scene/slab_refraction.hpp"

namespace mpr {

std::optional<DVec3> refLightPosition(const RefFace& f, DVec3 light) {
  const double side = f.side(light);
  if (!(side != 0.0) || !std::isfinite(side)) return std::nullopt;
  if (f.kind == MaterialKind::Mirror) {
    if (side < 0.0) return std::nullopt;  // lit from behind: a mirror passes nothing on
    return reflectPoint(light, f.plane());
  }
  if (f.ior == 1.0) return light;  // no bending: the light itself, bit for bit
  if (f.thickness > 0.0) {
    // A slab (in-out refraction): the light passes parallel to itself,
    // shifted sideways as its ray to the centre is; the virtual light is
    // the light moved by that shift, no critical angle.
    const DVec3 toCentre = f.centre - light;
    if (!(glm::length(toCentre) > 0.0)) return std::nullopt;
    return light + slabShift(glm::normalize(toCentre), f.normal, f.ior, f.thickness);
  }
  // Snell's law at the face centre, n on the light's side, eta = n_light / n_other.
  const DVec3 n = side > 0.0 ? f.normal : -f.normal;
  const double eta = side > 0.0 ? 1.0 / f.ior : f.ior;
  const DVec3 toCentre = f.centre - light;
  const double dist = glm::length(toCentre);
  if (!(dist > 0.0)) return std::nullopt;
  const DVec3 d = toCentre / dist;
  const double cosI = std::min(1.0, -glm::dot(d, n));
  const double sin2T = eta * eta * std::max(0.0, 1.0 - cosI * cosI);
  if (sin2T >= 1.0) return std::nullopt;  // past the critical angle: wholly reflected
  const DVec3 t = eta * d + (eta * cosI - std::sqrt(1.0 - sin2T)) * n;  // the refracted ray, unit
  // Back along the refracted ray by the light's distance: the light turned
  // about the centre by theta_i - theta_t.
  return f.centre - glm::normalize(t) * dist;
}

DVec3 transferThroughFace(const RefFace& f, DVec3 light, DVec3 ref, DVec3 p) {
  if (f.kind == MaterialKind::Mirror) return reflectPoint(p, f.plane());
  if (f.thickness > 0.0) return p + (ref - light);  // a slab: everything moves with the light's shift
  return p + (ref - light) * (f.side(p) / f.side(light));
}

int reflectedLightCount(const Scene& scene, const std::vector<RefFace>& faces) {
  int n = 0;
  for (const PointLight& l : scene.lights)
    for (const RefFace& f : faces) n += refLightPosition(f, DVec3(l.position)).has_value();
  return n;
}

namespace {

// The face as a one-polygon object wound to face `towards` (a light volume is
// the face's shadow volume from the virtual light).
// A slab's light leaves the face shifted with the light: `shift`.
SceneObject faceFacing(const RefFace& f, const std::string& name, DVec3 towards, DVec3 shift = DVec3(0.0)) {
  SceneObject face;
  face.name = name;
  const bool reverse = f.side(towards) < 0.0;
  const std::size_t k = f.polygon.size();
  for (std::size_t i = 0; i < k; ++i) {
    face.mesh.positions.push_back(Vec3(DVec3(f.polygon[reverse ? k - 1 - i : i]) + shift));
    face.mesh.normals.push_back(Vec3(reverse ? -f.normal : f.normal));
  }
  for (std::uint32_t i = 1; i + 1 < k; ++i) face.mesh.triangles.push_back({0, i, i + 1});
  return face;
}

// Every vertex strictly on the side `sign` of the face's plane.
bool whollyOnSide(const Mesh& mesh, const RefFace& f, double sign) {
  if (mesh.positions.empty()) return false;
  for (const Vec3& v : mesh.positions)
    if (!(f.side(DVec3(v)) * sign > 0.0)) return false;
  return true;
}

}  // namespace

std::vector<ReflectedLight> reflectedLights(const Scene& scene, const std::vector<RefFace>& faces) {
  std::vector<ReflectedLight> out;
  const BoundingSphere bounds = sceneBoundingSphere(scene);
  for (std::size_t l = 0; l < scene.lights.size(); ++l)
    for (std::size_t fi = 0; fi < faces.size(); ++fi) {
      const RefFace& f = faces[fi];
      const PointLight& light = scene.lights[l];
      const DVec3 lightPos(light.position);
      const std::optional<DVec3> ref = refLightPosition(f, lightPos);
      if (!ref) continue;
      ReflectedLight r;
      r.light = static_cast<int>(l);
      r.face = static_cast<int>(fi);
      r.virtualLight = light;
      r.virtualLight.position = Vec3(*ref);
      const SceneObject& specular = scene.objects[static_cast<std::size_t>(f.object)];
      const SceneMaterial& m = scene.materials[static_cast<std::size_t>(specular.material)];
      r.virtualLight.color = light.color * (f.kind == MaterialKind::Mirror ? m.reflectance : m.transmittance);
      const DVec3 shift = f.refracts() && f.thickness > 0.0 ? *ref - lightPos : DVec3(0.0);
      r.lightVolume = objectShadowVolume(faceFacing(f, specular.name + " (light volume)", *ref, shift),
                                         r.virtualLight.position, bounds);
      // The light's side of the plane, and the side its light goes on to.
      const double lightSide = f.side(lightPos) > 0.0 ? 1.0 : -1.0;
      const double volumeSide = f.kind == MaterialKind::Mirror ? lightSide : -lightSide;
      for (const SceneObject& o : scene.objects) {
        if (!o.castsShadows || isRefMaterial(scene.materials[static_cast<std::size_t>(o.material)], scene.render))
          continue;
        // CAN'T_INTERSECT: the object stands where the light goes on.
        if (whollyOnSide(o.mesh, f, volumeSide)) {
          VolumeGeometry v = objectShadowVolume(o, r.virtualLight.position, bounds);
          if (!v.volume.empty()) r.shadows.push_back(std::move(v));
        }
        // MUST_INTERSECT: between the light and the face, its shadow falls
        // on the face and is passed on: the volume, from the virtual light,
        // of the object carried through the face (a mirror's: its mirror
        // image behind the face). The carried object is not drawn, so
        // nothing hides its light cap: counted by z-fail.
        if (whollyOnSide(o.mesh, f, lightSide) && shadowCrossesFace(o.mesh, f.polygon, light.position)) {
          SceneObject image = o;
          image.name = o.name + (f.kind == MaterialKind::Mirror ? " (mirror image)" : " (through the face)");
          for (Vec3& p : image.mesh.positions) p = Vec3(transferThroughFace(f, lightPos, *ref, DVec3(p)));
          if (f.kind == MaterialKind::Mirror)
            for (auto& t : image.mesh.triangles) std::swap(t[1], t[2]);  // a reflection turns the winding
          VolumeGeometry v = objectShadowVolume(image, r.virtualLight.position, bounds);
          v.alwaysZFail = true;
          if (!v.volume.empty()) r.shadows.push_back(std::move(v));
        }
      }
      out.push_back(std::move(r));
    }
  return out;
}

}  // namespace mpr
