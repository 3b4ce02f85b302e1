#include "algorithms/ref_light.hpp"

#include <utility>

#include "algorithms/shadow_geometry.hpp"

namespace mpr {
namespace {

bool lightsFace(const PointLight& l, const RefFace& f) { return f.kind == MaterialKind::Mirror && f.side(DVec3(l.position)) > 0.0; }

}  // namespace

int reflectedLightCount(const Scene& scene, const std::vector<RefFace>& faces) {
  int n = 0;
  for (const PointLight& l : scene.lights)
    for (const RefFace& f : faces) n += lightsFace(l, f);
  return n;
}

std::vector<ReflectedLight> reflectedLights(const Scene& scene, const std::vector<RefFace>& faces) {
  std::vector<ReflectedLight> out;
  const BoundingSphere bounds = sceneBoundingSphere(scene);
  for (std::size_t l = 0; l < scene.lights.size(); ++l)
    for (std::size_t fi = 0; fi < faces.size(); ++fi) {
      const RefFace& f = faces[fi];
      const PointLight& light = scene.lights[l];
      if (!lightsFace(light, f)) continue;
      ReflectedLight r;
      r.light = static_cast<int>(l);
      r.face = static_cast<int>(fi);
      r.virtualLight = light;
      r.virtualLight.position = reflectPoint(light.position, f.plane());
      const SceneObject& mirror = scene.objects[static_cast<std::size_t>(f.object)];
      r.virtualLight.color = light.color * scene.materials[static_cast<std::size_t>(mirror.material)].reflectance;
      // The light volume is the face's own shadow volume from the virtual
      // light, which sits behind it: the face wound the other way round.
      SceneObject face;
      face.name = mirror.name + " (light volume)";
      for (std::size_t i = 0; i < f.polygon.size(); ++i) {
        face.mesh.positions.push_back(f.polygon[f.polygon.size() - 1 - i]);
        face.mesh.normals.push_back(Vec3(-f.normal));
      }
      for (std::uint32_t i = 1; i + 1 < f.polygon.size(); ++i) face.mesh.triangles.push_back({0, i, i + 1});
      r.lightVolume = objectShadowVolume(face, r.virtualLight.position, bounds);
      for (const SceneObject& o : scene.objects) {
        if (!o.castsShadows || isRefMaterial(scene.materials[static_cast<std::size_t>(o.material)], scene.render))
          continue;
        bool inFront = !o.mesh.positions.empty();
        for (const Vec3& v : o.mesh.positions) inFront = inFront && f.side(DVec3(v)) > 0.0;
        if (!inFront) continue;
        // CAN'T_INTERSECT: the object stands in the reflected light itself.
        VolumeGeometry v = objectShadowVolume(o, r.virtualLight.position, bounds);
        if (!v.volume.empty()) r.shadows.push_back(std::move(v));
        // MUST_INTERSECT: its shadow from the real light falls on the face, so
        // the face reflects that shadow into its light volume: the volume of
        // the object's mirror image (behind the face) from the virtual light.
        if (shadowCrossesFace(o.mesh, f.polygon, light.position)) {
          SceneObject image = o;
          image.name = o.name + " (mirror image)";
          for (Vec3& p : image.mesh.positions) p = reflectPoint(p, f.plane());
          for (auto& t : image.mesh.triangles) std::swap(t[1], t[2]);  // a reflection turns the winding
          VolumeGeometry m = objectShadowVolume(image, r.virtualLight.position, bounds);
          m.alwaysZFail = true;
          if (!m.volume.empty()) r.shadows.push_back(std::move(m));
        }
      }
      out.push_back(std::move(r));
    }
  return out;
}

}  // namespace mpr
