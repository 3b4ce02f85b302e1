#include "scene/scene_loader.hpp"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

#include "framebuffer/framebuffer.hpp"
#include "framebuffer/profile.hpp"
#include "util/input_file.hpp"
#include "util/spelling.hpp"
#include "util/transforms.hpp"
#include "scene/mesh_loader.hpp"
#include "scene/primitives.hpp"
#include "scene/tessellation.hpp"
#include "scene/ward_fit.hpp"

namespace mpr {
namespace {

// The format, one table per section: the single source of truth for the
// unknown-key check, the suggestions and --describe-format.
struct KeySpec {
  std::string_view key, type, meaning;
};
const std::vector<KeySpec> kTopKeys = {
    {"camera", "mapping", "the viewer"},
    {"ambient", "rgb", "scene ambient light, default [0.1, 0.1, 0.1]"},
    {"lights", "sequence of light", "point lights"},
    {"materials", "mapping name -> material", "named materials"},
    {"objects", "sequence of object", "what is drawn"},
    {"render", "mapping", "image size, recursion, effects, hardware profile"},
    {"expect", "sequence of expectation", "probes of the buffers at named points of the 1994 algorithm"},
};
const std::vector<KeySpec> kCameraKeys = {
    {"position", "vec3", "eye position"}, {"look_at", "vec3", "point looked at"},
    {"up", "vec3", "up direction, default [0, 1, 0]"}, {"fov", "number in [0.05, 180)", "vertical field of view, degrees, default 45"},
    {"near", "number > 0", "near plane distance"}, {"far", "number > near", "far plane distance"},
    {"aperture", "number >= 0", "lens radius for depth of field (images accumulated: render.antialias_samples), default 0"},
    {"focal_distance", "number > 0", "distance in focus, default the distance to look_at"},
};
const std::vector<KeySpec> kLightKeys = {
    {"position", "vec3", "light position"}, {"color", "rgb", "intensity, default [1, 1, 1]"},
    {"attenuation", "vec3 >= 0", "constant, linear, quadratic; default [1, 0, 0]"},
    {"radius", "number >= 0", "area light radius for soft shadows, default 0"},
};
const std::vector<KeySpec> kMaterialKeys = {
    {"kind", "diffuse | mirror | refractive | translucent | frosted", "the specular effect, default diffuse"},
    {"diffuse", "rgb", "diffuse reflectance, default [0.8, 0.8, 0.8]"},
    {"specular", "rgb", "Phong specular reflectance, default [0, 0, 0]"},
    {"shininess", "number in [0, 128]", "Phong exponent"},
    {"roughness", "number >= 0.125",
     "Ward alpha, mapped to Phong by the 1997 paper's eq. (6); on a mirror also a glossy reflection (its view sheared by 2 alpha)"},
    {"emission", "rgb", "emitted light, default [0, 0, 0]"},
    {"reflectance", "number in [0, 1]", "mirror: fraction reflected, default 1"},
    {"ior", "number > 0", "refractive, translucent, frosted: index of refraction, default 1.5"},
    {"transmittance", "number in [0, 1]", "refractive, translucent, frosted: fraction transmitted, default 0.9"},
    {"fog_distance", "number > 0", "translucent and frosted: distance behind the face of full fog, default 1"},
    {"thickness", "number >= 0",
     "refractive, translucent, frosted: a slab of this thickness, its view and light shifted, not turned (in-out "
     "refraction, 1997 §2); default 0, one change of medium (1994)"},
    {"shear", "number >= 0", "frosted: the stochastic shear's multiplier m (1997 section 3), default 0.05"},
    {"samples", "integer >= 1", "frosted and glossy mirrors: sheared images accumulated, default 8"},
};
const std::vector<KeySpec> kObjectKeys = {
    {"name", "string", "for messages and statistics"},
    {"primitive", "box | sphere | cylinder | quad | plane", "a built-in shape (or `mesh`)"},
    {"mesh", "path", "OBJ, OFF, PLY or STL file, relative to the scene file (or `primitive`)"},
    {"subdivisions", "integer >= 1",
     "sphere slices (stacks are half), cylinder slices, plane, quad and box-side divisions (cells per side)"},
    {"translate", "vec3", "applied last"}, {"rotate", "[degrees, x, y, z]", "applied after scale"},
    {"scale", "number or vec3", "applied first"}, {"material", "name", "a key of `materials`"},
    {"casts_shadows", "bool",
     "gets a shadow volume; default true, false for quad and plane; mirrors never, refracting faces always "
     "(their light goes on through their light volume)"},
};
const std::vector<KeySpec> kRenderKeys = {
    {"width", "integer", "image width, default 640"}, {"height", "integer", "image height, default 480"},
    {"recursion_depth", "integer >= 0", "mirror and refraction levels, default 2"},
    {"shadow_recursion_depth", "integer >= 0", "levels that get shadows, default 1"},
    {"light_bounces", "integer in [1, 16]",
     "specular faces a light may pass on its way, each bounce a virtual light of a virtual light (1997 §4.2-4.3); "
     "default shadow_recursion_depth, at least 1"},
    {"soft_shadow_samples", "integer >= 1",
     "light samples of every light with a radius, one shadowed image each, accumulated; default 1"},
    {"antialias_samples", "integer >= 1", "jittered (and, with camera.aperture, lens) images accumulated, default 1"},
    {"soft_shadow_method", "images | darkness_levels | pivot",
     "how soft shadows are made: images (1994's first method, default), darkness_levels (its second: every "
     "sample's shadow volume counted at once, the light added per darkness level) or pivot (1997 Fig. 7: images "
     "whose shadow volumes are built once and only their far ends moved per sample)"},
    {"shadows", "bool", "default true"}, {"reflections", "bool", "default true"},
    {"refractions", "bool", "default true"}, {"translucency", "bool", "default true"},
    {"frosted", "bool", "default true"}, {"profile", "indigo | mesa", "hardware profile, default indigo"},
    {"refraction_map", "projection | projection_zeroed_z | end_of_pipeline",
     "where a refracted view's image map M3 is applied, default projection (the 4x4 with Z kept)"},
    {"tessellation", "number >= 0",
     "the longest edge of a lit triangle the pipeline draws (larger ones are split for GL's per-vertex lighting), "
     "world units; default 0: as modelled"},
};

const std::vector<KeySpec> kExpectKeys = {
    {"after", "string",
     "evaluated at the end of the pass whose label contains this text (mpr step SCENE lists the labels), or end: "
     "the finished render"},
    {"occurrence", "integer >= 1", "the Nth pass that matches, default 1"},
    {"level", "integer >= 0", "only passes of recursion level N (the innermost draw_window level N)"},
    {"light", "integer >= 0", "only passes inside the loop over light N of their draw_window"},
    {"stencil", "[x, y] | [x, y, width, height] | all", "the stencil of a pixel, a rectangle (bottom-left x, y) or the window"},
    {"depth", "[x, y] | [x, y, width, height] | all", "the stored depth integer (0 .. 2^24 - 1)"},
    {"color", "[x, y] | [x, y, width, height] | all", "the colour bytes"},
    {"accum", "[x, y] | [x, y, width, height] | all", "the four accumulation words (32767 stands for 1.0)"},
    {"value", "integer, stencil level, [r, g, b, a]",
     "what the pixels hold: stencil an integer or ZERO, SHAD_MIN, SHAD_ZERO, MAX with + or - n; depth an integer; "
     "color four bytes; accum four words"},
    {"tolerance", "integer in [0, 255]", "color: the largest difference accepted per channel, default 0"},
    {"picture", "string of rows",
     "stencil [x, y] only, instead of value: rows top-down, blank-separated cells (a value, . for 0, * for any)"},
};

struct Override {
  std::string text;                 // "key.path=value" as given
  YAML::Node node;                  // the parsed value, placed in the document
  std::vector<YAML::Node> created;  // the mappings its path made on the way
};

// Whether `at` is `root` or lies inside it (a key or a value at any depth):
// an error there is the --set's that gave `root`, not the file's.
bool within(const YAML::Node& at, const YAML::Node& root) {
  if (at.is(root)) return true;
  if (root.IsSequence()) {
    for (const YAML::Node& c : root)
      if (within(at, c)) return true;
  } else if (root.IsMap()) {
    for (auto it = root.begin(); it != root.end(); ++it)
      if (within(at, it->first) || within(at, it->second)) return true;
  }
  return false;
}

class Loader {
 public:
  Loader(std::string file, std::vector<Override> overrides, bool confine)
      : file_(std::move(file)), overrides_(std::move(overrides)), confine_(confine) {}

