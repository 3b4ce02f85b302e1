#include "reference/accuracy/sweep.hpp"

#include <algorithm>
#include <cstdint>
#include <sstream>
#include <stdexcept>

#include "algorithms/light_path.hpp"

namespace mpr {
namespace {

std::vector<std::string> splitCommas(const std::string& s) {
  std::vector<std::string> out;
  std::string cur;
  std::istringstream in(s);
  while (std::getline(in, cur, ',')) out.push_back(cur);
  if (!s.empty() && s.back() == ',') out.push_back("");
  return out;
}

std::string vec(const Vec3& v) {
  std::ostringstream o;
  o.precision(9);
  o << "[" << v.x << ", " << v.y << ", " << v.z << "]";
  return o.str();
}

std::string refractionMapName(RefractionMap m) {
  switch (m) {
    case RefractionMap::ProjectionKeptZ: return "projection";
    case RefractionMap::ProjectionZeroedZ: return "projection_zeroed_z";
    case RefractionMap::EndOfPipeline: return "end_of_pipeline";
  }
  return "?";
}

}  // namespace

VaryKey parseVary(const std::string& argument) {
  const std::size_t eq = argument.find('=');
  if (eq == std::string::npos || eq == 0)
    throw std::invalid_argument("--vary '" + argument + "' must be KEY=V1,V2,... (e.g. render.recursion_depth=0,1,2)");
  VaryKey k{argument.substr(0, eq), splitCommas(argument.substr(eq + 1))};
  if (k.values.empty()) throw std::invalid_argument("--vary '" + argument + "' gives no value for " + k.key);
  for (const std::string& v : k.values)
    if (v.empty()) throw std::invalid_argument("--vary '" + argument + "' has an empty value");
  return k;
}

std::vector<VaryKey> defaultSweep() {
  return {{"render.recursion_depth", {"0", "1", "2", "3"}},
          {"render.shadow_recursion_depth", {"0", "1", "2"}},
          {"render.light_bounces", {"1", "2", "3"}},
          {"render.shadows", {"true", "false"}},
          {"render.refraction_map", {"projection", "projection_zeroed_z", "end_of_pipeline"}},
          {"render.tessellation", {"1", "0.5", "0.25"}},
          {"render.antialias_samples", {"4", "16"}},
          {"render.soft_shadow_samples", {"4", "16"}}};
}

std::vector<std::string> SweepSetting::sets() const {
  std::vector<std::string> s;
  for (const auto& [k, v] : overrides) s.push_back(k + "=" + v);
  return s;
}

std::string SweepSetting::label() const {
  if (overrides.empty()) return "scene";
  std::string l;
  for (const auto& [k, v] : overrides) l += (l.empty() ? "" : " ") + k + "=" + v;
  return l;
}

std::vector<SweepSetting> expandSweep(const std::vector<VaryKey>& keys, bool product) {
  std::vector<SweepSetting> out{SweepSetting{}};
  if (!product) {
    for (const VaryKey& k : keys)
      for (const std::string& v : k.values) out.push_back(SweepSetting{{{k.key, v}}});
    return out;
  }
  for (const VaryKey& k : keys) {
    std::vector<SweepSetting> next;
    for (const SweepSetting& s : out)
      for (const std::string& v : k.values) {
        SweepSetting t = s;
        t.overrides.emplace_back(k.key, v);
        next.push_back(t);
      }
    out = next;
  }
  out.insert(out.begin(), SweepSetting{});  // the scene itself first; removed as a duplicate when it is one
  return out;
}

std::vector<std::string> singlePassSets() {
  return {"render.shadows=false", "render.reflections=false", "render.refractions=false",
          "render.translucency=false", "render.frosted=false", "render.antialias_samples=1",
          "render.soft_shadow_samples=1", "camera.aperture=0"};
}

namespace {
// FNV-1a over raw bytes: every vertex, normal and index of a mesh.
template <class T>
void hashBytes(std::uint64_t& h, const std::vector<T>& v) {
  const auto* p = reinterpret_cast<const unsigned char*>(v.data());
  for (std::size_t i = 0; i < v.size() * sizeof(T); ++i) h = (h ^ p[i]) * 1099511628211ull;
}
}  // namespace

std::string sceneFingerprint(const Scene& s) {
  std::ostringstream o;
  o.precision(9);
  const Camera& c = s.camera;
  o << vec(c.position) << vec(c.lookAt) << vec(c.up) << c.fovY << ' ' << c.near << ' ' << c.far << ' ' << c.aperture
    << ' ' << c.focalDistance << vec(s.ambient);
  for (const PointLight& l : s.lights) o << "L" << vec(l.position) << vec(l.color) << vec(l.attenuation) << l.radius;
  for (const SceneMaterial& m : s.materials)
    o << "M" << static_cast<int>(m.kind) << vec(m.diffuse) << vec(m.specular) << vec(m.emission) << m.shininess << ' '
      << m.reflectance << ' ' << m.ior << ' ' << m.transmittance << ' ' << m.fogDistance << ' ' << m.shear << ' '
      << m.samples << ' ' << m.roughness << vec(m.wardSpecular) << m.thickness;
  for (const SceneObject& ob : s.objects) {
    std::uint64_t h = 14695981039346656037ull;
    hashBytes(h, ob.mesh.positions), hashBytes(h, ob.mesh.normals), hashBytes(h, ob.mesh.triangles);
    o << "O" << ob.material << ob.castsShadows << ' ' << ob.mesh.positions.size() << ' ' << ob.mesh.triangles.size()
      << ' ' << ob.mesh.faces.size() << ' ' << h;
  }
  for (const char* k : {"render.width", "render.height", "render.recursion_depth", "render.shadow_recursion_depth",
                        "render.light_bounces", "render.soft_shadow_samples", "render.soft_shadow_method",
                        "render.antialias_samples", "render.shadows", "render.reflections", "render.refractions",
                        "render.translucency", "render.frosted", "render.profile", "render.refraction_map",
                        "render.tessellation"})
    o << "R" << *sceneValue(s, k);
  return o.str();
}

std::optional<std::string> sceneValue(const Scene& s, const std::string& key) {
  const RenderSettings& r = s.render;
  const auto b = [](bool v) { return std::string(v ? "true" : "false"); };
  std::ostringstream num;
  num.precision(9);
  if (key == "render.width") return std::to_string(r.width);
  if (key == "render.height") return std::to_string(r.height);
  if (key == "render.recursion_depth") return std::to_string(r.recursionDepth);
  if (key == "render.shadow_recursion_depth") return std::to_string(r.shadowRecursionDepth);
  if (key == "render.light_bounces") return std::to_string(lightBounces(r));
  if (key == "render.soft_shadow_samples") return std::to_string(r.softShadowSamples);
  if (key == "render.soft_shadow_method")
    return std::string(r.softShadowMethod == SoftShadowMethod::Images           ? "images"
                       : r.softShadowMethod == SoftShadowMethod::DarknessLevels ? "darkness_levels"
                                                                                : "pivot");
  if (key == "render.antialias_samples") return std::to_string(r.antialiasSamples);
  if (key == "render.shadows") return b(r.shadows);
  if (key == "render.reflections") return b(r.reflections);
  if (key == "render.refractions") return b(r.refractions);
  if (key == "render.translucency") return b(r.translucency);
  if (key == "render.frosted") return b(r.frosted);
  if (key == "render.profile") return r.profile;
  if (key == "render.refraction_map") return refractionMapName(r.refractionMap);
  if (key == "render.tessellation") return (num << r.tessellation, num.str());
  if (key == "camera.fov") return (num << s.camera.fovY, num.str());
  if (key == "camera.near") return (num << s.camera.near, num.str());
  if (key == "camera.far") return (num << s.camera.far, num.str());
  return std::nullopt;
}

}  // namespace mpr
