// Every key the scene format accepts changes the render (pbrt's rule: a
// parameter that is accepted and unused is an error): each key of
// describeSceneFormat() has a case below, a context where it matters and a
// change of its value, and the render (its buffers, or its trace where the
// key names things) must differ. A key added to the format without a case
// fails the coverage test. Expectations (expect[]) assert, they never
// change a render: they have their own tests (tests/scene_probes).
#include <gtest/gtest.h>

#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "algorithms/scene_renderer.hpp"
#include "scene/scene_loader.hpp"

namespace mpr {
namespace {

const char* kBase = R"(camera: {position: [0, 2, 6], look_at: [0, 0.5, 0], fov: 45, near: 0.1, far: 40}
ambient: [0.1, 0.1, 0.1]
lights:
  - {position: [2, 4, 3], color: [1, 1, 1], attenuation: [1, 0, 0]}
materials:
  grey: {diffuse: [0.6, 0.6, 0.6]}
  shiny: {diffuse: [0.8, 0.2, 0.1], specular: [0.5, 0.5, 0.5], shininess: 20}
  mirror: {kind: mirror, diffuse: [0.05, 0.05, 0.05], reflectance: 0.8}
  glass: {kind: refractive, diffuse: [0.5, 0.6, 0.7], ior: 1.5, transmittance: 0.7}
objects:
  - {name: floor, primitive: plane, subdivisions: 4, scale: [8, 1, 8], material: grey}
  - {name: box, primitive: box, translate: [-1, 0.5, 0], material: shiny}
  - {name: ball, primitive: sphere, subdivisions: 16, translate: [1, 0.5, -0.5], scale: 0.5, material: shiny}
  - {name: mirror, primitive: quad, translate: [0, 1, -2], scale: [3, 2, 1], material: mirror}
  - {name: pane, primitive: quad, translate: [1.5, 0.7, 1], rotate: [20, 0, 1, 0], scale: [1, 1.4, 1], material: glass}
render: {width: 32, height: 24}
)";

using Edits = std::vector<std::pair<std::string, std::string>>;  // find, replace (first occurrence)

struct KeyCase {
  Edits context;  // makes the key matter
  Edits change;   // changes its value
};

std::string edited(std::string text, const Edits& edits) {
  for (const auto& [from, to] : edits) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << "no '" << from << "' to edit";
    if (at != std::string::npos) text.replace(at, from.size(), to);
  }
  return text;
}

std::string rendered(const std::string& text) {
  const Scene s = loadSceneText(text, "keys.yaml");
  GLContext gl(s.render.width, s.render.height, *findProfile(s.render.profile));
  GLCommandStream stream(gl, true);
  renderScene(s, stream);
  const Framebuffer& fb = gl.framebuffer();
  std::ostringstream o;
  o << fb.width() << "x" << fb.height() << "\n";
  for (const Rgba8& c : fb.colorData()) o.write(reinterpret_cast<const char*>(c.data()), 4);
  for (std::uint32_t d : fb.depthData()) o.write(reinterpret_cast<const char*>(&d), 4);
  for (std::uint8_t st : fb.stencilData()) o.put(static_cast<char>(st));
  for (std::int16_t a : fb.accumData()) o.write(reinterpret_cast<const char*>(&a), 2);
  return o.str() + stream.trace();
}

const std::string kGlassMat = "glass: {kind: refractive, diffuse: [0.5, 0.6, 0.7], ior: 1.5, transmittance: 0.7}";
const std::string kMirrorMat = "mirror: {kind: mirror, diffuse: [0.05, 0.05, 0.05], reflectance: 0.8}";
const std::string kLight = "{position: [2, 4, 3], color: [1, 1, 1], attenuation: [1, 0, 0]}";
const std::string kRender = "render: {width: 32, height: 24}";
const std::string kBox = "{name: box, primitive: box, translate: [-1, 0.5, 0], material: shiny}";