  [[noreturn]] void fail(const YAML::Node& at, const std::string& message) const {
    // A value that came from --set has no place in the file: name the option.
    // The last --set first: a later one may have replaced what an earlier gave.
    for (auto o = overrides_.rbegin(); o != overrides_.rend(); ++o) {
      if (within(at, o->node)) throw SceneError("--set " + o->text, 1, 1, message);
      for (const YAML::Node& c : o->created)
        if (at.is(c)) throw SceneError("--set " + o->text, 1, 1, message);
    }
    const YAML::Mark m = at.Mark();
    if (m.is_null() && !overrides_.empty()) {  // a key --set created
      std::string all;
      for (const Override& o : overrides_) all += (all.empty() ? "" : " --set ") + o.text;
      throw SceneError("--set " + all, 1, 1, message);
    }
    throw SceneError(file_, m.line + 1, m.column + 1, message);
  }

  bool givenBySet(const YAML::Node& at) const {
    return std::any_of(overrides_.begin(), overrides_.end(), [&](const Override& o) { return within(at, o.node); });
  }

  // A warning, placed as fail places an error; loadSceneText writes them
  // once the scene has loaded.
  void warn(const YAML::Node& at, const std::string& message) const {
    try {
      fail(at, "warning: " + message);
    } catch (const SceneError& e) {
      warnings_.push_back(e.what());
    }
  }
  const std::vector<std::string>& warnings() const { return warnings_; }

  // YAML forbids a key twice in one mapping; yaml-cpp keeps both and reads
  // the first, so `scale: 1` then `scale: 0` would silently drop the second.
  void checkUniqueKeys(const YAML::Node& map, const std::string& where) const {
    std::map<std::string, YAML::Mark> seen;
    for (auto it = map.begin(); it != map.end(); ++it) {
      if (!it->first.IsScalar()) fail(it->first, "a key in " + where + " must be a plain name");
      const auto [at, fresh] = seen.emplace(it->first.Scalar(), it->first.Mark());
      if (!fresh)
        fail(it->first, "key '" + it->first.Scalar() + "' given twice in " + where + " (first at line " +
                            std::to_string(at->second.line + 1) + ", column " + std::to_string(at->second.column + 1) +
                            "); give it once");
    }
  }

  void checkKeys(const YAML::Node& map, const std::vector<KeySpec>& keys, const std::string& where) const {
    if (!map.IsMap()) fail(map, where + " must be a mapping");
    checkUniqueKeys(map, where);
    for (auto it = map.begin(); it != map.end(); ++it) {
      const std::string k = it->first.as<std::string>();
      if (std::any_of(keys.begin(), keys.end(), [&](const KeySpec& s) { return s.key == k; })) continue;
      std::vector<std::string_view> names;
      for (const KeySpec& s : keys) names.push_back(s.key);
      const std::string best = closestMatch(k, names, 3);
      std::string known;
      for (const KeySpec& s : keys) known += (known.empty() ? "" : ", ") + std::string(s.key);
      fail(it->first, "unknown key '" + k + "' in " + where +
                          (best.empty() ? " (known: " + known + ")" : "; did you mean '" + best + "'?"));
    }
  }

  // A number, a boolean: a plain scalar only. yaml-cpp hands a quoted
  // scalar ('45', "true") over with the same text as a plain one, so without
  // this a string stood in for a number wherever one was read; its tag ("!"
  // for a quoted scalar, "?" for a plain one) tells them apart.
  void checkPlain(const YAML::Node& n, const std::string& what, const std::string& kind) const {
    const std::string& tag = n.Tag();
    if (tag == "?" || tag.empty()) return;
    if (tag == "!")
      fail(n, what + " must be " + kind + ", not the quoted string '" + n.Scalar() + "' (write it without quotes)");
    if (kind == "a number" && (tag == "tag:yaml.org,2002:float" || tag == "tag:yaml.org,2002:int")) return;
    if (kind == "true or false" && tag == "tag:yaml.org,2002:bool") return;
    fail(n, what + " must be " + kind + ", not a value tagged '" + tag + "'");
  }

