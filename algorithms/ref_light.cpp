#include "algorithms/ref_light.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "algorithms/image_samples.hpp"
#include "algorithms/light_path.hpp"
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
  // Back along the refracted ray to where it meets the perpendicular from
  // the light to the face's plane: the paraxial (sagittal) image of the
  // light seen from the other medium, at the light's distance times
  // n_other / n_light -- the apparent depth at normal incidence, where a
  // point at the light's own distance (the light turned about the centre)
  // spread the light volume wider than the refracted beam (1997 §4.3: the
  // virtual light "approximates the refracted shadow ray direction for
  // paraxial rays"; refraction_plate 7.04 % to 4.81 %, issue 43).
  return f.centre - glm::normalize(t) * (dist / eta);
}

DVec3 transferThroughFace(const RefFace& f, DVec3 light, DVec3 ref, DVec3 p) {
  if (f.kind == MaterialKind::Mirror) return reflectPoint(p, f.plane());
  if (f.thickness > 0.0) return p + (ref - light);  // a slab: everything moves with the light's shift
  return p + (ref - light) * (f.side(p) / f.side(light));
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

// The polygon `poly` (double, any winding) as a one-polygon object wound to
// face `towards`.
SceneObject polygonFacing(const std::vector<DVec3>& poly, const std::string& name, DVec3 towards) {
  std::vector<Vec3> corners;
  for (const DVec3& p : poly) corners.push_back(Vec3(p));
  const Plane plane = planeOfPolygon(corners);
  const bool reverse = plane.signedDistance(towards) < 0.0;
  SceneObject face;
  face.name = name;
  const std::size_t k = corners.size();
  for (std::size_t i = 0; i < k; ++i) {
    face.mesh.positions.push_back(corners[reverse ? k - 1 - i : i]);
    face.mesh.normals.push_back(Vec3(reverse ? -plane.normal : plane.normal));
  }
  for (std::uint32_t i = 1; i + 1 < k; ++i) face.mesh.triangles.push_back({0, i, i + 1});
  return face;
}

// The side of the face's plane the light from `light` goes on to: a
// mirror's light stays on the light's side, a refracting face's crosses.
double outgoingSide(const RefFace& f, DVec3 light) {
  const double lightSide = f.side(light) > 0.0 ? 1.0 : -1.0;
  return f.kind == MaterialKind::Mirror ? lightSide : -lightSide;
}

// Every vertex on the side `sign` of the face's plane, or on the plane
// within `touch` (an object standing on a mirror floor touches it: its
// shadows in the floor's light were lost, issue 43), and some strictly.
bool whollyOnSide(const Mesh& mesh, const RefFace& f, double sign, double touch) {
  bool strictly = false;
  for (const Vec3& v : mesh.positions) {
    const double d = f.side(DVec3(v)) * sign;
    if (!(d >= -touch)) return false;
    strictly = strictly || d > touch;
  }
  return strictly;
}

}  // namespace

