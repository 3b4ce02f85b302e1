// pbrt's rule (issue 43): a key the scene format accepts must change the
// image, or be refused, or, where mpr reference alone uses it, be warned
// about once. The keys come from the format's own description
// (describeSceneFormat, what mpr render --describe-format prints): each has
// a case below, a scene where it should matter rendered with and without a
// change of its value, and the render must differ; a key added to the
// format without a case fails HasACase. Where a key counts for nothing (a
// kind that does not read it, a render setting with nothing to act on) the
// loader refuses it at its line and column: each refusal's exact message is
// held below, and RefusedKeysChangeNothing shows, on the scene model, that
// the render is indeed the same whatever the refused value.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "algorithms/scene_expectations.hpp"
#include "algorithms/scene_renderer.hpp"
#include "scene/scene_loader.hpp"

// A namespace of its own: the suite is compiled in batches (unity builds).
namespace mpr::every_key_test {
namespace {

// Every kind of face the keys act on: diffuse, Phong, a mirror and a pane
// of glass (the change of medium, so that its view is mapped), one light.
const char* kBase = R"(camera: {position: [0, 2, 6], look_at: [0, 0.5, 0], fov: 45, near: 0.1, far: 40}
ambient: [0.1, 0.1, 0.1]
lights:
  - {position: [2, 4, 3], color: [1, 1, 1], attenuation: [1, 0, 0]}
materials:
  grey: {diffuse: [0.6, 0.6, 0.6]}
  shiny: {diffuse: [0.8, 0.2, 0.1], specular: [0.5, 0.5, 0.5], shininess: 20}
  mirror: {kind: mirror, diffuse: [0.3, 0.05, 0.05], reflectance: 0.8}
  glass: {kind: refractive, diffuse: [0.5, 0.6, 0.7], ior: 1.5, transmittance: 0.7}
objects:
  - {name: floor, primitive: plane, subdivisions: 4, scale: [8, 1, 8], material: grey}
  - {name: box, primitive: box, translate: [-1, 0.5, 0], material: shiny}
  - {name: ball, primitive: sphere, subdivisions: 16, translate: [1, 0.5, -0.5], scale: 0.5, material: shiny}
  - {name: mirror, primitive: quad, translate: [0, 1, -2], scale: [3, 2, 1], material: mirror}
  - {name: pane, primitive: quad, translate: [1.5, 0.7, 1], rotate: [20, 0, 1, 0], scale: [1, 1.4, 1], material: glass}
render: {width: 48, height: 36}
)";

using Edits = std::vector<std::pair<std::string, std::string>>;  // find, replace (first occurrence)

std::string edited(std::string text, const Edits& edits) {
  for (const auto& [from, to] : edits) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << "no '" << from << "' to edit";
    if (at != std::string::npos) text.replace(at, from.size(), to);
  }
  return text;
}

// What a case looks at: the image (every key that draws), the pass labels
// (names, which the format gives "for messages and statistics") or the
// expectations' outcomes (expect:, which reads the buffers and draws
// nothing).
enum class Seen { Image, PassLabels, Expectations };

struct KeyCase {
  Edits context;  // makes the key matter
  Edits change;   // changes its value
  Seen seen = Seen::Image;
};

std::string seenOf(const Scene& s, Seen seen) {
  GLContext gl(s.render.width, s.render.height, *findProfile(s.render.profile));
  GLCommandStream stream(gl, false);
  std::ostringstream o;
  if (seen == Seen::PassLabels) stream.onPassEnd([&](const std::string& label) { o << label << "\n"; });
  std::optional<SceneExpectationWatcher> watcher;
  if (seen == Seen::Expectations) watcher.emplace(s, stream, gl);
  renderScene(s, stream);
  stream.endPasses();
  if (watcher) {
    watcher->finish();
    for (const ExpectationOutcome& e : watcher->outcomes())
      o << e.evaluated << " " << e.pass << " " << e.passLabel << " " << e.probe.passed << " " << e.probe.message << "\n";
  }
  if (seen == Seen::Image) {
    o << gl.framebuffer().width() << "x" << gl.framebuffer().height() << "\n";
    for (const Rgba8& c : gl.framebuffer().colorData()) o.write(reinterpret_cast<const char*>(c.data()), 3);  // RGB: the image
  }
  return o.str();
}

std::string seenOf(const std::string& text, Seen seen = Seen::Image) { return seenOf(loadSceneText(text, "keys.yaml"), seen); }

const std::string kMirrorMat = "mirror: {kind: mirror, diffuse: [0.3, 0.05, 0.05], reflectance: 0.8}";
const std::string kGlassMat = "glass: {kind: refractive, diffuse: [0.5, 0.6, 0.7], ior: 1.5, transmittance: 0.7}";
const std::string kLight = "{position: [2, 4, 3], color: [1, 1, 1], attenuation: [1, 0, 0]}";
const std::string kRender = "render: {width: 48, height: 36}";
const std::string kBox = "{name: box, primitive: box, translate: [-1, 0.5, 0], material: shiny}";
// Soft shadows: an area light sampled 4 times.
const Edits kSoft = {{kLight, "{position: [2, 4, 3], radius: 0.4}"},
                     {kRender, "render: {width: 48, height: 36, soft_shadow_samples: 4}"}};