  double number(const YAML::Node& n, const std::string& what) const {
    if (!n.IsScalar()) fail(n, what + " must be a number");
    checkPlain(n, what, "a number");
    const std::string s = n.Scalar();
    // YAML's own spellings of the non-finite values.
    static const char* const nonFinite[] = {".nan", ".NaN", ".NAN", ".inf", ".Inf", ".INF", "+.inf", "+.Inf",
                                            "+.INF", "-.inf", "-.Inf", "-.INF"};
    for (const char* nf : nonFinite)
      if (s == nf) fail(n, what + " must be finite, not '" + s + "'");
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || end != s.c_str() + s.size()) fail(n, what + " must be a number, not '" + s + "'");
    if (!std::isfinite(v)) fail(n, what + " must be finite, not '" + s + "'");
    // Every scene number is used as a float: 1e39 is finite as a double and
    // infinite as a float, so the check is on the range it will be used in.
    if (std::fabs(v) > static_cast<double>(std::numeric_limits<float>::max()))
      fail(n, what + " must be within a float's range (magnitude at most 3.4e38), not '" + s + "'");
    return v;
  }
  double number(const YAML::Node& n, const std::string& what, double lo, double hi, bool openLo = false) const {
    const double v = number(n, what);
    if (v < lo || v > hi || (openLo && v == lo)) {
      std::ostringstream r;
      r << what << " must be in " << (openLo ? "(" : "[") << lo << ", " << hi << "], not " << n.Scalar();
      fail(n, r.str());
    }
    return v;
  }
  int integer(const YAML::Node& n, const std::string& what, long lo, long hi) const {
    const double v = number(n, what);
    if (v != std::floor(v)) fail(n, what + " must be an integer, not " + n.Scalar());
    if (v < lo || v > hi)
      fail(n, what + " must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], not " + n.Scalar());
    return static_cast<int>(v);
  }
  bool boolean(const YAML::Node& n, const std::string& what) const {
    if (!n.IsScalar()) fail(n, what + " must be true or false");
    checkPlain(n, what, "true or false");
    const std::string s = n.Scalar();
    if (s == "true" || s == "yes" || s == "on") return true;
    if (s == "false" || s == "no" || s == "off") return false;
    fail(n, what + " must be true or false, not '" + s + "'");
  }
  std::string string(const YAML::Node& n, const std::string& what) const {
    if (!n.IsScalar()) fail(n, what + " must be a string");
    return n.Scalar();
  }
  Vec3 vec3(const YAML::Node& n, const std::string& what) const {
    if (!n.IsSequence() || n.size() != 3) fail(n, what + " must be a list of 3 numbers, like [0, 1, 0]");
    return Vec3(static_cast<float>(number(n[0], what + "[0]")), static_cast<float>(number(n[1], what + "[1]")),
                static_cast<float>(number(n[2], what + "[2]")));
  }
  Vec3 rgb(const YAML::Node& n, const std::string& what) const {
    const Vec3 c = vec3(n, what);
    for (int i = 0; i < 3; ++i)
      if (c[i] < 0.0f) fail(n, what + " must not be negative");
    return c;
  }

  Scene load(YAML::Node doc) {
    Scene s;
    s.file = file_;
    if (doc.IsNull()) doc = YAML::Node(YAML::NodeType::Map);
    checkKeys(doc, kTopKeys, "the scene");
    if (const YAML::Node r = doc["render"]) readRender(r, s.render);
    if (const YAML::Node c = doc["camera"]) readCamera(c, s.camera);
    if (const YAML::Node a = doc["ambient"]) s.ambient = rgb(a, "ambient");
    if (const YAML::Node ls = doc["lights"]) {
      if (!ls.IsSequence()) fail(ls, "lights must be a list");
      checkCount(ls, "lights", kMaxSceneLights);
      for (const YAML::Node& l : ls) s.lights.push_back(readLight(l));
    }
    std::map<std::string, int> materialIndex;
    s.materials.push_back(SceneMaterial{"default"});
    if (const YAML::Node ms = doc["materials"]) {
      if (!ms.IsMap()) fail(ms, "materials must be a mapping from names to materials");
      checkUniqueKeys(ms, "materials");
      for (auto it = ms.begin(); it != ms.end(); ++it) {
        SceneMaterial m = readMaterial(it->second, it->first.as<std::string>());
        materialIndex[m.name] = static_cast<int>(s.materials.size());
        s.materials.push_back(std::move(m));
      }
    }
    if (const YAML::Node os = doc["objects"]) {
      if (!os.IsSequence()) fail(os, "objects must be a list");
      checkCount(os, "objects", kMaxSceneObjects);
      for (const YAML::Node& o : os) s.objects.push_back(readObject(o, materialIndex, s));
    }
    checkLimits(doc, s);
    if (const YAML::Node e = doc["expect"]) readExpectations(e, s);
    return s;
  }

  void readRender(const YAML::Node& n, RenderSettings& r) const {
    checkKeys(n, kRenderKeys, "render");
    if (n["width"]) r.width = integer(n["width"], "render.width", 1, Framebuffer::kMaxSide);
    if (n["height"]) r.height = integer(n["height"], "render.height", 1, Framebuffer::kMaxSide);
    if (n["recursion_depth"]) r.recursionDepth = integer(n["recursion_depth"], "render.recursion_depth", 0, 1 << 20);
    if (n["shadow_recursion_depth"])
      r.shadowRecursionDepth = integer(n["shadow_recursion_depth"], "render.shadow_recursion_depth", 0, 1 << 20);
    if (n["light_bounces"]) r.lightBounces = integer(n["light_bounces"], "render.light_bounces", 1, 16);
    if (n["soft_shadow_samples"]) r.softShadowSamples = integer(n["soft_shadow_samples"], "render.soft_shadow_samples", 1, 1024);
    if (n["antialias_samples"]) r.antialiasSamples = integer(n["antialias_samples"], "render.antialias_samples", 1, 1024);
    if (n["soft_shadow_method"]) {
      const std::string m = string(n["soft_shadow_method"], "render.soft_shadow_method");
      if (m == "darkness_levels") r.softShadowMethod = SoftShadowMethod::DarknessLevels;
      else if (m == "pivot") r.softShadowMethod = SoftShadowMethod::Pivot;
      else if (m != "images")
        fail(n["soft_shadow_method"], "unknown soft_shadow_method '" + m + "' (known: images, darkness_levels, pivot)");
    }
    if (n["shadows"]) r.shadows = boolean(n["shadows"], "render.shadows");
    if (n["reflections"]) r.reflections = boolean(n["reflections"], "render.reflections");
    if (n["refractions"]) r.refractions = boolean(n["refractions"], "render.refractions");
    if (n["translucency"]) r.translucency = boolean(n["translucency"], "render.translucency");
    if (n["frosted"]) r.frosted = boolean(n["frosted"], "render.frosted");
    if (n["profile"]) {
      r.profile = string(n["profile"], "render.profile");
      if (!findProfile(r.profile)) fail(n["profile"], "unknown profile '" + r.profile + "' (known: indigo, mesa)");
    }
    if (n["tessellation"])
      r.tessellation = static_cast<float>(number(n["tessellation"], "render.tessellation", 0.0, 1e6));
    if (n["refraction_map"]) {
      const std::string m = string(n["refraction_map"], "render.refraction_map");
      if (m == "projection") r.refractionMap = RefractionMap::ProjectionKeptZ;
      else if (m == "projection_zeroed_z") r.refractionMap = RefractionMap::ProjectionZeroedZ;
      else if (m == "end_of_pipeline") r.refractionMap = RefractionMap::EndOfPipeline;
      else
        fail(n["refraction_map"], "unknown refraction_map '" + m +
                                      "' (known: projection, projection_zeroed_z, end_of_pipeline)");
    }
  }

