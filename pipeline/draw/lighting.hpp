#pragma once
// GL 1.x fixed-function lighting (GL 1.1 section 2.13), evaluated in eye
// space per vertex: 8 lights with ambient, diffuse and specular terms,
// shininess, local or infinite viewer, distance attenuation, spot lights, and
// the colour-material tracking of the current colour.
#include <array>

#include "util/vecmath.hpp"

namespace mpr {

inline constexpr int kMaxLights = 8;

struct LightSource {
  bool enabled = false;
  Vec4 ambient{0, 0, 0, 1};
  Vec4 diffuse{0, 0, 0, 1};   // GL_LIGHT0 defaults to (1,1,1,1), set by the context
  Vec4 specular{0, 0, 0, 1};  // likewise
  Vec4 position{0, 0, 1, 0};  // eye space (transformed by the modelview when specified)
  Vec3 spotDirection{0, 0, -1};  // eye space
  float spotExponent = 0.0f;
  float spotCutoff = 180.0f;
  float constantAttenuation = 1.0f;
  float linearAttenuation = 0.0f;
  float quadraticAttenuation = 0.0f;
};

struct Material {
  Vec4 ambient{0.2f, 0.2f, 0.2f, 1.0f};
  Vec4 diffuse{0.8f, 0.8f, 0.8f, 1.0f};
  Vec4 specular{0, 0, 0, 1};
  Vec4 emission{0, 0, 0, 1};
  float shininess = 0.0f;
};

struct LightModel {
  Vec4 ambient{0.2f, 0.2f, 0.2f, 1.0f};
  bool localViewer = false;
  bool twoSide = false;
};

struct LightingState {
  std::array<LightSource, kMaxLights> lights;
  LightModel model;
  std::array<Material, 2> material;  // [0] front, [1] back
  // Emulates Mesa 22.3's fixed-function program (`mpr conform` only, docs/explanation/mesa.md,
  // "Known Mesa departures", shininess0_attenuated): with every shininess 0
  // (material_shininess_is_zero) its dot products are all N.VP, so for a light
  // with a spot cutoff or a positional light with attenuation (ffvertex_prog.c
  // calculate_light_attenuation, then LIT) the specular factor is
  // (N.VP)^(N.VP) instead of 1.
  bool mesaShininess0Attenuated = false;
  // Mesa's material_shininess_is_zero (ffvertex_prog.c) for the draw: no
  // shininess active, so the program takes no specular power and the
  // specular factor is 1 wherever N.L > 0. With a shininess active it takes
  // max(N.H, 0)^shininess, which llvmpipe makes 0 at N.H <= 0 even for a
  // shininess of 0 (GL leaves 0^0 open): shininess_zero_power.gls.
  bool shininessKeyZero = true;
  // Mesa lights in object space where nothing needs eye coordinates
  // (mesaLightsInObjectSpace): the program takes the normal as given
  // (ffvertex_prog.c need_eye_coords), the lights' directions by the
  // modelview's inverse and the half vector's eye z by its third row
  // (compute_light_positions). Then the light positions above are in object
  // space.
  bool objectSpace = false;
  Vec3 eyeZDirection{0.0f, 0.0f, 1.0f};  // Mesa's _EyeZDir
};

// Whether Mesa lights `s` in object space under a modelview with Mesa's
// flags `modelviewFlags` (light.c _mesa_update_tnl_spaces): every enabled
// light directional and none a spot light, no local viewer, the modelview
// rotation and translation only.
bool mesaLightsInObjectSpace(const LightingState& s, unsigned modelviewFlags);

// Puts `s`'s lights into object space as Mesa does for `modelview` (whose
// inverse Mesa keeps as `inverse`): sets objectSpace and eyeZDirection.
// Only for a state mesaLightsInObjectSpace accepts.
void toObjectSpace(LightingState& s, const Mat4& modelview, const Mat4& inverse);

// The lit colour of a vertex at eye position `eye` with unit or non-unit eye
// normal `normal` (used as given: GL_NORMALIZE is the caller's business), for
// the front material (back = false) or the back material with the normal
// negated (back = true). RGB is clamped to [0, 1]; alpha is the material's
// diffuse alpha, clamped.
Vec4 lightVertex(const LightingState& s, const Vec4& eye, const Vec3& normal, bool back);

}  // namespace mpr