const std::map<std::string, KeyCase>& cases() {
  static const std::map<std::string, KeyCase> c = {
      {"camera", {{}, {{"look_at: [0, 0.5, 0]", "look_at: [0.3, 0.5, 0]"}}}},
      {"camera.position", {{}, {{"position: [0, 2, 6]", "position: [0.5, 2, 6]"}}}},
      {"camera.look_at", {{}, {{"look_at: [0, 0.5, 0]", "look_at: [0, 0.8, 0]"}}}},
      {"camera.up", {{}, {{"far: 40}", "far: 40, up: [0.2, 1, 0]}"}}}},
      {"camera.fov", {{}, {{"fov: 45", "fov: 50"}}}},
      {"camera.near", {{}, {{"near: 0.1", "near: 5"}}}},
      {"camera.far", {{}, {{"far: 40", "far: 6"}}}},
      {"camera.aperture", {{{kRender, "render: {width: 32, height: 24, antialias_samples: 4}"}}, {{"far: 40", "far: 40, aperture: 0.2"}}}},
      {"camera.focal_distance",
       {{{kRender, "render: {width: 32, height: 24, antialias_samples: 4}"}, {"far: 40", "far: 40, aperture: 0.2"}},
        {{"aperture: 0.2", "aperture: 0.2, focal_distance: 3"}}}},
      {"ambient", {{}, {{"ambient: [0.1, 0.1, 0.1]", "ambient: [0.2, 0.1, 0.1]"}}}},
      {"lights[]", {{}, {{"lights:\n", "lights:\n  - {position: [-2, 3, 2]}\n"}}}},
      {"lights[].position", {{}, {{"position: [2, 4, 3]", "position: [2, 4, 2]"}}}},
      {"lights[].color", {{}, {{"color: [1, 1, 1]", "color: [1, 0.5, 1]"}}}},
      {"lights[].attenuation", {{}, {{"attenuation: [1, 0, 0]", "attenuation: [1, 0.1, 0]"}}}},
      {"lights[].radius", {{{kRender, "render: {width: 32, height: 24, soft_shadow_samples: 4}"}},
                           {{"attenuation: [1, 0, 0]}", "attenuation: [1, 0, 0], radius: 0.4}"}}}},
      {"materials.<name>", {{}, {{"grey: {diffuse: [0.6, 0.6, 0.6]}", "grey: {diffuse: [0.6, 0.6, 0.6]}\n  new: {}"},
                                 {"material: grey}", "material: new}"}}}},
      {"materials.<name>.kind", {{}, {{"shiny: {diffuse", "shiny: {kind: translucent, diffuse"}}}},
      {"materials.<name>.diffuse", {{}, {{"grey: {diffuse: [0.6, 0.6, 0.6]}", "grey: {diffuse: [0.6, 0.5, 0.6]}"}}}},
      {"materials.<name>.specular", {{}, {{"specular: [0.5, 0.5, 0.5]", "specular: [0.2, 0.5, 0.5]"}}}},
      {"materials.<name>.shininess", {{}, {{"shininess: 20", "shininess: 5"}}}},
      {"materials.<name>.roughness", {{}, {{"shininess: 20", "roughness: 0.3"}}}},
      {"materials.<name>.emission", {{}, {{"grey: {diffuse: [0.6, 0.6, 0.6]}", "grey: {diffuse: [0.6, 0.6, 0.6], emission: [0.2, 0, 0]}"}}}},
      {"materials.<name>.reflectance", {{}, {{"reflectance: 0.8", "reflectance: 0.5"}}}},
      {"materials.<name>.ior", {{}, {{"ior: 1.5", "ior: 1.3"}}}},
      {"materials.<name>.transmittance", {{}, {{"transmittance: 0.7", "transmittance: 0.4"}}}},
      {"materials.<name>.fog_distance", {{{"kind: refractive", "kind: translucent"}}, {{"transmittance: 0.7", "transmittance: 0.7, fog_distance: 0.5"}}}},
      {"materials.<name>.thickness", {{}, {{"transmittance: 0.7", "transmittance: 0.7, thickness: 0.3"}}}},
      {"materials.<name>.shear", {{{"kind: refractive", "kind: frosted"}}, {{"transmittance: 0.7", "transmittance: 0.7, shear: 0.2"}}}},
      {"materials.<name>.samples", {{{"kind: refractive", "kind: frosted"}}, {{"transmittance: 0.7", "transmittance: 0.7, samples: 3"}}}},
      {"objects[]", {{}, {{"objects:\n", "objects:\n  - {name: extra, primitive: box, translate: [0, 0.3, 2], scale: 0.3}\n"}}}},
      {"objects[].name", {{}, {{"name: mirror", "name: looking glass"}}}},  // in the trace's pass labels
      {"objects[].primitive", {{}, {{"name: box, primitive: box", "name: box, primitive: sphere"}}}},
      {"objects[].mesh", {{}, {{kBox, "{name: box, mesh: " + std::string(MPR_SOURCE_DIR) + "/scenes/meshes/vase.obj, translate: [-1, 0, 0], material: shiny}"}}}},
      {"objects[].subdivisions", {{}, {{"primitive: plane, subdivisions: 4", "primitive: plane, subdivisions: 2"}}}},
      {"objects[].translate", {{}, {{"translate: [-1, 0.5, 0]", "translate: [-1.2, 0.5, 0]"}}}},
      {"objects[].rotate", {{}, {{"translate: [-1, 0.5, 0]", "translate: [-1, 0.5, 0], rotate: [30, 0, 1, 0]"}}}},
      {"objects[].scale", {{}, {{"translate: [-1, 0.5, 0]", "translate: [-1, 0.5, 0], scale: 0.8"}}}},
      {"objects[].material", {{}, {{"translate: [-1, 0.5, 0], material: shiny", "translate: [-1, 0.5, 0], material: grey"}}}},
      {"objects[].casts_shadows", {{}, {{"material: shiny}", "material: shiny, casts_shadows: false}"}}}},
      {"render", {{}, {{kRender, "render: {width: 30, height: 24}"}}}},
      {"render.width", {{}, {{"width: 32", "width: 30"}}}},
      {"render.height", {{}, {{"height: 24", "height: 20"}}}},
      {"render.recursion_depth", {{}, {{kRender, "render: {width: 32, height: 24, recursion_depth: 0}"}}}},
      {"render.shadow_recursion_depth", {{}, {{kRender, "render: {width: 32, height: 24, shadow_recursion_depth: 0}"}}}},
      {"render.light_bounces", {{}, {{kRender, "render: {width: 32, height: 24, light_bounces: 2}"}}}},
      {"render.soft_shadow_samples", {{{kLight, "{position: [2, 4, 3], radius: 0.4}"}}, {{kRender, "render: {width: 32, height: 24, soft_shadow_samples: 3}"}}}},
      {"render.antialias_samples", {{}, {{kRender, "render: {width: 32, height: 24, antialias_samples: 3}"}}}},
      {"render.soft_shadow_method", {{{kLight, "{position: [2, 4, 3], radius: 0.4}"}, {kRender, "render: {width: 32, height: 24, soft_shadow_samples: 3}"}},
                                     {{"soft_shadow_samples: 3", "soft_shadow_samples: 3, soft_shadow_method: darkness_levels"}}}},
      {"render.shadows", {{}, {{kRender, "render: {width: 32, height: 24, shadows: false}"}}}},
      {"render.reflections", {{}, {{kRender, "render: {width: 32, height: 24, reflections: false}"}}}},
      {"render.refractions", {{}, {{kRender, "render: {width: 32, height: 24, refractions: false}"}}}},
      {"render.translucency", {{{"kind: refractive", "kind: translucent"}}, {{kRender, "render: {width: 32, height: 24, translucency: false}"}}}},
      {"render.frosted", {{{"kind: refractive", "kind: frosted"}}, {{kRender, "render: {width: 32, height: 24, frosted: false}"}}}},
      {"render.profile", {{{kRender, "render: {width: 32, height: 24, antialias_samples: 2}"}}, {{"antialias_samples: 2", "antialias_samples: 2, profile: mesa"}}}},
      {"render.refraction_map", {{}, {{kRender, "render: {width: 32, height: 24, refraction_map: projection_zeroed_z}"}}}},
      {"render.tessellation", {{}, {{kRender, "render: {width: 32, height: 24, tessellation: 0.5}"}}}},
  };
  return c;
}