  void readCamera(const YAML::Node& n, Camera& c) const {
    checkKeys(n, kCameraKeys, "camera");
    if (n["position"]) c.position = vec3(n["position"], "camera.position");
    if (n["look_at"]) c.lookAt = vec3(n["look_at"], "camera.look_at");
    if (n["up"]) c.up = vec3(n["up"], "camera.up");
    if (n["fov"]) c.fovY = fieldOfView(n["fov"]);
    if (n["near"]) c.near = static_cast<float>(number(n["near"], "camera.near", 0.0, 1e30, true));
    if (n["far"]) c.far = static_cast<float>(number(n["far"], "camera.far", 0.0, 1e30, true));
    if (n["aperture"]) c.aperture = static_cast<float>(number(n["aperture"], "camera.aperture", 0.0, 1e6));
    if (n["focal_distance"])
      c.focalDistance = static_cast<float>(number(n["focal_distance"], "camera.focal_distance", 0.0, 1e30, true));
    const YAML::Node at = n["far"] ? n["far"] : n;
    if (!(c.far > c.near)) fail(at, "camera.far must be greater than camera.near");
    if (c.position == c.lookAt) fail(n["look_at"] ? n["look_at"] : n, "camera.look_at must differ from camera.position");
    const Vec3 f = c.lookAt - c.position;
    const Vec3 side = glm::cross(f, c.up);
    if (glm::dot(side, side) == 0.0f) fail(n["up"] ? n["up"] : n, "camera.up must not be parallel to the view direction");
  }

  // (0, 180) as the format says, as the float the camera keeps: 180 (or a
  // number that rounds to it) projects the scene onto the window's centre
  // (cot 90 degrees is 6e-17), and below kMinFieldOfView float clipping
  // leaves bands of the window empty (1e-50 is 0 as a float, and
  // gluPerspective then does nothing; 1e-8 drew black bands).
  float fieldOfView(const YAML::Node& n) const {
    const double v = number(n, "camera.fov");
    std::ostringstream min;
    min << kMinFieldOfView;
    if (!(v >= kMinFieldOfView))
      fail(n, "camera.fov must be at least " + min.str() + " degrees (narrower, float rounding in clipping leaves bands of the window empty), not " +
                  n.Scalar());
    if (v >= 180.0) fail(n, "camera.fov must be below 180, not " + n.Scalar());
    const float f = static_cast<float>(v);
    if (f >= 180.0f) fail(n, "camera.fov must be below 180, not " + n.Scalar() + " (180 as a float)");
    return f;
  }

  PointLight readLight(const YAML::Node& n) const {
    checkKeys(n, kLightKeys, "a light");
    PointLight l;
    if (!n["position"]) fail(n, "a light needs a position");
    l.position = vec3(n["position"], "light position");
    if (n["color"]) l.color = rgb(n["color"], "light color");
    if (n["attenuation"]) {
      l.attenuation = rgb(n["attenuation"], "light attenuation");
      if (l.attenuation == Vec3(0.0f)) fail(n["attenuation"], "light attenuation must not be all zero");
    }
    if (n["radius"]) l.radius = static_cast<float>(number(n["radius"], "light radius", 0.0, 1e30));
    return l;
  }

  SceneMaterial readMaterial(const YAML::Node& n, const std::string& name) const {
    const std::string where = "material '" + name + "'";
    checkKeys(n, kMaterialKeys, where);
    SceneMaterial m;
    m.name = name;
    if (n["kind"]) {
      const std::string k = string(n["kind"], where + " kind");
      static const std::map<std::string, MaterialKind> kinds = {
          {"diffuse", MaterialKind::Diffuse}, {"mirror", MaterialKind::Mirror}, {"refractive", MaterialKind::Refractive},
          {"translucent", MaterialKind::Translucent}, {"frosted", MaterialKind::Frosted}};
      const auto it = kinds.find(k);
      if (it == kinds.end())
        fail(n["kind"], where + " kind must be diffuse, mirror, refractive, translucent or frosted, not '" + k + "'");
      m.kind = it->second;
    }
    if (n["diffuse"]) m.diffuse = rgb(n["diffuse"], where + " diffuse");
    if (n["specular"]) m.specular = rgb(n["specular"], where + " specular");
    if (n["emission"]) m.emission = rgb(n["emission"], where + " emission");
    if (n["shininess"] && n["roughness"]) fail(n["roughness"], where + " gives both shininess and roughness; give one");
    if (n["shininess"]) m.shininess = static_cast<float>(number(n["shininess"], where + " shininess", 0.0, 128.0));
    if (n["roughness"]) {
      // 1997 paper eq. (6): the Chi-square fit of Ward's isotropic Gaussian by
      // Phong: exponent 1.999 / alpha^2, scale 0.0398 * exponent.
      const double alpha = number(n["roughness"], where + " roughness");
      const double exponent = alpha > 0.0 ? kWardFitExponent / (alpha * alpha) : 1e30;
      if (!(exponent <= 128.0))
        fail(n["roughness"], where + " roughness must be at least 0.125: eq. (6) gives a Phong exponent of 1.999/alpha^2, "
                                 "and GL's largest is 128");
      m.shininess = static_cast<float>(exponent);
      m.roughness = static_cast<float>(alpha);
      m.wardSpecular = m.specular;
      m.specular *= static_cast<float>(kWardFitScale * exponent);
    }
    if (n["reflectance"]) m.reflectance = static_cast<float>(number(n["reflectance"], where + " reflectance", 0.0, 1.0));
    if (n["ior"]) {
      const double ior = number(n["ior"], where + " ior");
      if (ior <= 0.0) fail(n["ior"], where + " ior (index of refraction) must be greater than 0, not " + n["ior"].Scalar());
      m.ior = static_cast<float>(ior);
    }
    if (n["transmittance"]) m.transmittance = static_cast<float>(number(n["transmittance"], where + " transmittance", 0.0, 1.0));
    if (n["fog_distance"]) m.fogDistance = static_cast<float>(number(n["fog_distance"], where + " fog_distance", 0.0, 1e30, true));
    if (n["thickness"]) {
      m.thickness = static_cast<float>(number(n["thickness"], where + " thickness", 0.0, 1e6));
      const bool refracting =
          m.kind == MaterialKind::Refractive || m.kind == MaterialKind::Translucent || m.kind == MaterialKind::Frosted;
      if (!refracting && m.thickness > 0.0f)
        fail(n["thickness"], where + " thickness is for refracting materials (kind refractive, translucent or frosted): "
                                     "a slab shifts the view through it; this one is not looked through");
    }
    if (n["shear"]) m.shear = static_cast<float>(number(n["shear"], where + " shear", 0.0, 1e30));
    if (n["samples"]) m.samples = integer(n["samples"], where + " samples", 1, 1024);
    return m;
  }

