// The scene's lights: list: point lights, with a radius an area light for
// soft shadows.
#include "scene/scene_loader.hpp"
#include "scene/scene_section_readers.hpp"

namespace mpr {
namespace {

PointLight readLight(const SceneNodeReader& in, const YAML::Node& n, DVec3 origin) {
  in.checkKeys(n, scene_format::kLightKeys, "a light");
  PointLight l;
  if (!n["position"]) in.fail(n, "a light needs a position");
  l.position = Vec3(in.dvec3(n["position"], "light position") - origin);
  if (n["color"]) l.color = in.rgb(n["color"], "light color");
  if (n["attenuation"]) {
    l.attenuation = in.rgb(n["attenuation"], "light attenuation");
    if (l.attenuation == Vec3(0.0f)) in.fail(n["attenuation"], "light attenuation must not be all zero");
  }
  if (n["radius"]) l.radius = static_cast<float>(in.number(n["radius"], "light radius", 0.0, 1e30));
  return l;
}

}  // namespace

void readLights(const SceneNodeReader& in, const YAML::Node& list, DVec3 origin, std::vector<PointLight>& lights) {
  if (!list.IsSequence()) in.fail(list, "lights must be a list");
  in.checkCount(list, "lights", kMaxSceneLights);
  for (const YAML::Node& l : list) lights.push_back(readLight(in, l, origin));
}

}  // namespace mpr
