// The scene's materials: mapping: named materials, each a diffuse and
// Phong surface with at most one of the papers' specular effects (its kind).
#include <map>
#include <string>
#include <utility>

#include "scene/scene_section_readers.hpp"
#include "scene/ward_fit.hpp"

namespace mpr {
namespace {

std::string kindName(MaterialKind k) {
  switch (k) {
    case MaterialKind::Diffuse: return "diffuse";
    case MaterialKind::Mirror: return "mirror";
    case MaterialKind::Refractive: return "refractive";
    case MaterialKind::Translucent: return "translucent";
    case MaterialKind::Frosted: return "frosted";
  }
  return "?";
}

// pbrt's rule: a key accepted must count. Each specular kind draws with its
// own keys (algorithms/draw_window.cpp, the reference's ray_tracer.cpp): a
// key this material's kind does not read, at any render setting, is refused
// where it is written, naming the kinds that read it. A value or a kind a
// --set gave is not (scene/keys_count.cpp says why).
void checkMaterialKeysCount(const SceneNodeReader& in, const YAML::Node& n, const SceneMaterial& m, const std::string& where) {
  const MaterialKind k = m.kind;
  const bool mirror = k == MaterialKind::Mirror, frosted = k == MaterialKind::Frosted;
  const bool refracting = k == MaterialKind::Refractive || k == MaterialKind::Translucent || frosted;
  const bool fogged = k == MaterialKind::Translucent || frosted;
  const bool kindBySet = n["kind"] && in.givenBySet(n["kind"]);
  const auto refuse = [&](const char* key, bool uses, const std::string& why) {
    if (uses || !n[key] || kindBySet || in.givenBySet(n[key])) return;
    in.fail(n[key], where + " (kind " + kindName(k) + ") does not use '" + key + "': " + why);
  };
  refuse("reflectance", mirror,
         std::string("only mirrors reflect (kind: mirror)") +
             (refracting ? "; what a refracting face passes on is its transmittance" : ""));
  refuse("ior", refracting, "only refracting materials bend the view through them (kind: refractive, translucent or frosted)");
  refuse("transmittance", refracting,
         std::string("only refracting materials are seen through (kind: refractive, translucent or frosted)") +
             (mirror ? "; what a mirror passes on is its reflectance" : ""));
  refuse("fog_distance", fogged, "only translucent and frosted materials are fogged (kind: translucent or frosted)");
  refuse("shear", frosted,
         std::string("only frosted materials are sheared (kind: frosted)") +
             (mirror ? "; a glossy mirror's view is sheared by its roughness" : ""));
  refuse("samples", frosted || mirror,
         "only frosted materials and glossy mirrors accumulate sheared images (kind: frosted, or kind: mirror with a "
         "roughness)");
  const auto bySet = [&](const char* key) { return n[key] && in.givenBySet(n[key]); };
  // A glossy mirror is one with a roughness (its view sheared by 2 alpha).
  if (mirror && n["samples"] && !n["roughness"] && !bySet("samples"))
    in.fail(n["samples"], where + " (kind mirror) does not use 'samples' without a roughness: only a glossy mirror's "
                                  "view is sheared and accumulated (give roughness, at least 0.125)");
  // The Phong exponent and Ward's alpha shape the highlight, which a zero
  // specular leaves out (GL's and the reference's alike); a mirror's
  // roughness also makes its reflection glossy.
  const bool noSpecular = m.specular == Vec3(0.0f) && !bySet("specular");
  if (noSpecular && n["shininess"] && m.shininess != 0.0f && !bySet("shininess"))
    in.fail(n["shininess"], where + " (kind " + kindName(k) + ") does not use 'shininess' while its specular is 0: "
                                    "shininess shapes the specular highlight (give specular above 0)");
  if (noSpecular && !mirror && n["roughness"] && !bySet("roughness") && !kindBySet)
    in.fail(n["roughness"], where + " (kind " + kindName(k) + ") does not use 'roughness' while its specular is 0: "
                                    "roughness shapes the specular highlight (1997 eq. 6; give specular above 0), and "
                                    "makes only a mirror's reflection glossy (kind: mirror)");
}

SceneMaterial readMaterial(const SceneNodeReader& in, const YAML::Node& n, const std::string& name) {
  const std::string where = "material '" + name + "'";
  in.checkKeys(n, scene_format::kMaterialKeys, where);
  SceneMaterial m;
  m.name = name;
  if (n["kind"]) {
    const std::string k = in.string(n["kind"], where + " kind");
    static const std::map<std::string, MaterialKind> kinds = {
        {"diffuse", MaterialKind::Diffuse}, {"mirror", MaterialKind::Mirror}, {"refractive", MaterialKind::Refractive},
        {"translucent", MaterialKind::Translucent}, {"frosted", MaterialKind::Frosted}};
    const auto it = kinds.find(k);
    if (it == kinds.end())
      in.fail(n["kind"], where + " kind must be diffuse, mirror, refractive, translucent or frosted, not '" + k + "'");
    m.kind = it->second;
  }
  if (n["diffuse"]) m.diffuse = in.rgb(n["diffuse"], where + " diffuse");
  if (n["specular"]) m.specular = in.rgb(n["specular"], where + " specular");
  if (n["emission"]) m.emission = in.rgb(n["emission"], where + " emission");
  if (n["shininess"] && n["roughness"]) in.fail(n["roughness"], where + " gives both shininess and roughness; give one");
  if (n["shininess"]) m.shininess = static_cast<float>(in.number(n["shininess"], where + " shininess", 0.0, 128.0));
  if (n["roughness"]) {
    // 1997 paper eq. (6): the Chi-square fit of Ward's isotropic Gaussian by
    // Phong: exponent 1.999 / alpha^2, scale 0.0398 * exponent.
    const double alpha = in.number(n["roughness"], where + " roughness");
    const double exponent = alpha > 0.0 ? kWardFitExponent / (alpha * alpha) : 1e30;
    if (!(exponent <= 128.0))
      in.fail(n["roughness"], where + " roughness must be at least 0.125: eq. (6) gives a Phong exponent of 1.999/alpha^2, "
                                  "and GL's largest is 128");
    m.shininess = static_cast<float>(exponent);
    m.roughness = static_cast<float>(alpha);
    m.wardSpecular = m.specular;
    m.specular *= static_cast<float>(kWardFitScale * exponent);
  }
  if (n["reflectance"]) m.reflectance = static_cast<float>(in.number(n["reflectance"], where + " reflectance", 0.0, 1.0));
  if (n["ior"]) {
    const double ior = in.number(n["ior"], where + " ior");
    if (ior <= 0.0) in.fail(n["ior"], where + " ior (index of refraction) must be greater than 0, not " + n["ior"].Scalar());
    m.ior = static_cast<float>(ior);
  }
  if (n["transmittance"]) m.transmittance = static_cast<float>(in.number(n["transmittance"], where + " transmittance", 0.0, 1.0));
  if (n["fog_distance"]) m.fogDistance = static_cast<float>(in.number(n["fog_distance"], where + " fog_distance", 0.0, 1e30, true));
  if (n["thickness"]) {
    m.thickness = static_cast<float>(in.number(n["thickness"], where + " thickness", 0.0, 1e6));
    const bool refracting =
        m.kind == MaterialKind::Refractive || m.kind == MaterialKind::Translucent || m.kind == MaterialKind::Frosted;
    if (!refracting && m.thickness > 0.0f)
      in.fail(n["thickness"], where + " thickness is for refracting materials (kind refractive, translucent or frosted): "
                                      "a slab shifts the view through it; this one is not looked through");
  }
  if (n["shear"]) m.shear = static_cast<float>(in.number(n["shear"], where + " shear", 0.0, 1e30));
  if (n["samples"]) m.samples = in.integer(n["samples"], where + " samples", 1, 1024);
  checkMaterialKeysCount(in, n, m, where);
  return m;
}

}  // namespace

std::map<std::string, int> readMaterials(const SceneNodeReader& in, const YAML::Node& map,
                                         std::vector<SceneMaterial>& materials) {
  std::map<std::string, int> index;
  if (!map.IsMap()) in.fail(map, "materials must be a mapping from names to materials");
  in.checkUniqueKeys(map, "materials");
  for (auto it = map.begin(); it != map.end(); ++it) {
    SceneMaterial m = readMaterial(in, it->second, it->first.as<std::string>());
    index[m.name] = static_cast<int>(materials.size());
    materials.push_back(std::move(m));
  }
  return index;
}

}  // namespace mpr