  SceneObject readObject(const YAML::Node& n, const std::map<std::string, int>& materials, const Scene& s) const {
    checkKeys(n, kObjectKeys, "an object");
    SceneObject o;
    o.line = n.Mark().line + 1;
    // An object a --set gave has no line in the file: its place in the list.
    o.name = n["name"]          ? string(n["name"], "object name")
             : givenBySet(n) ? "object " + std::to_string(s.objects.size()) + " of the list"
                             : "object at line " + std::to_string(o.line);
    const std::string where = "object '" + o.name + "'";
    if (n["primitive"] && n["mesh"]) fail(n["mesh"], where + " gives both primitive and mesh; give one");
    if (!n["primitive"] && !n["mesh"]) fail(n, where + " needs a primitive or a mesh");
    const int sub = n["subdivisions"] ? integer(n["subdivisions"], where + " subdivisions", 1, 4096) : 0;
    if (n["primitive"]) {
      const std::string p = string(n["primitive"], where + " primitive");
      // Grids grow with the square of their divisions: 1024 gives a quad of
      // 2 M triangles, a box of 12.6 M (about 1 GB of mesh at most).
      if ((p == "box" || p == "quad" || p == "plane") && sub > 1024)
        fail(n["subdivisions"], where + " subdivisions must be at most 1024 for a " + p + " (its cells grow with the square), not " +
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
      else fail(n["primitive"], where + " primitive must be box, sphere, cylinder, quad or plane, not '" + p + "'");
    } else {
      const std::string rel = string(n["mesh"], where + " mesh");
      const std::filesystem::path path = std::filesystem::path(file_).parent_path() / rel;
      if (confine_) {
        std::error_code ec;
        const auto folder = std::filesystem::weakly_canonical(std::filesystem::absolute(std::filesystem::path(file_).parent_path()), ec);
        const auto mesh = std::filesystem::weakly_canonical(std::filesystem::absolute(path), ec);
        const auto inside = mesh.lexically_relative(folder);
        if (ec || std::filesystem::path(rel).is_absolute() || inside.empty() || *inside.begin() == "..")
          fail(n["mesh"], where + " mesh '" + rel + "' lies outside the scene's folder, which --confine refuses");
      }
      std::vector<std::string> said;
      try {
        o.mesh = loadMeshFile(path.string(), &said);
        o.meshFile = path.string();
      } catch (const std::exception& e) {
        fail(n["mesh"], where + ": " + e.what());
      }
      for (const std::string& w : said) warn(n["mesh"], where + ": mesh file '" + path.string() + "': " + w);
      checkTriangleBudget(n["mesh"], where, o.mesh.triangles.size());
    }
    triangles_ += o.mesh.triangles.size();
    Mat4 m(1.0f);
    if (n["translate"]) m = multiply(m, translationMatrix(vec3(n["translate"], where + " translate").x,
                                                           vec3(n["translate"], where + " translate").y,
                                                           vec3(n["translate"], where + " translate").z));
    if (n["rotate"]) {
      const YAML::Node r = n["rotate"];
      if (!r.IsSequence() || r.size() != 4) fail(r, where + " rotate must be [degrees, x, y, z]");
      const Vec3 axis(static_cast<float>(number(r[1], "rotate x")), static_cast<float>(number(r[2], "rotate y")),
                      static_cast<float>(number(r[3], "rotate z")));
      if (glm::dot(axis, axis) == 0.0f) fail(r, where + " rotate axis must not be zero");
      m = multiply(m, rotationMatrix(static_cast<float>(number(r[0], "rotate angle")), axis.x, axis.y, axis.z));
    }
    if (n["scale"]) {
      const YAML::Node sc = n["scale"];
      const Vec3 v = sc.IsScalar() ? Vec3(static_cast<float>(number(sc, where + " scale"))) : vec3(sc, where + " scale");
      if (v.x == 0.0f || v.y == 0.0f || v.z == 0.0f) fail(sc, where + " scale must not be zero");
      m = multiply(m, scaleMatrix(v.x, v.y, v.z));
    }
    transformMesh(o.mesh, m);
    if (n["material"]) {
      const std::string name = string(n["material"], where + " material");
      const auto it = materials.find(name);
      if (it == materials.end()) {
        std::vector<std::string_view> names;
        for (const auto& entry : materials) names.push_back(entry.first);
        const std::string best = closestMatch(name, names, 3);
        fail(n["material"], where + " uses unknown material '" + name + "'" +
                                (best.empty() ? "" : "; did you mean '" + best + "'?"));
      }
      o.material = it->second;
    }
    if (n["casts_shadows"]) o.castsShadows = boolean(n["casts_shadows"], where + " casts_shadows");
    if (s.materials[static_cast<std::size_t>(o.material)].specularKind()) checkPlanarFaces(n, o, where);
    return o;
  }

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
        fail(n, where + " has a zero-area face (face " + std::to_string(f) + "); specular objects need faces with area");
      const glm::dvec3 unit = normal / area2;
      for (std::uint32_t v : face) {
        const double d = std::fabs(glm::dot(glm::dvec3(o.mesh.positions[v] - p0), unit));
        if (d > 1e-4 * std::max(1.0, extent))
          fail(n, where + " has a non-planar face (face " + std::to_string(f) + ", a corner " + std::to_string(d) +
                      " off its plane); the paper's method needs planar specular faces");
      }
    }
  }

  // ---- expect: (docs/scene-format.md, "Expectations") --------------------
  void readExpectations(const YAML::Node& list, Scene& s) const {
    if (!list.IsSequence()) fail(list, "expect must be a list of expectations, like - {after: end, stencil: [0, 0], value: ZERO}");
    checkCount(list, "expect", kMaxSceneExpectations);
    for (const YAML::Node& n : list) s.expectations.push_back(readExpectation(n, s));
  }

  SceneExpectation readExpectation(const YAML::Node& n, const Scene& s) const {
    checkKeys(n, kExpectKeys, "an expectation");
    SceneExpectation e;
    e.line = n.Mark().line + 1;
    if (!n["after"]) fail(n, "an expectation needs after: a text of the pass label (mpr step SCENE lists them), or end");
    e.after = string(n["after"], "expect after");
    e.afterLine = n["after"].Mark().line + 1;
    e.afterColumn = n["after"].Mark().column + 1;
    if (e.after.empty()) fail(n["after"], "expect after must not be empty");
    for (const char* k : {"occurrence", "level", "light"})
      if (e.atEnd() && n[k])
        fail(n[k], std::string("expect after: end takes no ") + k + " (the finished render is one point)");
    if (n["occurrence"]) e.occurrence = integer(n["occurrence"], "expect occurrence", 1, 1 << 30);
    if (n["level"]) e.level = integer(n["level"], "expect level", 0, s.render.recursionDepth);
    if (n["light"]) {
      if (s.lights.empty()) fail(n["light"], "expect light: the scene has no lights");
      e.light = integer(n["light"], "expect light", 0, static_cast<long>(s.lights.size()) - 1);
    }
    ScriptProbe& p = e.probe;
    static const std::pair<const char*, ScriptProbe::Buffer> buffers[] = {
        {"stencil", ScriptProbe::Buffer::Stencil}, {"depth", ScriptProbe::Buffer::Depth},
        {"color", ScriptProbe::Buffer::Color}, {"accum", ScriptProbe::Buffer::Accum}};
    const char* buffer = nullptr;
    for (const auto& [name, b] : buffers) {
      if (!n[name]) continue;
      if (buffer) fail(n[name], std::string("an expectation probes one buffer: give ") + buffer + " or " + name + ", not both");
      buffer = name;
      p.buffer = b;
    }
    if (!buffer) fail(n, "an expectation needs the pixels it probes: stencil, depth, color or accum");
    const std::string what = std::string("expect ") + buffer;
    const YAML::Node at = n[buffer];
    const bool picture = static_cast<bool>(n["picture"]);
    if (picture && n["value"]) fail(n["picture"], "an expectation gives value or picture, not both");
    if (!picture && !n["value"]) fail(n, "an expectation needs a value (or, for stencil [x, y], a picture)");
    if (n["tolerance"] && p.buffer != ScriptProbe::Buffer::Color)
      fail(n["tolerance"], "expect tolerance is for color only");
    readRegion(at, what, s.render, p);
    if (picture) {
      if (p.buffer != ScriptProbe::Buffer::Stencil || p.form != ScriptProbe::Form::Pixel)
        fail(n["picture"], "expect picture takes stencil: [x, y], the picture's bottom-left pixel");
      readPicture(n["picture"], s.render, p);
      return e;
    }
    readValue(n["value"], what, s, p);
    if (n["tolerance"]) p.tolerance = integer(n["tolerance"], "expect tolerance", 0, 255);
    return e;
  }

