// pbrt's rule for the keys whose use depends on the rest of the scene: a
// key accepted must change the image. Where the scene's other keys leave it
// nothing to do (a soft-shadow method with no soft shadow, an image map
// with no view that is mapped, a material no object has), it is refused at
// its place in the file, saying what would make it count. Two are kept with
// one warning each: a light's radius and the camera's aperture, which
// `mpr reference` traces whatever the sample counts, while the pipeline
// needs more than one image for them (docs/reference/scene-format.md,
// "Keys that count").
//
// What the file writes is checked, not what a --set gave or changed:
// mpr accuracy sweeps settings across scenes (render.refraction_map on a
// scene of slabs, render.soft_shadow_samples=1 for its single-pass
// baseline) and mpr test --profile gives every scene one profile. The
// effect switches (render.shadows, reflections, ...) turn effects off to
// compare, so they never make another key an error; a switch turned off
// with nothing to turn off is one.
#include <algorithm>
#include <optional>
#include <set>
#include <string>

#include "scene/scene_section_readers.hpp"

namespace mpr {
namespace {

// What the scene holds, as far as the render keys care.
struct SceneContent {
  int specularObjects = 0, specularFaces = 0;
  bool mirror = false, refractive = false, translucent = false, frosted = false, glossyMirror = false;
  bool mappedRefraction = false;  // a refracting face without thickness: its view goes through the image map M3
  bool areaLight = false;
  std::set<int> materialsUsed;

  explicit SceneContent(const Scene& s) {
    for (const SceneObject& o : s.objects) {
      materialsUsed.insert(o.material);
      const SceneMaterial& m = s.materials[static_cast<std::size_t>(o.material)];
      if (!m.specularKind()) continue;
      ++specularObjects;
      specularFaces += static_cast<int>(o.mesh.faces.size());
      mirror = mirror || m.kind == MaterialKind::Mirror;
      glossyMirror = glossyMirror || (m.kind == MaterialKind::Mirror && m.roughness > 0.0f);
      refractive = refractive || m.kind == MaterialKind::Refractive;
      translucent = translucent || m.kind == MaterialKind::Translucent;
      frosted = frosted || m.kind == MaterialKind::Frosted;
      mappedRefraction = mappedRefraction || (m.kind != MaterialKind::Mirror && m.thickness == 0.0f);
    }
    for (const PointLight& l : s.lights) areaLight = areaLight || l.radius > 0.0f;
  }
};

class KeysCountCheck {
 public:
  KeysCountCheck(const SceneNodeReader& in, const YAML::Node& doc, const Scene& s)
      : in_(in), doc_(doc), s_(s), content_(s) {}

  void run() {
    lensAndAreaLights();
    unusedMaterials();
    renderKeys();
  }

 private:
  // `section`'s `key` where the file writes it (a --set gave nothing of it).
  // (A default YAML::Node is a null value, not none: hence the optional.)
  std::optional<YAML::Node> written(const YAML::Node& section, const char* key) const {
    if (!section || !section.IsMap()) return std::nullopt;
    const YAML::Node v = section[key];
    if (!v || in_.givenBySet(v)) return std::nullopt;
    return v;
  }
  // Whether a --set gave `key` of `section` (or made the section).
  bool bySet(const YAML::Node& section, const char* key) const {
    if (!section || !section.IsMap()) return false;
    const YAML::Node v = section[key];
    return v && in_.givenBySet(v);
  }
  // Whether a --set changed anything in the scene's content (its lights,
  // materials or objects): a render key is then left unchecked.
  bool contentBySet() const {
    return in_.setInside(doc_["lights"]) || in_.setInside(doc_["materials"]) || in_.setInside(doc_["objects"]);
  }

  // Kept, with one warning: the pipeline makes a light's radius an area
  // light and a lens of the camera's aperture only over several images
  // (image_samples.hpp), mpr reference always. Writing the sample count, 1
  // included, says the hard shadows or the pinhole are meant.
  void lensAndAreaLights() const {
    const YAML::Node render = doc_["render"];
    const bool samplesGiven = render && render.IsMap() && render["soft_shadow_samples"];
    if (!samplesGiven && s_.render.softShadowSamples <= 1 && doc_["lights"]) {
      const YAML::Node lights = doc_["lights"];
      std::optional<YAML::Node> first;
      int more = 0;
      for (std::size_t i = 0; i < lights.size(); ++i) {
        const std::optional<YAML::Node> r = written(lights[i], "radius");
        if (!r || !(s_.lights[i].radius > 0.0f)) continue;
        if (first) ++more;
        else first = r;
      }
      if (first)
        in_.warn(*first, "light radius " + first->Scalar() +
                            (more ? " (and that of " + std::to_string(more) + " more light" + (more > 1 ? "s" : "") + ")"
                                  : std::string()) +
                            " makes no soft shadow in mpr render while render.soft_shadow_samples is 1: above 1 it "
                            "samples the area light (mpr reference traces it at any count; write "
                            "soft_shadow_samples: 1 to say hard shadows are meant)");
    }
    const std::optional<YAML::Node> aperture = written(doc_["camera"], "aperture");
    const bool antialiasGiven = render && render.IsMap() && render["antialias_samples"];
    if (aperture && s_.camera.aperture > 0.0f && !antialiasGiven && s_.render.antialiasSamples <= 1)
      in_.warn(*aperture, "camera.aperture " + aperture->Scalar() +
                             (doc_["camera"]["focal_distance"] ? " (and focal_distance)" : "") +
                             " makes no depth of field in mpr render while render.antialias_samples is 1: above 1 "
                             "its images are seen from points of the lens (mpr reference traces the lens at any count; "
                             "write antialias_samples: 1 to say a pinhole is meant)");
  }