// An expectation read at the end of the render, which holds.
const std::string kExpect = "expect:\n  - {after: end, color: [24, 30], value: [0, 0, 0, 255]}\n";

Edits plus(Edits a, const Edits& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

const std::map<std::string, KeyCase>& cases() {
  static const std::map<std::string, KeyCase> c = {
      {"camera", {{}, {{"look_at: [0, 0.5, 0]", "look_at: [0.3, 0.5, 0]"}}}},
      {"camera.position", {{}, {{"position: [0, 2, 6]", "position: [0.5, 2, 6]"}}}},
      {"camera.look_at", {{}, {{"look_at: [0, 0.5, 0]", "look_at: [0, 0.8, 0]"}}}},
      {"camera.up", {{}, {{"far: 40}", "far: 40, up: [0.2, 1, 0]}"}}}},
      {"camera.fov", {{}, {{"fov: 45", "fov: 50"}}}},
      {"camera.near", {{}, {{"near: 0.1", "near: 5"}}}},
      {"camera.far", {{}, {{"far: 40", "far: 6"}}}},
      {"camera.aperture", {{{kRender, "render: {width: 48, height: 36, antialias_samples: 4}"}}, {{"far: 40", "far: 40, aperture: 0.2"}}}},
      {"camera.focal_distance",
       {{{kRender, "render: {width: 48, height: 36, antialias_samples: 4}"}, {"far: 40", "far: 40, aperture: 0.2"}},
        {{"aperture: 0.2", "aperture: 0.2, focal_distance: 3"}}}},
      {"ambient", {{}, {{"ambient: [0.1, 0.1, 0.1]", "ambient: [0.2, 0.1, 0.1]"}}}},
      {"lights[]", {{}, {{"lights:\n", "lights:\n  - {position: [-2, 3, 2]}\n"}}}},
      {"lights[].position", {{}, {{"position: [2, 4, 3]", "position: [2, 4, 2]"}}}},
      {"lights[].color", {{}, {{"color: [1, 1, 1]", "color: [1, 0.5, 1]"}}}},
      {"lights[].attenuation", {{}, {{"attenuation: [1, 0, 0]", "attenuation: [1, 0.1, 0]"}}}},
      {"lights[].radius", {kSoft, {{"radius: 0.4", "radius: 0.1"}}}},
      {"materials.<name>", {{}, {{"grey: {diffuse: [0.6, 0.6, 0.6]}", "grey: {diffuse: [0.6, 0.6, 0.6]}\n  new: {}"},
                                 {"translate: [-1, 0.5, 0], material: shiny}", "translate: [-1, 0.5, 0], material: new}"}}}},
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
      // In the pass labels of the mirror's views (names are for messages and statistics).
      {"objects[].name", {{}, {{"name: mirror", "name: looking glass"}}, Seen::PassLabels}},
      {"objects[].primitive", {{}, {{"name: box, primitive: box", "name: box, primitive: sphere"}}}},
      {"objects[].mesh", {{}, {{kBox, "{name: box, mesh: " + std::string(MPR_SOURCE_DIR) + "/scenes/meshes/vase.obj, translate: [-1, 0, 0], material: shiny}"}}}},
      {"objects[].subdivisions", {{}, {{"primitive: sphere, subdivisions: 16", "primitive: sphere, subdivisions: 6"}}}},
      {"objects[].translate", {{}, {{"translate: [-1, 0.5, 0]", "translate: [-1.2, 0.5, 0]"}}}},
      {"objects[].rotate", {{}, {{"translate: [-1, 0.5, 0]", "translate: [-1, 0.5, 0], rotate: [30, 0, 1, 0]"}}}},
      {"objects[].scale", {{}, {{"translate: [-1, 0.5, 0]", "translate: [-1, 0.5, 0], scale: 0.8"}}}},
      {"objects[].material", {{}, {{"translate: [-1, 0.5, 0], material: shiny", "translate: [-1, 0.5, 0], material: grey"}}}},
      {"objects[].casts_shadows", {{}, {{"material: shiny}", "material: shiny, casts_shadows: false}"}}}},
      {"render", {{}, {{kRender, "render: {width: 46, height: 36}"}}}},
      {"render.width", {{}, {{"width: 48", "width: 46"}}}},
      {"render.height", {{}, {{"height: 36", "height: 30"}}}},
      {"render.recursion_depth", {{}, {{kRender, "render: {width: 48, height: 36, recursion_depth: 0}"}}}},
      {"render.shadow_recursion_depth", {{}, {{kRender, "render: {width: 48, height: 36, shadow_recursion_depth: 0}"}}}},
      {"render.light_bounces", {{}, {{kRender, "render: {width: 48, height: 36, light_bounces: 2}"}}}},
      {"render.soft_shadow_samples", {{{kLight, "{position: [2, 4, 3], radius: 0.4}"}, {kRender, "render: {width: 48, height: 36, soft_shadow_samples: 1}"}},
                                      {{"soft_shadow_samples: 1", "soft_shadow_samples: 3"}}}},
      {"render.antialias_samples", {{}, {{kRender, "render: {width: 48, height: 36, antialias_samples: 3}"}}}},
      {"render.soft_shadow_method", {kSoft, {{"soft_shadow_samples: 4", "soft_shadow_samples: 4, soft_shadow_method: darkness_levels"}}}},
      {"render.shadows", {{}, {{kRender, "render: {width: 48, height: 36, shadows: false}"}}}},
      {"render.reflections", {{}, {{kRender, "render: {width: 48, height: 36, reflections: false}"}}}},
      {"render.refractions", {{}, {{kRender, "render: {width: 48, height: 36, refractions: false}"}}}},
      {"render.translucency", {{{"kind: refractive", "kind: translucent"}}, {{kRender, "render: {width: 48, height: 36, translucency: false}"}}}},
      {"render.frosted", {{{"kind: refractive", "kind: frosted"}}, {{kRender, "render: {width: 48, height: 36, frosted: false}"}}}},
      // The profiles differ in the accumulation buffer alone: mesa's sums
      // wrap as Mesa's accum.c does, indigo's saturate. Darkness levels load
      // the image so far and add the light's levels to it (LOAD, ACCUM 1/S,
      // RETURN), past 1 where the lit floor is bright: mesa's wrap shows.
      {"render.profile", {plus(kSoft, {{"soft_shadow_samples: 4", "soft_shadow_samples: 4, soft_shadow_method: darkness_levels"}}),
                          {{"soft_shadow_method: darkness_levels", "soft_shadow_method: darkness_levels, profile: mesa"}}}},
      {"render.refraction_map", {{}, {{kRender, "render: {width: 48, height: 36, refraction_map: projection_zeroed_z}"}}}},
      {"render.tessellation", {{}, {{kRender, "render: {width: 48, height: 36, tessellation: 0.5}"}}}},
      // Expectations read the buffers and draw nothing: what changes is
      // which pass they read and what they find there.
      {"expect[]", {{{kRender, kRender + "\n" + kExpect}}, {{"value: [0, 0, 0, 255]}\n", "value: [0, 0, 0, 255]}\n  - {after: end, stencil: all, value: 3}\n"}}, Seen::Expectations}},
      {"expect[].after", {{{kRender, kRender + "\n" + kExpect}}, {{"after: end, color", "after: ambient, color"}}, Seen::Expectations}},
      {"expect[].occurrence",
       {{{kRender, kRender + "\n" + kExpect}, {"after: end, color", "after: apply_stencil, color"}},
        {{"after: apply_stencil, color", "after: apply_stencil, occurrence: 2, color"}}, Seen::Expectations}},
      {"expect[].level",
       {{{kRender, kRender + "\n" + kExpect}, {"after: end, color", "after: ambient, color"}},
        {{"after: ambient, color", "after: ambient, level: 1, color"}}, Seen::Expectations}},
      {"expect[].light",
       {{{kRender, kRender + "\n" + kExpect}, {"after: end, color", "after: \"lit outside\", light: 0, color"},
         {"lights:\n", "lights:\n  - {position: [-2, 3, 2]}\n"}},
        {{"light: 0", "light: 1"}}, Seen::Expectations}},
      {"expect[].color", {{{kRender, kRender + "\n" + kExpect}}, {{"color: [24, 30]", "color: [24, 8]"}}, Seen::Expectations}},
      {"expect[].stencil", {{{kRender, kRender + "\n" + kExpect}}, {{"color: [24, 30], value: [0, 0, 0, 255]", "stencil: [24, 30], value: 1"}}, Seen::Expectations}},
      {"expect[].depth", {{{kRender, kRender + "\n" + kExpect}}, {{"color: [24, 30], value: [0, 0, 0, 255]", "depth: [24, 30], value: 1"}}, Seen::Expectations}},
      {"expect[].accum", {{{kRender, kRender + "\n" + kExpect}}, {{"color: [24, 30], value: [0, 0, 0, 255]", "accum: [24, 30], value: [1, 1, 1, 1]"}}, Seen::Expectations}},
      {"expect[].value", {{{kRender, kRender + "\n" + kExpect}}, {{"value: [0, 0, 0, 255]", "value: [0, 0, 1, 255]"}}, Seen::Expectations}},
      {"expect[].tolerance",
       {{{kRender, kRender + "\n" + kExpect}, {"value: [0, 0, 0, 255]", "value: [0, 0, 9, 255]"}},
        {{"value: [0, 0, 9, 255]", "value: [0, 0, 9, 255], tolerance: 10"}}, Seen::Expectations}},
      {"expect[].picture",
       {{{kRender, kRender + "\n" + kExpect}, {"color: [24, 30], value: [0, 0, 0, 255]", "stencil: [24, 30], value: 1"}},
        {{"value: 1", "picture: \"0 0\""}}, Seen::Expectations}},
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
  EXPECT_GT(keys.size(), 60u);
  for (const std::string& k : keys)
    EXPECT_TRUE(cases().count(k)) << "scene key " << k << " has no case: show that it changes the render";
  for (const auto& [k, c] : cases()) EXPECT_TRUE(keys.count(k)) << k << " is not a key of the format";
}

TEST(EveryKey, ChangesTheRender) {
  for (const auto& [key, c] : cases()) {
    const std::string before = edited(kBase, c.context), after = edited(before, c.change);
    try {
      EXPECT_NE(seenOf(before, c.seen), seenOf(after, c.seen)) << key << " was accepted and changed nothing";
    } catch (const SceneError& e) {
      ADD_FAILURE() << key << ": its case is refused: " << e.what();
    }
  }
}

// ---- refused where it counts for nothing ----------------------------------

std::string errorOf(const std::string& text, const std::vector<std::string>& sets = {}) {
  try {
    loadSceneText(text, "s.yaml", sets);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "no error";
}

const std::string kQuad = "objects:\n  - {primitive: quad, material: m}\n";

// Each refusal, with the key it refuses, at its line and column: the
// value's place, as the loader's other errors are.
struct Refusal {
  std::string key, text, message;
};

const std::vector<Refusal>& refusals() {
  static const std::vector<Refusal> r = {
      // Materials: a key the kind does not read (algorithms/draw_window.cpp,
      // reference/ray_tracer.cpp), at any render setting.
      {"materials.<name>.shear", "materials:\n  m: {kind: refractive, shear: 0.2}\n" + kQuad,
       "s.yaml:2:32: material 'm' (kind refractive) does not use 'shear': only frosted materials are sheared (kind: frosted)"},
      {"materials.<name>.shear", "materials:\n  m: {kind: mirror, shear: 0.2}\n" + kQuad,
       "s.yaml:2:28: material 'm' (kind mirror) does not use 'shear': only frosted materials are sheared (kind: "
       "frosted); a glossy mirror's view is sheared by its roughness"},
      {"materials.<name>.samples", "materials:\n  m: {kind: refractive, samples: 4}\n" + kQuad,
       "s.yaml:2:34: material 'm' (kind refractive) does not use 'samples': only frosted materials and glossy mirrors "
       "accumulate sheared images (kind: frosted, or kind: mirror with a roughness)"},
      {"materials.<name>.samples", "materials:\n  m: {kind: translucent, samples: 4}\n" + kQuad,
       "s.yaml:2:35: material 'm' (kind translucent) does not use 'samples': only frosted materials and glossy mirrors "
       "accumulate sheared images (kind: frosted, or kind: mirror with a roughness)"},
      {"materials.<name>.samples", "materials:\n  m: {kind: mirror, samples: 4}\n" + kQuad,
       "s.yaml:2:30: material 'm' (kind mirror) does not use 'samples' without a roughness: only a glossy mirror's view "
       "is sheared and accumulated (give roughness, at least 0.125)"},
      {"materials.<name>.fog_distance", "materials:\n  m: {kind: refractive, fog_distance: 2}\n" + kQuad,
       "s.yaml:2:39: material 'm' (kind refractive) does not use 'fog_distance': only translucent and frosted materials "
       "are fogged (kind: translucent or frosted)"},
      {"materials.<name>.fog_distance", "materials:\n  m: {fog_distance: 2}\n" + kQuad,
       "s.yaml:2:21: material 'm' (kind diffuse) does not use 'fog_distance': only translucent and frosted materials "
       "are fogged (kind: translucent or frosted)"},
      {"materials.<name>.roughness", "materials:\n  m: {kind: refractive, roughness: 0.2}\n" + kQuad,
       "s.yaml:2:36: material 'm' (kind refractive) does not use 'roughness' while its specular is 0: roughness shapes "
       "the specular highlight (1997 eq. 6; give specular above 0), and makes only a mirror's reflection glossy (kind: "
       "mirror)"},
      {"materials.<name>.shininess", "materials:\n  m: {diffuse: [1, 0, 0], shininess: 30}\n" + kQuad,
       "s.yaml:2:38: material 'm' (kind diffuse) does not use 'shininess' while its specular is 0: shininess shapes "
       "the specular highlight (give specular above 0)"},
      {"materials.<name>.reflectance", "materials:\n  m: {reflectance: 0.5}\n" + kQuad,
       "s.yaml:2:20: material 'm' (kind diffuse) does not use 'reflectance': only mirrors reflect (kind: mirror)"},
      {"materials.<name>.reflectance", "materials:\n  m: {kind: frosted, reflectance: 0.5}\n" + kQuad,
       "s.yaml:2:35: material 'm' (kind frosted) does not use 'reflectance': only mirrors reflect (kind: mirror); what "
       "a refracting face passes on is its transmittance"},
      {"materials.<name>.ior", "materials:\n  m: {kind: mirror, ior: 1.3}\n" + kQuad,
       "s.yaml:2:26: material 'm' (kind mirror) does not use 'ior': only refracting materials bend the view through "
       "them (kind: refractive, translucent or frosted)"},
      {"materials.<name>.transmittance", "materials:\n  m: {kind: mirror, transmittance: 0.5}\n" + kQuad,
       "s.yaml:2:36: material 'm' (kind mirror) does not use 'transmittance': only refracting materials are seen "
       "through (kind: refractive, translucent or frosted); what a mirror passes on is its reflectance"},
      {"materials.<name>.thickness", "materials:\n  m: {kind: mirror, thickness: 0.1}\n" + kQuad,
       "s.yaml:2:32: material 'm' thickness is for refracting materials (kind refractive, translucent or frosted): a "
       "slab shifts the view through it; this one is not looked through"},
      {"materials.<name>", "materials:\n  m: {}\n  spare: {diffuse: [1, 0, 0]}\n" + kQuad,
       "s.yaml:3:3: material 'spare' is given to no object, so none of its keys changes the image (give it to an "
       "object with material: spare, or remove it)"},
      // Objects and the camera.
      {"objects[].subdivisions",
       "objects:\n  - {mesh: " + std::string(MPR_SOURCE_DIR) + "/scenes/meshes/vase.obj, subdivisions: 8}\n",
       "s.yaml:2:" + std::to_string(51 + std::string(MPR_SOURCE_DIR).size()) +
           ": object 'object at line 2' does not use 'subdivisions': only primitives are divided (a mesh is drawn as "
           "its file gives it)"},
      {"camera.focal_distance", "camera: {focal_distance: 4}\n",
       "s.yaml:1:26: camera.focal_distance is the distance a lens keeps in focus, and camera.aperture is 0 (a pinhole: "
       "everything is in focus); give aperture above 0 for depth of field"},
      // Render settings with nothing to act on in this scene.
      {"render.recursion_depth", "objects: [{primitive: box}]\nrender: {recursion_depth: 4}\n",
       "s.yaml:2:27: render.recursion_depth 4 counts the views through mirrors and refracting faces, and no object "
       "here has a specular material (kind mirror, refractive, translucent or frosted)"},
      {"render.shadow_recursion_depth", "objects: [{primitive: box}]\nrender: {shadow_recursion_depth: 2}\n",
       "s.yaml:2:34: render.shadow_recursion_depth 2 counts the levels of views through specular faces that get "
       "shadows, and no object here has a specular material (kind mirror, refractive, translucent or frosted)"},
      {"render.light_bounces", "materials: {m: {kind: mirror}}\n" + kQuad + "render: {light_bounces: 3}\n",
       "s.yaml:4:25: render.light_bounces 3 counts the specular faces a light passes on its way from one to the next, "
       "and this scene has one (a planar face cannot light itself): it counts with two or more"},
      {"render.soft_shadow_samples", "lights: [{position: [0, 3, 0]}]\nrender: {soft_shadow_samples: 8}\n",
       "s.yaml:2:31: render.soft_shadow_samples 8 samples the lights that have a radius, and no light here has one "
       "(give a light a radius for soft shadows)"},
      {"render.soft_shadow_method", "lights: [{position: [0, 3, 0]}]\nrender: {soft_shadow_method: pivot}\n",
       "s.yaml:2:30: render.soft_shadow_method pivot is how soft shadows are made, and this render makes none: they "
       "need a light with a radius and render.soft_shadow_samples above 1"},
      {"render.soft_shadow_method",
       "lights: [{position: [0, 3, 0], radius: 0.5}]\nrender: {soft_shadow_samples: 1, soft_shadow_method: darkness_levels}\n",
       "s.yaml:2:54: render.soft_shadow_method darkness_levels is how soft shadows are made, and this render makes none: "
       "they need a light with a radius and render.soft_shadow_samples above 1"},
      {"render.refraction_map",
       "materials: {m: {kind: refractive, thickness: 0.05}}\n" + kQuad + "render: {refraction_map: end_of_pipeline}\n",
       "s.yaml:4:26: render.refraction_map end_of_pipeline places the image map of a view through a refracting face "
       "without thickness (1994's change of medium), and no object here has one: a slab's view (thickness above 0) is "
       "shifted, not mapped"},
      {"render.reflections", "objects: [{primitive: box}]\nrender: {reflections: false}\n",
       "s.yaml:2:23: render.reflections false draws mirrors as their own colour, and no object here is a mirror (kind: "
       "mirror)"},
      {"render.refractions", "materials: {m: {kind: translucent}}\n" + kQuad + "render: {refractions: false}\n",
       "s.yaml:4:23: render.refractions false draws refractive faces as their own colour, and no object here is "
       "refractive (kind: refractive)"},
      {"render.translucency", "materials: {m: {kind: refractive}}\n" + kQuad + "render: {translucency: false}\n",
       "s.yaml:4:24: render.translucency false draws translucent faces as their own colour, and no object here is "
       "translucent (kind: translucent)"},
      {"render.frosted", "materials: {m: {kind: mirror}}\n" + kQuad + "render: {frosted: false}\n",
       "s.yaml:4:19: render.frosted false draws frosted faces as their own colour and glossy mirrors sharp, and no "
       "object here is frosted (kind: frosted) or a glossy mirror (kind: mirror with a roughness)"},
      {"render.shadows", "objects: [{primitive: box}]\nrender: {shadows: false}\n",
       "s.yaml:2:19: render.shadows false turns the lights' shadows off, and this scene has no light"},
  };
  return r;
}

TEST(EveryKey, RefusedAtItsPlaceWhereItCountsForNothing) {
  const std::set<std::string> keys = formatKeys();
  for (const Refusal& r : refusals()) {
    EXPECT_TRUE(keys.count(r.key)) << r.key << " is not a key of the format";
    EXPECT_EQ(errorOf(r.text), r.message) << r.key;
  }
}

// Where the key does count, the same keys load: each kind with its own
// keys, a glossy mirror's samples, the default written explicitly.
TEST(EveryKey, KeysThatCountLoad) {
  for (const std::string& text : std::vector<std::string>{
           "materials:\n  m: {kind: frosted, ior: 1.3, transmittance: 0.5, fog_distance: 2, thickness: 0.1, shear: 0.2, "
           "samples: 4, specular: [0.5, 0.5, 0.5], roughness: 0.2}\n" + kQuad,
           "materials:\n  m: {kind: mirror, reflectance: 0.5, roughness: 0.2, samples: 4, thickness: 0}\n" + kQuad,
           "materials:\n  m: {kind: translucent, ior: 1.3, transmittance: 0.5, fog_distance: 2, specular: [1, 1, 1], "
           "shininess: 4}\n" + kQuad,
           "materials:\n  m: {diffuse: [1, 0, 0], specular: [0, 0, 0], shininess: 0}\n" + kQuad,
           "camera: {aperture: 0.1, focal_distance: 4}\nrender: {antialias_samples: 4}\n",
           "objects: [{primitive: box}]\nrender: {recursion_depth: 2, shadow_recursion_depth: 1, light_bounces: 1, "
           "soft_shadow_samples: 1, soft_shadow_method: images, refraction_map: projection, reflections: true, "
           "refractions: true, translucency: true, frosted: true, shadows: true}\n",
           "materials: {m: {kind: mirror}, n: {kind: mirror}}\nobjects:\n  - {primitive: quad, material: m}\n"
           "  - {primitive: quad, translate: [0, 0, -2], rotate: [180, 0, 1, 0], material: n}\nrender: {light_bounces: 3}\n",
           "lights: [{position: [0, 3, 0], radius: 0.5}]\nrender: {soft_shadow_samples: 4, soft_shadow_method: pivot}\n",
           "materials: {m: {kind: refractive}}\n" + kQuad + "render: {refraction_map: end_of_pipeline}\n",
           "materials: {m: {kind: mirror, roughness: 0.2}}\n" + kQuad + "render: {frosted: false}\n",
       })
    EXPECT_EQ(errorOf(text), "no error") << text;
}

// A --set is not the file: mpr accuracy sweeps settings across scenes
// (render.refraction_map on a scene of slabs) and its single-pass baseline
// turns every effect off (camera.aperture=0 under the file's
// focal_distance, soft_shadow_samples=1 under its soft_shadow_method);
// mpr test --profile gives every scene one profile. What a --set gave or
// changed is not refused, nor what it leaves without use.
TEST(EveryKey, WhatASetGivesOrChangesIsNotRefused) {
  const std::string slab = "materials: {m: {kind: refractive, thickness: 0.05}}\n" + kQuad;
  EXPECT_EQ(errorOf(slab, {"render.refraction_map=end_of_pipeline"}), "no error");
  EXPECT_EQ(errorOf(slab + "render: {refraction_map: end_of_pipeline}\n"), errorOf(slab + "render: {refraction_map: end_of_pipeline}\n", {"render.width=20"}));
  EXPECT_EQ(errorOf("camera: {aperture: 0.1, focal_distance: 4}\nrender: {antialias_samples: 4}\n", {"camera.aperture=0"}), "no error");
  EXPECT_EQ(errorOf("lights: [{position: [0, 3, 0], radius: 0.5}]\nrender: {soft_shadow_samples: 4, soft_shadow_method: pivot}\n",
                    {"render.soft_shadow_samples=1"}),
            "no error");
  EXPECT_EQ(errorOf("materials:\n  m: {kind: refractive, ior: 1.2}\n" + kQuad, {"materials.m.kind=mirror"}), "no error");
  EXPECT_EQ(errorOf("objects: [{primitive: box}]\n", {"render.translucency=false", "render.light_bounces=3"}), "no error");
  EXPECT_EQ(errorOf("materials: {m: {}, n: {}}\n" + kQuad + "  - {primitive: box, material: n}\n", {"objects.1.material=m"}),
            "no error");
}

// Kept with one warning, as the mesh files' warnings are: a light's radius
// and the camera's lens, which mpr reference traces at any sample count
// while mpr render needs several images to draw them. Written, the sample
// count says the hard shadows or the pinhole are meant: no warning.
TEST(EveryKey, WarnedOnceWhereOnlyTheReferenceUsesIt) {
  const auto warnings = [](const std::string& text, const std::vector<std::string>& sets = {}) {
    ::testing::internal::CaptureStderr();
    try {
      loadSceneText(text, "s.yaml", sets);
    } catch (const SceneError&) {
    }
    return ::testing::internal::GetCapturedStderr();
  };
  const std::string lights = "lights:\n  - {position: [0, 3, 0], radius: 0.15}\n  - {position: [1, 3, 0], radius: 0.2}\n"
                             "  - {position: [2, 3, 0]}\n  - {position: [3, 3, 0], radius: 0.1}\n";
  EXPECT_EQ(warnings(lights),
            "s.yaml:2:35: warning: light radius 0.15 (and that of 2 more lights) makes no soft shadow in mpr render while "
            "render.soft_shadow_samples is 1: above 1 it samples the area light (mpr reference traces it at any count; "
            "write soft_shadow_samples: 1 to say hard shadows are meant)\n");
  EXPECT_EQ(warnings(lights + "render: {soft_shadow_samples: 1}\n"), "");
  EXPECT_EQ(warnings(lights + "render: {soft_shadow_samples: 4}\n"), "");
  EXPECT_EQ(warnings(lights, {"render.soft_shadow_samples=1"}), "");
  EXPECT_EQ(warnings("camera: {aperture: 0.1, focal_distance: 4}\n"),
            "s.yaml:1:20: warning: camera.aperture 0.1 (and focal_distance) makes no depth of field in mpr render while "
            "render.antialias_samples is 1: above 1 its images are seen from points of the lens (mpr reference traces "
            "the lens at any count; write antialias_samples: 1 to say a pinhole is meant)\n");
  EXPECT_EQ(warnings("camera: {aperture: 0.1}\nrender: {antialias_samples: 1}\n"), "");
  EXPECT_EQ(warnings("camera: {aperture: 0}\n"), "");
  // A scene that is refused says only why.
  EXPECT_EQ(warnings(lights + "render: {reflections: false}\n" + "objects: [{primitive: box}]\n"), "");
}

// The sample scenes load without a word (the default scene and the
// bathroom write soft_shadow_samples: 1 beside their lights' radius).
TEST(EveryKey, SampleScenesLoadQuietly) {
  int scenes = 0;
  for (const auto& f : std::filesystem::directory_iterator(std::string(MPR_SOURCE_DIR) + "/scenes")) {
    if (f.path().extension() != ".yaml") continue;
    ++scenes;
    ::testing::internal::CaptureStderr();
    EXPECT_NO_THROW(loadSceneFile(f.path().string())) << f.path();
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "") << f.path();
  }
  EXPECT_GE(scenes, 8);
  ::testing::internal::CaptureStderr();
  loadSceneText(defaultSceneText(), "<default scene>");
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  // So does the annotated example of docs/reference/scene-format.md (its
  // mesh path is relative to scenes/).
  std::ifstream doc(std::string(MPR_SOURCE_DIR) + "/docs/reference/scene-format.md");
  const std::string text((std::istreambuf_iterator<char>(doc)), std::istreambuf_iterator<char>());
  const std::size_t from = text.find("```yaml\n"), to = text.find("```", from + 8);
  ASSERT_NE(from, std::string::npos);
  ::testing::internal::CaptureStderr();
  EXPECT_NO_THROW(loadSceneText(text.substr(from + 8, to - from - 8), std::string(MPR_SOURCE_DIR) + "/scenes/annotated.yaml"));
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
}

// What the loader refuses (or warns about) indeed changes nothing in the
// image: the same values given on the scene model, past the loader, render
// the same bytes.
TEST(EveryKey, RefusedKeysChangeNothing) {
  const auto material = [](Scene& s, const std::string& name) -> SceneMaterial& {
    for (SceneMaterial& m : s.materials)
      if (m.name == name) return m;
    throw std::runtime_error("no material " + name);
  };
  struct Change {
    std::string what;
    Edits context;  // of kBase, as text
    std::function<void(Scene&)> apply;
  };
  // The mirror and the pane made diffuse, each with only its diffuse colour.
  const Edits noSpecular = {{kMirrorMat, "mirror: {diffuse: [0.3, 0.05, 0.05]}"}, {kGlassMat, "glass: {diffuse: [0.5, 0.6, 0.7]}"}};
  const Edits slab = {{"ior: 1.5, transmittance: 0.7}", "ior: 1.5, transmittance: 0.7, thickness: 0.05}"}};
  const std::vector<Change> changes = {
      {"shear on a refractive face", {}, [&](Scene& s) { material(s, "glass").shear = 0.5f; }},
      {"samples on a refractive face", {}, [&](Scene& s) { material(s, "glass").samples = 3; }},
      {"fog_distance on a refractive face", {}, [&](Scene& s) { material(s, "glass").fogDistance = 0.2f; }},
      {"reflectance on a refractive face", {}, [&](Scene& s) { material(s, "glass").reflectance = 0.2f; }},
      {"roughness on a refractive face without specular", {},
       [&](Scene& s) { material(s, "glass").roughness = 0.3f, material(s, "glass").shininess = 22.2f; }},
      {"ior on a mirror", {}, [&](Scene& s) { material(s, "mirror").ior = 1.2f; }},
      {"transmittance on a mirror", {}, [&](Scene& s) { material(s, "mirror").transmittance = 0.2f; }},
      {"shear on a mirror", {}, [&](Scene& s) { material(s, "mirror").shear = 0.5f; }},
      {"fog_distance on a mirror", {}, [&](Scene& s) { material(s, "mirror").fogDistance = 0.2f; }},
      {"samples on a mirror without roughness", {}, [&](Scene& s) { material(s, "mirror").samples = 3; }},
      {"shininess without specular", {}, [&](Scene& s) { material(s, "grey").shininess = 20.0f; }},
      {"ior, transmittance, reflectance, samples on a diffuse face", {},
       [&](Scene& s) {
         SceneMaterial& g = material(s, "grey");
         g.ior = 1.2f, g.transmittance = 0.2f, g.reflectance = 0.1f, g.samples = 3, g.shear = 0.4f, g.fogDistance = 0.3f;
       }},
      {"a material no object has", {}, [&](Scene& s) { s.materials.push_back(SceneMaterial{"spare", MaterialKind::Frosted}); }},
      {"focal_distance without aperture", {}, [&](Scene& s) { s.camera.focalDistance = 3.0f; }},
      {"aperture with one image (warned)", {}, [&](Scene& s) { s.camera.aperture = 0.3f; }},
      {"radius with one light sample (warned)", {}, [&](Scene& s) { s.lights[0].radius = 0.5f; }},
      {"soft_shadow_samples without a radius", {}, [&](Scene& s) { s.render.softShadowSamples = 4; }},
      {"soft_shadow_method without a radius", {},
       [&](Scene& s) { s.render.softShadowSamples = 4, s.render.softShadowMethod = SoftShadowMethod::Pivot; }},
      {"soft_shadow_method darkness_levels with one sample", {},
       [&](Scene& s) { s.lights[0].radius = 0.5f, s.render.softShadowMethod = SoftShadowMethod::DarknessLevels; }},
      {"refraction_map with slabs only", slab, [&](Scene& s) { s.render.refractionMap = RefractionMap::EndOfPipeline; }},
      {"refraction_map projection_zeroed_z with slabs only", slab,
       [&](Scene& s) { s.render.refractionMap = RefractionMap::ProjectionZeroedZ; }},
      {"recursion_depth and shadow_recursion_depth without a specular face", noSpecular,
       [&](Scene& s) { s.render.recursionDepth = 5, s.render.shadowRecursionDepth = 3; }},
      {"light_bounces with one specular face", {{kGlassMat, "glass: {diffuse: [0.5, 0.6, 0.7]}"}},
       [&](Scene& s) { s.render.lightBounces = 4; }},
      {"switches with nothing to switch off", noSpecular,
       [&](Scene& s) {
         s.render.reflections = s.render.refractions = s.render.translucency = s.render.frosted = false;
       }},
      {"shadows off without a light", {{"  - " + kLight + "\n", ""}, {"lights:\n", "lights: []\n"}},
       [&](Scene& s) { s.render.shadows = false; }},
  };
  for (const Change& c : changes) {
    const Scene base = loadSceneText(edited(kBase, c.context), "keys.yaml");
    Scene changed = base;
    c.apply(changed);
    EXPECT_EQ(seenOf(base, Seen::Image), seenOf(changed, Seen::Image)) << c.what << " changed the image";
  }
}

// Every soft-shadow method is built; an unknown one is refused, not ignored.
// pivot renders the images method's passes with pivoted volumes: where the
// silhouette changes with the light samples (the box lit from (2, 4, 3) past
// its corner), its image differs from images'.
TEST(EveryKey, SoftShadowMethods) {
  EXPECT_THROW(loadSceneText(edited(kBase, {{kRender, "render: {width: 48, height: 36, soft_shadow_method: penumbra}"}}), "keys.yaml"),
               SceneError);
  const std::string soft = edited(kBase, {{kLight, "{position: [2, 4, 3], radius: 0.8}"},
                                          {kRender, "render: {width: 48, height: 36, soft_shadow_samples: 4}"}});
  const std::string pivot = edited(soft, {{"soft_shadow_samples: 4", "soft_shadow_samples: 4, soft_shadow_method: pivot"}});
  EXPECT_NE(seenOf(soft), seenOf(pivot));
}

}  // namespace
}  // namespace mpr::every_key_test
