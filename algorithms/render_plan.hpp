#pragma once
// The planner: from the scene, which passes of the 1994 paper's Figure 4 the
// render needs, so that a scene pays only for the effects it uses (no
// specular face: no recursion; no light or no shadow caster: no shadow
// passes), and the pass counts it predicts.
#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/ref_face.hpp"
#include "algorithms/stencil_levels.hpp"
#include "scene/scene.hpp"

namespace mpr {

struct RenderPlan {
  int lights = 0;
  int images = 1;             // whole renders accumulated (antialias, lens and light samples)
  int refFaces = 0;           // faces the recursion looks through (mirror and refracting)
  int refractingFaces = 0;    // of which refract (the rest reflect)
  int shadowCasters = 0;      // objects with a shadow volume: casters and refracting faces
  int reflectedLights = 0;    // light paths with a virtual light: draw_ref_shadows (light_path.hpp)
  int lightBounces = 1;       // the most faces a light path passes (render.light_bounces)
  int longestLightPath = 0;   // the most faces a light path found passes
  bool lightPathsOverLimit = false;  // more than kMaxLightPaths: refused (predictedPasses saturates)
  std::uint64_t shadowGenerations = 0;  // volume sets generated per view: 1997 eq. (7)'s unit, all lights
  // darkness_levels (1994's second soft-shadow method): the lights drawn in
  // levels and how many each (soft_shadow_samples); their lit pass becomes
  // `darknessLevels` lit passes in every view with shadows.
  int darknessLights = 0;
  int darknessLevels = 1;
  bool shadows = false;       // shadow volumes drawn (draw_all_shadows)
  bool reflections = false;   // draw_ref_objects runs
  int recursionDepth = 0;     // REF_LEVEL reaches this (0 without reflections)
  int shadowDepth = 0;        // shadows are drawn in views up to this level
  bool cull = true;           // skip faces seen from behind and faces no pixel shows
  StencilLevels levels;
  std::vector<std::string> notes;  // what the planner left out and why

  // The stencil is in use: shadow counts, recursion levels or light volumes.
  bool usesStencil() const { return shadows || reflections || reflectedLights > 0; }

  // Exact counts for this implementation with culling off: views (scene
  // renderings: the camera plus every virtual camera), lit passes and
  // shadow-volume passes. The paper's estimates are given beside them. The
  // counts saturate (util/saturating.hpp) instead of wrapping.
  std::uint64_t predictedViews() const;
  std::uint64_t predictedViewsAtLevel(int level) const;  // 1994 eq. (5) for level >= 1
  std::uint64_t predictedShadowPasses() const;           // views up to shadowDepth x lights
  std::uint64_t predictedLightPasses() const;            // views x lights (+ the darkness levels)
  std::uint64_t predictedPasses() const;                 // the three above together (mpr render --max-passes)
  double paperEq7ShadowGenerations() const;               // 1997 eq. (7), per light
  double paperEq8Images() const;                          // 1997 eq. (8)
};

RenderPlan planRender(const Scene& scene, bool cull = true);

// The plan as text, for `mpr info`.
std::string describePlan(const RenderPlan& plan, const Scene& scene);

}  // namespace mpr