std::vector<ReflectedLight> reflectedLights(const Scene& scene, const std::vector<RefFace>& faces, int image) {
  std::vector<ReflectedLight> out;
  const BoundingSphere bounds = sceneBoundingSphere(scene);
  // Touching a face's plane: within float rounding of the scene's size.
  const double touch = 1e-6 * std::max(1.0, bounds.radius + glm::length(bounds.centre));
  for (const LightPath& path : lightPaths(scene, faces, lightBounces(scene.render), kMaxLightPaths)) {
    const std::size_t k = path.faces.size();
    const RefFace& f = faces[static_cast<std::size_t>(path.faces.back())];
    const PointLight& light = scene.lights[static_cast<std::size_t>(path.light)];
    // Frosted glass scatters the light it passes on as it scatters the view
    // through it (1997 §3, "light scattering through the translucent
    // material"): the light beyond the face is sheared about its normal by
    // this image's stochastic shear, so the accumulated images soften the
    // edges of its light volume and of the shadows in it. The shear fixes
    // the face's plane, so it maps the volume from the virtual light
    // through the face onto the volume from the sheared virtual light: every
    // point this light is built from is sheared (the mapped
    // casters' images too); the casters beyond the face are not, their
    // shadows from the sheared light are those of the sheared rays.
    const SceneObject& specular = scene.objects[static_cast<std::size_t>(f.object)];
    const SceneMaterial& lastMaterial = scene.materials[static_cast<std::size_t>(specular.material)];
    const DMat4 scatter = f.kind == MaterialKind::Frosted && scene.render.frosted
                              ? shearAboutFace(f.centre, f.normal,
                                               frostedShear(f.shear, lastMaterial.samples, image, kFrostedLightTable))
                              : DMat4(1.0);
    const auto sheared = [&scatter](DVec3 p) { return DVec3(scatter * DVec4(p, 1.0)); };
    const DVec3 ref = sheared(path.virtualLight());
    ReflectedLight r;
    r.light = path.light;
    r.face = path.faces.back();
    r.path = path.faces;
    r.virtualLight = light;
    r.virtualLight.position = Vec3(ref);
    // The light passed on by every face of the path.
    for (const int fi : path.faces) {
      const RefFace& pf = faces[static_cast<std::size_t>(fi)];
      const SceneMaterial& m =
          scene.materials[static_cast<std::size_t>(scene.objects[static_cast<std::size_t>(pf.object)].material)];
      r.virtualLight.color *= pf.kind == MaterialKind::Mirror ? m.reflectance : m.transmittance;
    }
    // The constituent light volumes (1997 §4.2): the earlier faces carried
    // into this light's space, then the last face (a slab's shifted).
    for (std::size_t i = 0; i + 1 < k; ++i) {
      const std::string& name = scene.objects[static_cast<std::size_t>(
          faces[static_cast<std::size_t>(path.faces[i])].object)].name;
      std::vector<DVec3> aperture = path.apertures[i];
      for (DVec3& p : aperture) p = sheared(p);
      r.lightVolumes.push_back(objectShadowVolume(polygonFacing(aperture, name + " (light volume, carried)", ref),
                                                  r.virtualLight.position, bounds));
    }
    SceneObject lastFace =
        faceFacing(f, specular.name + " (light volume)", ref, leavingShift(f, path.lights[k - 1], path.virtualLight()));
    for (Vec3& p : lastFace.mesh.positions) p = Vec3(sheared(DVec3(p)));
    r.lightVolumes.push_back(objectShadowVolume(lastFace, r.virtualLight.position, bounds));
    // A slab passes light on only where it stands in the light's way: a ray
    // that enters near an edge and is shifted past it leaves by the slab's
    // side, not its far face. So the shifted light volume is cut to the
    // face's own shadow from the light before it, and no sliver beside the
    // slab's shadow gets the direct and the passed-on light both (1 + T).
    if (f.refracts() && f.thickness > 0.0) {
      const DVec3 before = sheared(path.lights[k - 1]);
      r.lightVolumes.push_back(
          objectShadowVolume(faceFacing(f, specular.name + " (its own shadow)", before), Vec3(before), bounds));
    }
    for (std::size_t oi = 0; oi < scene.objects.size(); ++oi) {
      const SceneObject& o = scene.objects[oi];
      const ShadowRole role = shadowRole(o, scene);
      if (role == ShadowRole::None) continue;
      // The faces the light passed pass it on (their light volumes); every
      // other specular face blocks it as any caster does (a second mirror
      // between the first and the floor: issue 43).
      bool onPath = false;
      for (const int fi : path.faces) onPath = onPath || faces[static_cast<std::size_t>(fi)].object == static_cast<int>(oi);
      if (onPath) continue;
      // CAN'T_INTERSECT: the object stands where the light goes on from the
      // last face.
      if (whollyOnSide(o.mesh, f, outgoingSide(f, path.lights[k - 1]), touch)) {
        VolumeGeometry v = casterShadowVolume(o, role, r.virtualLight.position, bounds);
        if (!v.volume.empty()) r.shadows.push_back(std::move(v));
      }
      // MUST_INTERSECT, for every stretch of the path: between the light (or
      // the face before) and face i, its shadow from the light of that
      // stretch falls on face i and is passed on: the volume, from the last
      // virtual light, of the object carried through faces i.. (a mirror's:
      // its mirror image behind the face). The carried object is not drawn,
      // so nothing hides its light cap: counted by z-fail.
      for (std::size_t i = 0; i < k; ++i) {
        const RefFace& fi = faces[static_cast<std::size_t>(path.faces[i])];
        const DVec3 before = path.lights[i];
        if (!whollyOnSide(o.mesh, fi, fi.side(before) > 0.0 ? 1.0 : -1.0, touch)) continue;
        if (i > 0) {
          const RefFace& prev = faces[static_cast<std::size_t>(path.faces[i - 1])];
          if (!whollyOnSide(o.mesh, prev, outgoingSide(prev, path.lights[i - 1]), touch)) continue;
        }
        if (!shadowCrossesFace(o.mesh, fi.polygon, i == 0 ? light.position : Vec3(before))) continue;
        SceneObject image = o;
        image.name = o.name + (k == 1 ? (fi.kind == MaterialKind::Mirror ? " (mirror image)" : " (through the face)")
                                      : " (carried along the light path)");
        for (Vec3& p : image.mesh.positions) p = Vec3(sheared(carryAlongPath(path, faces, i, DVec3(p))));
        if (carryTurnsWinding(path, faces, i))
          for (auto& t : image.mesh.triangles) std::swap(t[1], t[2]);  // a reflection turns the winding
        VolumeGeometry v = casterShadowVolume(image, role, r.virtualLight.position, bounds);
        v.alwaysZFail = true;
        if (!v.volume.empty()) r.shadows.push_back(std::move(v));
      }
    }
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace mpr
