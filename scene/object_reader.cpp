#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "scene/mesh_loader.hpp"
#include "scene/primitives.hpp"
#include "scene/scene_loader.hpp"
#include "scene/scene_section_readers.hpp"
#include "util/spelling.hpp"
#include "util/transforms.hpp"

namespace mpr {
namespace {

using scene_format::kObjectKeys;

// One object after another, with the scene's triangles so far: the budget
// (kMaxSceneTriangles) is for the whole scene.
class ObjectReader {
 public:
  ObjectReader(const SceneNodeReader& in, bool confine) : in(in), confine(confine) {}

  SceneObject read(const YAML::Node& n, const std::map<std::string, int>& materials, const Scene& s) {
    in.checkKeys(n, kObjectKeys, "an object");
    SceneObject o;
    o.line = n.Mark().line + 1;
    // An object a --set gave has no line in the file: its place in the list.
    o.name = n["name"]             ? in.string(n["name"], "object name")
             : in.givenBySet(n) ? "object " + std::to_string(s.objects.size()) + " of the list"
                                : "object at line " + std::to_string(o.line);
    const std::string where = "object '" + o.name + "'";
    if (n["primitive"] && n["mesh"]) in.fail(n["mesh"], where + " gives both primitive and mesh; give one");
    if (!n["primitive"] && !n["mesh"]) in.fail(n, where + " needs a primitive or a mesh");
    const int sub = n["subdivisions"] ? in.integer(n["subdivisions"], where + " subdivisions", 1, 4096) : 0;
    if (n["primitive"]) {
      const std::string p = in.string(n["primitive"], where + " primitive");
      // Grids grow with the square of their divisions: 1024 gives a quad of
      // 2 M triangles, a box of 12.6 M (about 1 GB of mesh at most).
      if ((p == "box" || p == "quad" || p == "plane") && sub > 1024)
        in.fail(n["subdivisions"], where + " subdivisions must be at most 1024 for a " + p + " (its cells grow with the square), not " +
                                       std::to_string(sub));
      // Checked before the mesh is made: YAML aliases repeat an object at no
      // cost in the file, so the budget is for the whole scene.
      const bool grid = p == "box" || p == "quad" || p == "plane";
      const std::uint64_t d = static_cast<std::uint64_t>(sub ? sub : grid ? 1 : 32);
      const std::uint64_t predicted = p == "box" ? 12 * d * d : p == "sphere" ? 2 * d * std::max<std::uint64_t>(2, d / 2) + 2 * d
                                      : p == "cylinder" ? 4 * d : 2 * d * d;
      checkTriangleBudget(n, where, predicted);
      if (p == "box") o.mesh = makeBox(sub ? sub : 1);
      else if (p == "sphere") o.mesh = makeSphere(sub ? sub : 32, sub ? std::max(2, sub / 2) : 16);
      else if (p == "cylinder") o.mesh = makeCylinder(sub ? std::max(3, sub) : 32);
      else if (p == "quad") o.mesh = makeQuad(sub ? sub : 1), o.castsShadows = false;
      else if (p == "plane") o.mesh = makePlane(sub ? sub : 1), o.castsShadows = false;
      else in.fail(n["primitive"], where + " primitive must be box, sphere, cylinder, quad or plane, not '" + p + "'");
    } else {
      // A mesh is drawn as its file gives it (render.tessellation splits lit
      // faces of any object): subdivisions would count for nothing.
      if (n["subdivisions"] && !in.givenBySet(n["subdivisions"]))
        in.fail(n["subdivisions"], where + " does not use 'subdivisions': only primitives are divided (a mesh is drawn "
                                           "as its file gives it)");
      const std::string rel = in.string(n["mesh"], where + " mesh");
      const std::filesystem::path path = std::filesystem::path(in.file()).parent_path() / rel;
      if (confine) {
        std::error_code ec;
        const auto folder = std::filesystem::weakly_canonical(std::filesystem::absolute(std::filesystem::path(in.file()).parent_path()), ec);
        const auto mesh = std::filesystem::weakly_canonical(std::filesystem::absolute(path), ec);
        const auto inside = mesh.lexically_relative(folder);
        if (ec || std::filesystem::path(rel).is_absolute() || inside.empty() || *inside.begin() == "..")
          in.fail(n["mesh"], where + " mesh '" + rel + "' lies outside the scene's folder, which --confine refuses");
      }
      std::vector<std::string> said;
      try {
        o.mesh = loadMeshFile(path.string(), &said);
        o.meshFile = path.string();
      } catch (const std::exception& e) {
        in.fail(n["mesh"], where + ": " + e.what());
      }
      for (const std::string& w : said) in.warn(n["mesh"], where + ": mesh file '" + path.string() + "': " + w);
      checkTriangleBudget(n["mesh"], where, o.mesh.triangles.size());
    }
    triangles += o.mesh.triangles.size();
    Mat4 m(1.0f);
    // The translation relative to the scene's origin, in double before it is
    // a float (scene/camera_origin.hpp); as written when the origin is 0.
    const Vec3 t(
        (n["translate"] ? in.dvec3(n["translate"], where + " translate") : DVec3(0.0)) - s.origin);
    if (n["translate"] || t != Vec3(0.0f)) m = multiply(m, translationMatrix(t.x, t.y, t.z));
    if (n["rotate"]) {
      const YAML::Node r = n["rotate"];
      if (!r.IsSequence() || r.size() != 4) in.fail(r, where + " rotate must be [degrees, x, y, z]");
      const Vec3 axis(static_cast<float>(in.number(r[1], "rotate x")), static_cast<float>(in.number(r[2], "rotate y")),
                      static_cast<float>(in.number(r[3], "rotate z")));
      if (glm::dot(axis, axis) == 0.0f) in.fail(r, where + " rotate axis must not be zero");
      m = multiply(m, rotationMatrix(static_cast<float>(in.number(r[0], "rotate angle")), axis.x, axis.y, axis.z));
    }
    if (n["scale"]) {
      const YAML::Node sc = n["scale"];
      const Vec3 v = sc.IsScalar() ? Vec3(static_cast<float>(in.number(sc, where + " scale"))) : in.vec3(sc, where + " scale");
      if (v.x == 0.0f || v.y == 0.0f || v.z == 0.0f) in.fail(sc, where + " scale must not be zero");
      m = multiply(m, scaleMatrix(v.x, v.y, v.z));
    }
    transformMesh(o.mesh, m);
    if (n["material"]) {
      const std::string name = in.string(n["material"], where + " material");
      const auto it = materials.find(name);
      if (it == materials.end()) {
        std::vector<std::string_view> names;
        for (const auto& entry : materials) names.push_back(entry.first);
        const std::string best = closestMatch(name, names, 3);
        in.fail(n["material"], where + " uses unknown material '" + name + "'" +
                                   (best.empty() ? "" : "; did you mean '" + best + "'?"));
      }
      o.material = it->second;
    }
    const bool specular = s.materials[static_cast<std::size_t>(o.material)].specularKind();
    if (n["casts_shadows"]) o.castsShadows = in.boolean(n["casts_shadows"], where + " casts_shadows");
    // A mirror or a pane is opaque to the direct light whatever its
    // primitive: quads and planes cast no shadow by default only as walls.
    else if (specular) o.castsShadows = true;
    if (specular) checkPlanarFaces(n, o, where);
    return o;
  }