  // A material no object has changes nothing (pbrt refuses what it cannot use).
  void unusedMaterials() const {
    const YAML::Node materials = doc_["materials"];
    if (!materials || !materials.IsMap() || in_.setInside(doc_["objects"])) return;
    for (auto it = materials.begin(); it != materials.end(); ++it) {
      if (in_.givenBySet(it->second) || in_.setInside(it->second)) continue;
      const std::string name = it->first.as<std::string>();
      for (std::size_t i = 1; i < s_.materials.size(); ++i)
        if (s_.materials[i].name == name && !content_.materialsUsed.count(static_cast<int>(i)))
          in_.fail(it->first, "material '" + name + "' is given to no object, so none of its keys changes the image "
                                                    "(give it to an object with material: " + name + ", or remove it)");
    }
  }

  void renderKeys() const {
    const YAML::Node render = doc_["render"];
    if (!render || !render.IsMap() || contentBySet()) return;
    const RenderSettings& r = s_.render;
    const RenderSettings defaults;
    const SceneContent& c = content_;
    const auto refuse = [&](const YAML::Node& at, const std::string& key, const std::string& why) {
      in_.fail(at, "render." + key + " " + at.Scalar() + " " + why);
    };
    const std::string noSpecular = "no object here has a specular material (kind mirror, refractive, translucent or frosted)";
    if (const auto k = written(render, "recursion_depth"); k && r.recursionDepth != defaults.recursionDepth && !c.specularObjects)
      refuse(*k, "recursion_depth", "counts the views through mirrors and refracting faces, and " + noSpecular);
    if (const auto k = written(render, "shadow_recursion_depth");
        k && r.shadowRecursionDepth != defaults.shadowRecursionDepth && !c.specularObjects)
      refuse(*k, "shadow_recursion_depth",
             "counts the levels of views through specular faces that get shadows, and " + noSpecular);
    // A light passes one face at most where there are fewer than two (a
    // planar face cannot light itself): every count from 1 up is the same.
    if (const auto k = written(render, "light_bounces"); k && r.lightBounces != std::max(1, r.shadowRecursionDepth) &&
                                                         c.specularFaces < 2 && !bySet(render, "shadow_recursion_depth"))
      refuse(*k, "light_bounces",
             "counts the specular faces a light passes on its way from one to the next, and this scene has " +
                 std::string(c.specularFaces == 0 ? "none" : "one") +
                 " (a planar face cannot light itself): it counts with two or more");
    if (const auto k = written(render, "soft_shadow_samples"); k && r.softShadowSamples > 1 && !c.areaLight)
      refuse(*k, "soft_shadow_samples",
             "samples the lights that have a radius, and no light here has one (give a light a radius for soft shadows)");
    if (const auto k = written(render, "soft_shadow_method");
        k && r.softShadowMethod != SoftShadowMethod::Images && (!c.areaLight || r.softShadowSamples <= 1) &&
        !bySet(render, "soft_shadow_samples"))
      refuse(*k, "soft_shadow_method",
             "is how soft shadows are made, and this render makes none: they need a light with a radius and "
             "render.soft_shadow_samples above 1");
    // A slab's view is shifted, not mapped (1997 §2): only the 1994 change
    // of medium has an image map to place.
    if (const auto k = written(render, "refraction_map"); k && r.refractionMap != defaults.refractionMap && !c.mappedRefraction)
      refuse(*k, "refraction_map",
             "places the image map of a view through a refracting face without thickness (1994's change of medium), "
             "and no object here has one: a slab's view (thickness above 0) is shifted, not mapped");
    // The effect switches: false turns something off, if the scene has it.
    const auto switchedOff = [&](const char* key, bool has, const std::string& what) {
      const auto k = written(render, key);
      if (k && !has && !in_.boolean(*k, std::string("render.") + key)) refuse(*k, key, what);
    };
    switchedOff("reflections", c.mirror, "draws mirrors as their own colour, and no object here is a mirror (kind: mirror)");
    switchedOff("refractions", c.refractive,
                "draws refractive faces as their own colour, and no object here is refractive (kind: refractive)");
    switchedOff("translucency", c.translucent,
                "draws translucent faces as their own colour, and no object here is translucent (kind: translucent)");
    switchedOff("frosted", c.frosted || c.glossyMirror,
                "draws frosted faces as their own colour and glossy mirrors sharp, and no object here is frosted "
                "(kind: frosted) or a glossy mirror (kind: mirror with a roughness)");
    switchedOff("shadows", !s_.lights.empty(), "turns the lights' shadows off, and this scene has no light");
  }

  const SceneNodeReader& in_;
  const YAML::Node& doc_;
  const Scene& s_;
  SceneContent content_;
};

}  // namespace

void checkKeysCount(const SceneNodeReader& in, const YAML::Node& doc, const Scene& s) {
  KeysCountCheck(in, doc, s).run();
}

}  // namespace mpr
