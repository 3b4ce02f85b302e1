#include "algorithms/ref_face.hpp"

namespace mpr {

std::vector<RefFace> findRefFaces(const Scene& scene) {
  std::vector<RefFace> faces;
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const SceneObject& obj = scene.objects[o];
    const SceneMaterial& m = scene.materials[static_cast<std::size_t>(obj.material)];
    if (!isRefMaterial(m, scene.render)) continue;
    for (const auto& poly : obj.mesh.faces) {
      RefFace f;
      f.object = static_cast<int>(o);
      f.kind = m.kind;
      f.ior = m.ior;
      f.thickness = m.thickness;
      f.fogDistance = m.fogDistance;
      f.shear = m.shear;
      f.color = m.diffuse;
      DVec3 newell(0.0), centre(0.0);
      for (std::size_t i = 0; i < poly.size(); ++i) {
        const DVec3 a(obj.mesh.positions[poly[i]]), b(obj.mesh.positions[poly[(i + 1) % poly.size()]]);
        newell += DVec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
        centre += a;
        f.polygon.push_back(obj.mesh.positions[poly[i]]);
      }
      f.normal = glm::normalize(newell);
      f.centre = centre / static_cast<double>(poly.size());
      f.offset = glm::dot(f.normal, f.centre);
      faces.push_back(std::move(f));
    }
  }
  return faces;
}

}  // namespace mpr