  // [x, y], [x, y, width, height] or all, inside the window.
  void readRegion(const YAML::Node& at, const std::string& what, const RenderSettings& r, ScriptProbe& p) const {
    const std::string usage = what + " must be [x, y], [x, y, width, height] or all";
    if (at.IsScalar()) {
      if (at.Scalar() != "all") fail(at, usage + ", not '" + at.Scalar() + "'");
      p.form = ScriptProbe::Form::All;
      p.region = {0, 0, r.width, r.height};
      return;
    }
    if (!at.IsSequence() || (at.size() != 2 && at.size() != 4)) fail(at, usage);
    const int x = integer(at[0], what + " x", 0, 1 << 30), y = integer(at[1], what + " y", 0, 1 << 30);
    int w = 1, h = 1;
    if (at.size() == 4) {
      p.form = ScriptProbe::Form::Rect;
      w = integer(at[2], what + " width", 1, 1 << 30);
      h = integer(at[3], what + " height", 1, 1 << 30);
    }
    p.region = {x, y, x + w, y + h};
    checkInWindow(at, p, r);
  }

  void checkInWindow(const YAML::Node& at, const ScriptProbe& p, const RenderSettings& r) const {
    const PixelRect& g = p.region;
    if (g.x1 <= r.width && g.y1 <= r.height) return;
    const std::string window = std::to_string(r.width) + "x" + std::to_string(r.height) + " window";
    if (p.form == ScriptProbe::Form::Pixel)
      fail(at, "pixel (" + std::to_string(g.x0) + "," + std::to_string(g.y0) + ") is outside the " + window +
                   " (origin bottom-left)");
    fail(at, "the " + std::to_string(g.x1 - g.x0) + "x" + std::to_string(g.y1 - g.y0) + " region with bottom-left pixel (" +
                 std::to_string(g.x0) + "," + std::to_string(g.y0) + ") reaches outside the " + window);
  }

  void readValue(const YAML::Node& v, const std::string& what, const Scene& s, ScriptProbe& p) const {
    const std::string name = what + " value";
    switch (p.buffer) {
      case ScriptProbe::Buffer::Stencil: p.expected[0] = stencilValue(v, name, s, p.expectedName); return;
      case ScriptProbe::Buffer::Depth: p.expected[0] = integer(v, name, 0, (1 << 24) - 1); return;
      case ScriptProbe::Buffer::Color:
      case ScriptProbe::Buffer::Accum: {
        const bool color = p.buffer == ScriptProbe::Buffer::Color;
        if (!v.IsSequence() || v.size() != 4)
          fail(v, name + " must be " + (color ? "[r, g, b, a], four bytes 0 .. 255" : "[r, g, b, a], four words -32768 .. 32767"));
        for (std::size_t i = 0; i < 4; ++i)
          p.expected[i] = color ? integer(v[i], name, 0, 255) : integer(v[i], name, -32768, 32767);
        return;
      }
    }
  }

  // An integer, or ZERO, SHAD_MIN, SHAD_ZERO or MAX with an optional + n or
  // - n: the 1994 paper's levels for the profile's stencil width (the
  // formula of algorithms/stencil_levels.hpp: SHAD_MIN one-half, SHAD_ZERO
  // three-quarters of the range).
  std::int64_t stencilValue(const YAML::Node& v, const std::string& what, const Scene& s, std::string& named) const {
    const HardwareProfile profile = *findProfile(s.render.profile);
    const long max = static_cast<long>(profile.stencilMax());
    if (!v.IsScalar()) fail(v, what + " must be an integer or a stencil level (ZERO, SHAD_MIN, SHAD_ZERO, MAX, + or - n)");
    const std::string text = v.Scalar();
    if (!text.empty() && (std::isdigit(static_cast<unsigned char>(text[0])) || text[0] == '-' || text[0] == '+'))
      return integer(v, what, 0, max);
    std::size_t i = 0;
    while (i < text.size() && (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '_')) ++i;
    const std::string level = text.substr(0, i);
    const long range = max + 1;
    static const std::vector<std::string_view> names = {"ZERO", "SHAD_MIN", "SHAD_ZERO", "MAX"};
    long base = 0;
    if (level == "ZERO") base = 0;
    else if (level == "SHAD_MIN") base = range / 2;
    else if (level == "SHAD_ZERO") base = range / 4 * 3;
    else if (level == "MAX") base = max;
    else {
      const std::string best = closestMatch(level, names, 3);
      fail(v, what + " '" + text + "' is not an integer or a stencil level" +
                  (best.empty() ? " (known: ZERO, SHAD_MIN, SHAD_ZERO, MAX)" : "; did you mean '" + best + "'?"));
    }
    while (i < text.size() && text[i] == ' ') ++i;
    long offset = 0;
    char sign = 0;
    if (i < text.size()) {
      sign = text[i++];
      while (i < text.size() && text[i] == ' ') ++i;
      const std::string digits = text.substr(i);
      if ((sign != '+' && sign != '-') || digits.empty() || digits.size() > 9 ||
          digits.find_first_not_of("0123456789") != std::string::npos)
        fail(v, what + " '" + text + "' must be a level with an optional + n or - n, like SHAD_ZERO + 1");
      offset = std::stol(digits) * (sign == '-' ? -1 : 1);
    }
    const long value = base + offset;
    named = level + (sign ? std::string(" ") + sign + " " + std::to_string(offset < 0 ? -offset : offset) : "");
    if (value < 0 || value > max)
      fail(v, what + " " + named + " = " + std::to_string(value) + " is outside the " + std::to_string(profile.stencilBits) +
                  "-bit stencil of profile '" + profile.name + "' (0 .. " + std::to_string(max) + ")");
    return value;
  }

