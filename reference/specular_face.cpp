#include "reference/specular_face.hpp"

#include <cmath>

namespace mpr {

bool SpecularFace::contains(DVec3 p) const {
  const int u = dropAxis == 0 ? 1 : 0, v = dropAxis == 2 ? 1 : 2;
  bool inside = false;
  const std::size_t k = polygon.size();
  for (std::size_t i = 0, j = k - 1; i < k; j = i++) {
    const DVec3 &a = polygon[i], &b = polygon[j];
    if ((a[v] > p[v]) != (b[v] > p[v]) && p[u] < (b[u] - a[u]) * (p[v] - a[v]) / (b[v] - a[v]) + a[u]) inside = !inside;
  }
  return inside;
}

bool SpecularFace::crossing(DVec3 a, DVec3 b, DVec3& x) const {
  const double sa = side(a), sb = side(b);
  if (!((sa > 0.0 && sb < 0.0) || (sa < 0.0 && sb > 0.0))) return false;
  x = a + (b - a) * (sa / (sa - sb));
  return true;
}

std::vector<SpecularFace> findSpecularFaces(const Scene& scene) {
  std::vector<SpecularFace> faces;
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const SceneObject& obj = scene.objects[o];
    const SceneMaterial& m = scene.materials[static_cast<std::size_t>(obj.material)];
    if (m.kind == MaterialKind::Diffuse) continue;
    for (const auto& poly : obj.mesh.faces) {
      SpecularFace f;
      f.object = static_cast<int>(o);
      f.kind = m.kind;
      f.weight = m.kind == MaterialKind::Mirror ? m.reflectance : m.transmittance;
      f.ior = m.ior;
      f.thickness = m.thickness;
      if (m.kind == MaterialKind::Frosted) f.shear = m.shear;
      DVec3 newell(0.0), centre(0.0);
      for (std::size_t i = 0; i < poly.size(); ++i) {
        const DVec3 a(obj.mesh.positions[poly[i]]), b(obj.mesh.positions[poly[(i + 1) % poly.size()]]);
        newell += DVec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
        centre += a;
        f.polygon.push_back(a);
      }
      if (poly.size() < 3 || !(glm::length(newell) > 0.0)) continue;
      f.normal = glm::normalize(newell);
      f.centre = centre / static_cast<double>(poly.size());
      f.offset = glm::dot(f.normal, f.centre);
      for (const DVec3& p : f.polygon) f.radius = std::max(f.radius, glm::length(p - f.centre));
      const DVec3 an = glm::abs(f.normal);
      f.dropAxis = an.x > an.y && an.x > an.z ? 0 : (an.y > an.z ? 1 : 2);
      faces.push_back(std::move(f));
    }
  }
  return faces;
}

}  // namespace mpr
