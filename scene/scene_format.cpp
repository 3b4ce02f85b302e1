#include "scene/scene_format.hpp"

#include <cstddef>
#include <sstream>
#include <string>

#include "scene/scene_loader.hpp"

namespace mpr {
namespace scene_format {

const std::vector<KeySpec> kTopKeys = {
    {"camera", "mapping", "the viewer"},
    {"ambient", "rgb", "scene ambient light, default [0.1, 0.1, 0.1]"},
    {"lights", "sequence of light", "point lights"},
    {"materials", "mapping name -> material", "named materials, each given to an object"},
    {"objects", "sequence of object", "what is drawn"},
    {"render", "mapping", "image size, recursion, effects, hardware profile"},
    {"expect", "sequence of expectation", "probes of the buffers at named points of the 1994 algorithm"},
};
const std::vector<KeySpec> kCameraKeys = {
    {"position", "vec3", "eye position"}, {"look_at", "vec3", "point looked at"},
    {"up", "vec3", "up direction, default [0, 1, 0]"}, {"fov", "number in [0.05, 180)", "vertical field of view, degrees, default 45"},
    {"near", "number > 0", "near plane distance"}, {"far", "number > near", "far plane distance"},
    {"aperture", "number >= 0", "lens radius for depth of field (images accumulated: render.antialias_samples), default 0"},
    {"focal_distance", "number > 0", "distance in focus, with an aperture above 0; default the distance to look_at"},
};
const std::vector<KeySpec> kLightKeys = {
    {"position", "vec3", "light position"}, {"color", "rgb", "intensity, default [1, 1, 1]"},
    {"attenuation", "vec3 >= 0", "constant, linear, quadratic; default [1, 0, 0]"},
    {"radius", "number >= 0", "area light radius for soft shadows (render.soft_shadow_samples above 1), default 0"},
};
const std::vector<KeySpec> kMaterialKeys = {
    {"kind", "diffuse | mirror | refractive | translucent | frosted", "the specular effect, default diffuse"},
    {"diffuse", "rgb", "diffuse reflectance, default [0.8, 0.8, 0.8]"},
    {"specular", "rgb", "Phong specular reflectance, default [0, 0, 0]"},
    {"shininess", "number in [0, 128]", "Phong exponent, with a specular above 0"},
    {"roughness", "number >= 0.125",
     "Ward alpha, mapped to Phong by the 1997 paper's eq. (6) (with a specular above 0); on a mirror also a glossy "
     "reflection (its view sheared by 2 alpha)"},
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
     "sphere slices (stacks are half), cylinder slices, plane, quad and box-side divisions (cells per side); "
     "primitives only"},
    {"translate", "vec3", "applied last"}, {"rotate", "[degrees, x, y, z]", "applied after scale"},
    {"scale", "number or vec3", "applied first"}, {"material", "name", "a key of `materials`"},
    {"casts_shadows", "bool",
     "gets a shadow volume; default true, false for quad and plane; mirrors never, refracting faces always "
     "(their light goes on through their light volume)"},
};
const std::vector<KeySpec> kRenderKeys = {
    {"width", "integer", "image width, default 640"}, {"height", "integer", "image height, default 480"},
    {"recursion_depth", "integer >= 0", "mirror and refraction levels (with a specular object), default 2"},
    {"shadow_recursion_depth", "integer >= 0", "levels that get shadows (with a specular object), default 1"},
    {"light_bounces", "integer in [1, 16]",
     "specular faces a light may pass on its way, each bounce a virtual light of a virtual light (1997 §4.2-4.3); "
     "default shadow_recursion_depth, at least 1 (another value with two specular faces or more)"},
    {"soft_shadow_samples", "integer >= 1",
     "light samples of every light with a radius, one shadowed image each, accumulated; default 1"},
    {"antialias_samples", "integer >= 1", "jittered (and, with camera.aperture, lens) images accumulated, default 1"},
    {"soft_shadow_method", "images | darkness_levels | pivot",
     "how soft shadows are made: images (1994's first method, default), darkness_levels (its second: every "
     "sample's shadow volume counted at once, the light added per darkness level) or pivot (1997 Fig. 7: images "
     "whose shadow volumes are built once and only their far ends moved per sample); another than images only with "
     "soft shadows"},
    {"shadows", "bool", "default true"}, {"reflections", "bool", "default true"},
    {"refractions", "bool", "default true"}, {"translucency", "bool", "default true"},
    {"frosted", "bool", "default true"},
    {"profile", "indigo | mesa",
     "hardware profile, default indigo; the two differ in the accumulation buffer (mesa's has alpha and wraps its sums)"},
    {"refraction_map", "projection | projection_zeroed_z | end_of_pipeline",
     "where a refracted view's image map M3 is applied (a refracting face without thickness), default projection (the "
     "4x4 with Z kept)"},
    {"tessellation", "auto | number >= 0",
     "the longest edge of a lit triangle the pipeline draws (larger ones are split for GL's per-vertex lighting), "
     "world units; 0: as modelled; default auto: every edge at most 1/4 of its distance to the nearest light"},
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

}  // namespace scene_format

std::string describeSceneFormat() {
  using namespace scene_format;
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