  // Rows top-down (as framebuffer/stencil_picture.hpp reads them): cells a
  // decimal 0 .. 255, . for 0, * for any value.
  void readPicture(const YAML::Node& n, const RenderSettings& r, ScriptProbe& p) const {
    if (!n.IsScalar()) fail(n, "expect picture must be a string of rows, like picture: |");
    std::istringstream lines(n.Scalar());
    for (std::string line; std::getline(lines, line);) {
      std::istringstream cells(line);
      std::vector<int> row;
      std::string text;
      for (std::string c; cells >> c;) {
        int v = -1;
        if (c == ".") v = 0;
        else if (c != "*") {
          const bool digits = c.size() <= 3 && c.find_first_not_of("0123456789") == std::string::npos;
          v = digits ? std::stoi(c) : 256;
          if (v > 255) fail(n, "expect picture cell '" + c + "' is not a stencil value 0 .. 255, '.' or '*'");
        }
        row.push_back(v);
        text += (text.empty() ? "" : " ") + c;
      }
      if (row.empty()) continue;
      if (!p.cells.empty() && row.size() != p.cells[0].size())
        fail(n, "expect picture row " + std::to_string(p.cells.size() + 1) + " has " + std::to_string(row.size()) +
                    " cells, the first row has " + std::to_string(p.cells[0].size()));
      p.cells.push_back(std::move(row));
      p.picture += text + "\n";
    }
    if (p.cells.empty()) fail(n, "expect picture has no rows");
    p.form = ScriptProbe::Form::Picture;
    p.region.x1 = p.region.x0 + static_cast<int>(p.cells[0].size());
    p.region.y1 = p.region.y0 + static_cast<int>(p.cells.size());
    checkInWindow(n, p, r);
  }

  void checkTriangleBudget(const YAML::Node& at, const std::string& where, std::uint64_t more) const {
    if (triangles_ + more > kMaxSceneTriangles)
      fail(at, where + " would bring the scene to " + std::to_string(triangles_ + more) + " triangles, more than the " +
                   std::to_string(kMaxSceneTriangles) + " a scene may hold (about 3 GB of mesh)");
  }

  // A list whose entries multiply the render's work, bounded before any is read.
  void checkCount(const YAML::Node& list, const std::string& key, std::size_t max) const {
    if (list.size() > max)
      fail(list, key + " lists " + std::to_string(list.size()) + " entries, more than the " + std::to_string(max) +
                     " a scene may hold (each multiplies the render's passes; YAML aliases repeat an entry at no cost in "
                     "the file)");
  }

  void checkLimits(const YAML::Node& doc, const Scene& s) const {
    // render.tessellation splits lit faces at render time: the scene it
    // makes is held to the same budget as the one the file describes.
    if (s.render.tessellation > 0.0f) {
      const std::uint64_t n = tessellatedTriangleCount(s, s.render.tessellation);
      if (n > kMaxSceneTriangles)
        fail(doc["render"]["tessellation"], "render.tessellation " + doc["render"]["tessellation"].Scalar() +
                                                " would split the lit faces into " + std::to_string(n) +
                                                " triangles, more than the " + std::to_string(kMaxSceneTriangles) +
                                                " a scene may hold (about 3 GB of mesh); raise it or simplify the scene");
    }
    const HardwareProfile p = *findProfile(s.render.profile);
    // 1994 paper: recursion levels live below SHAD_MIN (half the stencil
    // range), shadow counts between SHAD_MIN and the maximum.
    const int shadMin = static_cast<int>((p.stencilMax() + 1) / 2);
    const int maxDepth = shadMin - 1;
    if (s.render.recursionDepth > maxDepth) {
      const YAML::Node at = doc["render"] && doc["render"]["recursion_depth"] ? doc["render"]["recursion_depth"] : doc;
      fail(at, "render.recursion_depth " + std::to_string(s.render.recursionDepth) + " needs more stencil levels than the " +
                   std::to_string(p.stencilBits) + "-bit stencil of profile '" + p.name + "' holds: recursion levels lie below SHAD_MIN = " +
                   std::to_string(shadMin) + ", so the deepest is " + std::to_string(maxDepth));
    }
    if (s.render.softShadowMethod == SoftShadowMethod::DarknessLevels) checkDarknessLevels(doc, s, p);
  }

  // darkness_levels (1994's second soft-shadow method) sums its levels in the
  // accumulation buffer (glAccum LOAD, ACCUM 1/S, RETURN inside each view),
  // so it cannot also sum whole images there (antialiasing, depth of field,
  // frosted glass, glossy mirrors): one accumulation buffer. And every
  // sample's volume is counted above SHAD_ZERO at once: a point in all S
  // volumes of one caster holds SHAD_ZERO + S, at most the stencil's maximum.
  void checkDarknessLevels(const YAML::Node& doc, const Scene& s, const HardwareProfile& p) const {
    const YAML::Node at = doc["render"]["soft_shadow_method"] ? doc["render"]["soft_shadow_method"] : doc;
    const int samples = s.render.softShadowSamples;
    bool areaLight = false;
    for (const PointLight& l : s.lights) areaLight = areaLight || l.radius > 0.0f;
    if (!areaLight || samples <= 1) return;  // hard shadows: no levels
    const int above = static_cast<int>(p.stencilMax() - (p.stencilMax() + 1) / 4 * 3);
    if (samples > above)
      fail(at, "render.soft_shadow_method darkness_levels counts all " + std::to_string(samples) +
                   " light samples' shadow volumes in one stencil: the " + std::to_string(p.stencilBits) +
                   "-bit stencil of profile '" + p.name + "' counts at most " + std::to_string(above) +
                   " above SHAD_ZERO (use soft_shadow_samples <= " + std::to_string(above) + " or the images method)");
    std::string other;
    if (s.render.antialiasSamples > 1) other = "render.antialias_samples " + std::to_string(s.render.antialiasSamples);
    if (s.render.frosted)
      for (const SceneObject& o : s.objects) {
        const SceneMaterial& m = s.materials[static_cast<std::size_t>(o.material)];
        if ((m.kind == MaterialKind::Frosted || (m.kind == MaterialKind::Mirror && m.roughness > 0.0f)) && m.samples > 1 &&
            other.empty())
          other = "the " + std::string(m.kind == MaterialKind::Frosted ? "frosted" : "glossy") + " object '" + o.name +
                  "' (" + std::to_string(m.samples) + " samples)";
      }
    if (!other.empty())
      fail(at, "render.soft_shadow_method darkness_levels sums its levels in the accumulation buffer, which " + other +
                   " needs for its images: one accumulation buffer holds one sum (use the images method, or "
                   "render.frosted: false / antialias_samples: 1)");
  }

 private:
  std::string file_;
  std::vector<Override> overrides_;
  bool confine_ = false;                  // meshes only from inside the scene's folder
  mutable std::uint64_t triangles_ = 0;  // the scene's so far, for the budget
  mutable std::vector<std::string> warnings_;
};