// The keys of the format, from its own description (indentation gives the nesting).
std::set<std::string> formatKeys() {
  std::set<std::string> keys;
  std::istringstream in(describeSceneFormat());
  std::string line, top;
  while (std::getline(in, line)) {
    const std::size_t q = line.find('"'), e = line.find("\": {\"type\"");
    if (q == std::string::npos || e == std::string::npos) continue;
    const std::string name = line.substr(q + 1, e - q - 1);
    if (q == 4) keys.insert(top = name);
    else if (q == 6) keys.insert(top + "." + name);
  }
  return keys;
}

TEST(EveryKey, HasACase) {
  const std::set<std::string> keys = formatKeys();
  EXPECT_GT(keys.size(), 50u);
  for (const std::string& k : keys) {
    if (k.rfind("expect[]", 0) == 0) continue;
    EXPECT_TRUE(cases().count(k)) << "scene key " << k << " has no case: show that it changes the render";
  }
  for (const auto& [k, c] : cases()) EXPECT_TRUE(keys.count(k)) << k << " is not a key of the format";
}

TEST(EveryKey, ChangesTheRender) {
  for (const auto& [key, c] : cases()) {
    if (c.change.empty()) continue;
    const std::string before = edited(kBase, c.context), after = edited(before, c.change);
    EXPECT_NE(rendered(before), rendered(after)) << key << " was accepted and changed nothing";
  }
}

// Every soft-shadow method is built; an unknown one is refused, not ignored.
// pivot renders the images method's passes with pivoted volumes: where the
// silhouette changes with the light samples (the box lit from (2, 4, 3) past
// its corner), its image differs from images'.
TEST(EveryKey, SoftShadowMethods) {
  EXPECT_THROW(loadSceneText(edited(kBase, {{kRender, "render: {width: 32, height: 24, soft_shadow_method: penumbra}"}}), "keys.yaml"),
               SceneError);
  const std::string soft = edited(kBase, {{kLight, "{position: [2, 4, 3], radius: 0.8}"},
                                          {kRender, "render: {width: 32, height: 24, soft_shadow_samples: 4}"}});
  const std::string pivot = edited(soft, {{"soft_shadow_samples: 4", "soft_shadow_samples: 4, soft_shadow_method: pivot"}});
  EXPECT_NE(rendered(soft), rendered(pivot));
}

}  // namespace
}  // namespace mpr