 private:
  // The papers' specular effects treat every face as a plane with one
  // virtual camera: faces must be planar and have area.
  void checkPlanarFaces(const YAML::Node& n, const SceneObject& o, const std::string& where) const {
    for (std::size_t f = 0; f < o.mesh.faces.size(); ++f) {
      const auto& face = o.mesh.faces[f];
      const Vec3 p0 = o.mesh.positions[face[0]];
      glm::dvec3 normal(0.0);
      for (std::size_t i = 0; i < face.size(); ++i) {  // Newell's normal
        const glm::dvec3 a = o.mesh.positions[face[i]], b = o.mesh.positions[face[(i + 1) % face.size()]];
        normal += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
      }
      const double area2 = glm::length(normal);
      double extent = 0.0;
      for (std::uint32_t v : face) extent = std::max(extent, glm::length(glm::dvec3(o.mesh.positions[v] - p0)));
      if (!(area2 > 1e-12 * std::max(1.0, extent * extent)))
        in.fail(n, where + " has a zero-area face (face " + std::to_string(f) + "); specular objects need faces with area");
      const glm::dvec3 unit = normal / area2;
      for (std::uint32_t v : face) {
        const double d = std::fabs(glm::dot(glm::dvec3(o.mesh.positions[v] - p0), unit));
        if (d > 1e-4 * std::max(1.0, extent))
          in.fail(n, where + " has a non-planar face (face " + std::to_string(f) + ", a corner " + std::to_string(d) +
                         " off its plane); the paper's method needs planar specular faces");
      }
    }
  }

  void checkTriangleBudget(const YAML::Node& at, const std::string& where, std::uint64_t more) const {
    if (triangles + more > kMaxSceneTriangles)
      in.fail(at, where + " would bring the scene to " + std::to_string(triangles + more) + " triangles, more than the " +
                      std::to_string(kMaxSceneTriangles) + " a scene may hold (about 3 GB of mesh)");
  }

  const SceneNodeReader& in;
  bool confine = false;          // meshes only from inside the scene's folder
  std::uint64_t triangles = 0;  // the scene's so far, for the budget
};

}  // namespace

void readObjects(const SceneNodeReader& in, const YAML::Node& list, const std::map<std::string, int>& materials,
                 bool confine, Scene& s) {
  if (!list.IsSequence()) in.fail(list, "objects must be a list");
  in.checkCount(list, "objects", kMaxSceneObjects);
  ObjectReader reader(in, confine);
  for (const YAML::Node& o : list) s.objects.push_back(reader.read(o, materials, s));
}

}  // namespace mpr