Override applyOverride(YAML::Node& doc, const std::string& kv) {
  const auto eq = kv.find('=');
  if (eq == std::string::npos || eq == 0) throw SceneError("--set", 1, 1, "'" + kv + "' must be key.path=value");
  const std::string path = kv.substr(0, eq), value = kv.substr(eq + 1);
  std::vector<std::string> keys;
  std::vector<std::size_t> columns;  // each key's, 1-based in kv
  for (std::size_t start = 0;;) {
    const std::size_t dot = path.find('.', start);
    keys.push_back(path.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
    columns.push_back(start + 1);
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  const std::string where = "--set " + kv;
  for (std::size_t i = 0; i < keys.size(); ++i)
    if (keys[i].empty())
      throw SceneError(where, 1, static_cast<int>(columns[i]), "'" + path + "' has an empty key; keys are joined by single dots");
  YAML::Node parsed;
  try {
    parsed = YAML::Load(value);
  } catch (const YAML::Exception& e) {
    throw SceneError("--set", 1, static_cast<int>(eq) + 2, "'" + value + "' is not a YAML value: " + e.msg);
  }
  Override o{kv, {}, {}};
  // yaml-cpp nodes are handles (assigning one to another rebinds the
  // first's node): walk down by copying handles, then assign. A list is
  // entered by its index (objects.0.scale): yaml-cpp's operator[] with a
  // text key turned the list into a mapping {"0": ...}, which the loader
  // then refused for not being a list, against the scene file.
  std::vector<YAML::Node> chain{doc};
  std::string name;  // the path so far
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const std::string& key = keys[i];
    const bool last = i + 1 == keys.size();
    const int column = static_cast<int>(columns[i]);
    YAML::Node at = chain.back();
    if (at.IsSequence()) {
      const bool digits = key.size() <= 9 && key.find_first_not_of("0123456789") == std::string::npos;
      const std::size_t index = digits ? std::stoul(key) : 0;
      if (!digits || index >= at.size())
        throw SceneError(where, 1, column,
                         name + " is a list of " + std::to_string(at.size()) + (at.size() == 1 ? " entry" : " entries") +
                             (at.size() == 0 ? "" : ": give an index from 0 to " + std::to_string(at.size() - 1)) +
                             ", not '" + key + "'");
      if (last) {
        at[index] = parsed;
        o.node.reset(at[index]);
        return o;
      }
      chain.push_back(at[index]);
    } else if (at.IsScalar()) {
      throw SceneError(where, 1, column, name + " is a value ('" + at.Scalar() + "'), not a mapping with a key '" + key + "'");
    } else {  // a mapping, or null (an empty document): operator[] makes it a mapping
      if (last) {
        at[key] = parsed;
        o.node.reset(at[key]);
        return o;
      }
      const YAML::Node next = at[key];
      if (!next.IsDefined() || next.IsNull()) {
        at[key] = YAML::Node(YAML::NodeType::Map);
        o.created.push_back(at[key]);
      }
      chain.push_back(at[key]);
    }
    name += (name.empty() ? "" : ".") + key;
  }
  return o;
}

// Where a text's second document starts (its "---"), if it has one. The
// parser is asked for two documents at most: yaml-cpp's LoadAll, which asks
// until none is left, loops for ever on some malformed text (a 524-byte
// scene found by fuzz/scene_fuzzer), handing on an empty document each time.
std::optional<YAML::Mark> secondDocumentStart(const std::string& text) {
  struct Starts : YAML::EventHandler {
    std::vector<YAML::Mark> marks;
    void OnDocumentStart(const YAML::Mark& m) override { marks.push_back(m); }
    void OnDocumentEnd() override {}
    void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
    void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
    void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t, const std::string&) override {}
    void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
    void OnSequenceEnd() override {}
    void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
    void OnMapEnd() override {}
  } starts;
  std::istringstream in(text);
  YAML::Parser parser(in);
  for (int i = 0; i < 2 && parser.HandleNextDocument(starts); ++i) {
  }
  if (starts.marks.size() > 1) return starts.marks[1];
  return std::nullopt;
}

}  // namespace

Scene loadSceneText(const std::string& text, const std::string& file, const std::vector<std::string>& overrides,
                    bool confine) {
  YAML::Node doc;
  try {
    // YAML::Load reads up to a second document's "---" and drops the rest
    // of the file without a word: a second document is refused.
    if (const std::optional<YAML::Mark> m = secondDocumentStart(text)) {
      // A real second document follows a "---" or a "..." that ended the
      // first; anything else is text yaml-cpp could not fit into the first.
      const std::size_t pos = static_cast<std::size_t>(std::max(m->pos, 0));
      const std::size_t before = text.find_last_not_of(" \t\r\n", pos == 0 ? 0 : pos - 1);
      const bool marked = text.compare(pos, 3, "---") == 0 ||
                          (pos > 0 && before != std::string::npos && before >= 2 && text.compare(before - 2, 3, "...") == 0);
      throw SceneError(file, m->line + 1, m->column + 1,
                       marked ? "a second YAML document starts here; a scene file holds one (remove this '---' and "
                                "what follows, or merge it into the first)"
                              : "YAML syntax: this does not continue the document above it (a scene file holds one "
                                "YAML document)");
    }
    // (An empty text has no document: a null node of its own, which a --set
    // path can make a mapping of.)
    doc = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw SceneError(file, e.mark.line + 1, e.mark.column + 1, "YAML syntax: " + e.msg);
  }
  std::vector<Override> applied;
  for (const std::string& kv : overrides) applied.push_back(applyOverride(doc, kv));
  try {
    Loader loader(file, applied, confine);
    Scene scene = loader.load(doc);
    for (const std::string& w : loader.warnings()) std::cerr << w << "\n";
    return scene;
  } catch (const YAML::Exception& e) {
    throw SceneError(file, e.mark.line + 1, e.mark.column + 1, e.msg);
  }
}

Scene loadSceneFile(const std::string& path, const std::vector<std::string>& overrides, bool confine) {
  std::string text;
  try {
    text = readInputFile(path, kMaxSceneBytes, "the scene file");
  } catch (const std::runtime_error& e) {
    throw SceneError(path, 0, 0, e.what());
  }
  return loadSceneText(text, path, overrides, confine);
}

std::string describeSceneFormat() {
  std::ostringstream o;
  auto section = [&](const std::string& name, const std::string& type, const std::vector<KeySpec>& keys, bool last) {
    o << "    \"" << name << "\": {\"type\": \"" << type << "\", \"properties\": {\n";
    for (std::size_t i = 0; i < keys.size(); ++i)
      o << "      \"" << keys[i].key << "\": {\"type\": \"" << keys[i].type << "\", \"description\": \""
        << keys[i].meaning << "\"}" << (i + 1 < keys.size() ? "," : "") << "\n";
    o << "    }}" << (last ? "" : ",") << "\n";
  };
  o << "{\n  \"title\": \"MPR scene\",\n  \"type\": \"object\",\n  \"additionalProperties\": false,\n  \"properties\": {\n";
  section("camera", "object", kCameraKeys, false);
  o << "    \"ambient\": {\"type\": \"rgb\", \"description\": \"scene ambient light\"},\n";
  section("lights[]", "array of object", kLightKeys, false);
  section("materials.<name>", "object", kMaterialKeys, false);
  section("objects[]", "array of object", kObjectKeys, false);
  section("render", "object", kRenderKeys, false);
  section("expect[]", "array of object", kExpectKeys, true);
  o << "  }\n}\n";
  return o.str();
}

}  // namespace mpr
