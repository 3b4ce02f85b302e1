// The scene's materials: mapping: named materials, each a diffuse and
// Phong surface with at most one of the papers' specular effects (its kind).
#include <map>
#include <string>
#include <utility>

#include "scene/scene_section_readers.hpp"
#include "scene/ward_fit.hpp"

namespace mpr {
namespace {

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
