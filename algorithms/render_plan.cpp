#include "algorithms/render_plan.hpp"

#include <cmath>
#include <sstream>

#include "algorithms/image_samples.hpp"
#include "algorithms/light_path.hpp"
#include "algorithms/ref_light.hpp"
#include "algorithms/shadow_pass.hpp"
#include "framebuffer/profile.hpp"
#include "util/saturating.hpp"

namespace mpr {

std::uint64_t RenderPlan::predictedViewsAtLevel(int level) const {
  // Every accumulated image is a whole render (image_samples.hpp).
  const auto n = static_cast<std::uint64_t>(images);
  if (level == 0) return n;
  if (!reflections || level > recursionDepth) return 0;
  // 1994 eq. (5): n (n - 1)^(d - 1) renderings at depth d; a planar face
  // never sees itself, so each view recurses into the other n - 1 faces.
  std::uint64_t v = saturatingMul(n, static_cast<std::uint64_t>(refFaces));
  for (int k = 1; k < level && v != kSaturated; ++k) v = saturatingMul(v, static_cast<std::uint64_t>(refFaces - 1));
  return v;
}

std::uint64_t RenderPlan::predictedViews() const {
  std::uint64_t total = 0;
  for (int l = 0; l <= recursionDepth; ++l) total = saturatingAdd(total, predictedViewsAtLevel(l));
  return total;
}

namespace {
std::uint64_t shadowedViews(const RenderPlan& p) {
  std::uint64_t views = 0;
  for (int l = 0; l <= std::min(p.shadowDepth, p.recursionDepth); ++l)
    views = saturatingAdd(views, p.predictedViewsAtLevel(l));
  return p.shadows ? views : 0;
}
}  // namespace

namespace {
// Mirrors and glass receive shadows (bug 4): every face a shadowed view
// recurses into has its own colour drawn with a shadow pass and a lit pass
// per light; the faces a view at level L recurses into are the views at
// level L + 1.
std::uint64_t shadowedFaces(const RenderPlan& p) {
  std::uint64_t faces = 0;
  if (!p.shadows) return 0;
  for (int l = 0; l <= std::min(p.shadowDepth, p.recursionDepth - 1); ++l)
    faces = saturatingAdd(faces, p.predictedViewsAtLevel(l + 1));
  return faces;
}
}  // namespace

std::uint64_t RenderPlan::predictedShadowPasses() const {
  // draw_all_shadows per light, draw_ref_shadows per reflected light, and
  // the shadows on each face recursed into, per light.
  return saturatingAdd(saturatingMul(shadowedViews(*this), static_cast<std::uint64_t>(lights + reflectedLights)),
                       saturatingMul(shadowedFaces(*this), static_cast<std::uint64_t>(lights)));
}

std::uint64_t RenderPlan::predictedLightPasses() const {
  // A light drawn in darkness levels has S lit passes where shadows are
  // drawn (one per level), one elsewhere.
  const std::uint64_t extraLevels =
      saturatingMul(static_cast<std::uint64_t>(darknessLights), static_cast<std::uint64_t>(darknessLevels - 1));
  // Every view adds each light and each virtual light once (the virtual
  // ones shadowed or not).
  const std::uint64_t base =
      saturatingAdd(saturatingMul(predictedViews(), static_cast<std::uint64_t>(lights + reflectedLights)),
                    saturatingMul(shadowedViews(*this), extraLevels));
  return saturatingAdd(base, saturatingMul(shadowedFaces(*this), static_cast<std::uint64_t>(lights)));
}

std::uint64_t RenderPlan::predictedPasses() const {
  if (lightPathsOverLimit) return kSaturated;  // refused by any --max-passes
  return saturatingAdd(saturatingAdd(predictedViews(), predictedLightPasses()), predictedShadowPasses());
}

double RenderPlan::paperEq7ShadowGenerations() const {
  // d: the depth of the light's reflections and refractions.
  const double n = refFaces, d = shadows && refFaces > 0 ? lightBounces : 0;
  return n * (d * d + 3.0 * d) / 2.0 + 1.0;
}

double RenderPlan::paperEq8Images() const {
  return std::pow(static_cast<double>(refFaces), reflections ? recursionDepth : 0) + 1.0;
}

RenderPlan planRender(const Scene& scene, bool cull) {
  RenderPlan p;
  p.cull = cull;
  p.levels = stencilLevelsFor(findProfile(scene.render.profile).value_or(indigoProfile()));
  p.lights = static_cast<int>(scene.lights.size());
  const std::vector<RefFace> faces = findRefFaces(scene);
  for (const RefFace& f : faces) {
    ++p.refFaces;
    if (f.refracts()) ++p.refractingFaces;
  }
  for (const SceneObject& o : scene.objects) p.shadowCasters += shadowRole(o, scene) != ShadowRole::None;

  p.reflections = p.refFaces > 0 && scene.render.recursionDepth > 0;
  p.recursionDepth = p.reflections ? scene.render.recursionDepth : 0;
  if (p.refFaces == 0) p.notes.push_back("no mirror or refracting faces: no recursion (draw_ref_objects never runs)");
  else if (scene.render.recursionDepth == 0) p.notes.push_back("recursion_depth 0: specular faces drawn as their own colour");
  if (!scene.render.reflections) p.notes.push_back("reflections off: mirrors drawn as their own colour");
  if (!scene.render.refractions) p.notes.push_back("refractions off: refracting faces drawn as their own colour");
  if (!scene.render.translucency) p.notes.push_back("translucency off: translucent faces drawn as their own colour");

  // A mirror lit by a light lights the room through its light volume, a
  // stencil count like a shadow's, so it needs the shadow passes even when
  // nothing casts a shadow.
  p.lightBounces = lightBounces(scene.render);
  bool overLimit = false;
  const std::vector<LightPath> paths = lightPaths(scene, faces, p.lightBounces, kMaxLightPaths, &overLimit);
  const int refLights = static_cast<int>(paths.size());
  p.shadows = scene.render.shadows && p.lights > 0 && (p.shadowCasters > 0 || refLights > 0);
  p.shadowDepth = p.shadows ? std::min(scene.render.shadowRecursionDepth, p.recursionDepth) : 0;
  // Virtual lights light every view, shadowed where shadows are drawn and
  // through their light volumes alone elsewhere (past shadow_recursion_depth,
  // or with shadows off): their light is not lost (issue 43).
  if (p.lights > 0) {
    p.reflectedLights = refLights;
    p.lightPathsOverLimit = overLimit;
  }
  if (p.shadows) {
    // Shadow generations (1997 eq. (7)'s unit): the light's own volumes,
    // and per virtual light its own shadows plus those carried from each
    // stretch of its path.
    p.shadowGenerations = p.lights;
    for (const LightPath& lp : paths) {
      p.shadowGenerations += 1 + static_cast<std::uint64_t>(lp.faces.size());
      p.longestLightPath = std::max(p.longestLightPath, static_cast<int>(lp.faces.size()));
    }
  }
  p.images = accumulatedImages(scene);
  if (p.shadows)
    for (const PointLight& l : scene.lights)
      if (const int k = darknessLevelSamples(scene, l); k > 1) ++p.darknessLights, p.darknessLevels = k;
  bool areaLight = false;
  for (const PointLight& l : scene.lights) areaLight = areaLight || l.radius > 0.0f;
  if (!areaLight && scene.render.softShadowSamples > 1)
    p.notes.push_back("soft_shadow_samples without a light radius: hard shadows, one image");
  if (p.lights == 0) p.notes.push_back("no lights: the ambient pass only");
  else if (!scene.render.shadows) p.notes.push_back("shadows off: no shadow volumes");
  else if (!p.shadows) p.notes.push_back("no object casts a shadow and no light reaches beyond a specular face: no shadow volumes");
  return p;
}

namespace {
// Where the recursion stops (issue 43, defect 7): the views of the deepest
// level draw the specular faces they see as their own material instead of
// looking through them (draw_window.cpp, drawNotRecursedInto), so a user
// knows which objects to raise render.recursion_depth for. Every face but
// the one a view looks through is one it may see: with culling off each of
// the n (n-1)^(d-1) views of level d >= 1 has n - 1 of them (the camera's
// view, at recursion_depth 0, all n).
std::string depthRunsOutText(const RenderPlan& p, const Scene& s) {
  if (p.refFaces == 0) return {};
  const int deepest = p.recursionDepth;
  const std::uint64_t faces = static_cast<std::uint64_t>(deepest == 0 ? p.refFaces : p.refFaces - 1);
  const std::uint64_t views = p.predictedViewsAtLevel(deepest);
  std::ostringstream o;
  if (faces == 0 || views == 0) {
    o << "  depth never runs out: the one specular face is looked through at level 1, and the view through it "
         "sees no other\n";
    return o.str();
  }
  // The objects whose faces are drawn so, in scene order, with their counts.
  std::vector<std::pair<std::size_t, int>> objects;
  for (const RefFace& f : findRefFaces(s)) {
    const auto object = static_cast<std::size_t>(f.object);
    if (objects.empty() || objects.back().first != object) objects.emplace_back(object, 0);
    ++objects.back().second;
  }
  constexpr std::size_t kNamed = 8;
  o << "  depth runs out at level " << deepest << " (render.recursion_depth " << s.render.recursionDepth << "): its "
    << countText(views) << (views == 1 ? " view" : " views (culling off)") << (views == 1 ? " draws" : " draw")
    << " up to " << faces << " specular face"
    << (faces == 1 ? "" : "s") << (views == 1 ? "" : " each") << " as their own material, not looked through:";
  for (std::size_t i = 0; i < objects.size() && i < kNamed; ++i) {
    const SceneObject& obj = s.objects[objects[i].first];
    const bool mirror = s.materials[static_cast<std::size_t>(obj.material)].kind == MaterialKind::Mirror;
    o << (i ? ", " : " ") << '"' << obj.name << "\" (" << objects[i].second << (mirror ? " mirror" : " refracting")
      << " face" << (objects[i].second == 1 ? "" : "s") << ")";
  }
  if (objects.size() > kNamed) o << " and " << objects.size() - kNamed << " more objects";
  o << "; raise render.recursion_depth to look through them\n";
  return o.str();
}
}  // namespace

std::string describePlan(const RenderPlan& p, const Scene& s) {
  std::ostringstream o;
  o << "scene: " << s.file << " (" << s.objects.size() << " objects, " << s.triangleCount() << " triangles, "
    << p.lights << " lights, " << p.refFaces - p.refractingFaces << " mirror faces, " << p.refractingFaces
    << " refracting faces)\n";
  o << "stencil: ZERO 0, levels 1.." << p.levels.maxRecursionDepth() << ", SHAD_MIN " << p.levels.shadMin
    << ", SHAD_ZERO " << p.levels.shadZero << ", max " << p.levels.max << " (at most "
    << p.levels.maxShadowDepthAbove() << " nested shadow volumes)\n";
  o << "plan (1994 Figure 4):\n";
  if (p.images > 1)
    o << "  accumulation: " << p.images << " whole renders summed with weight 1/" << p.images << " ("
      << s.render.antialiasSamples << " antialias" << (s.camera.aperture > 0.0f ? " and lens" : "") << " samples, "
      << s.render.softShadowSamples << " light samples of the lights with a radius; each table cycled)\n";
  o << "  draw_window: ambient pass, then per light "
    << (p.shadows ? "shadow volumes (draw_all_shadows) and a lit pass" : "a lit pass (no shadows)") << "\n";
  if (s.render.softShadowMethod == SoftShadowMethod::Pivot && p.shadows && p.images > 1 &&
      s.render.softShadowSamples > 1)
    o << "  pivot (1997 Fig. 7): the lights' shadow volumes built once from their centres; each image moves only "
         "their far ends, by the light's jitter times a2/a1 about the silhouette nodes (no silhouette recomputed)\n";
  if (p.darknessLights > 0)
    o << "  darkness levels (1994's second soft-shadow method): " << p.darknessLights << " light"
      << (p.darknessLights > 1 ? "s" : "") << " with a radius, the shadow volumes of their " << p.darknessLevels
      << " samples counted in one pass, then " << p.darknessLevels
      << " lit passes from the centre with the stencil stepped down between them, summed by glAccum "
         "(LOAD, ACCUM 1/" << p.darknessLevels << ", RETURN); virtual lights stay hard\n";
  if (p.reflectedLights > 0)
    o << "  draw_ref_shadows: " << p.reflectedLights
      << " virtual lights (a light reflected by a mirror face or refracted through a glass face"
      << (p.lightBounces > 1 ? ", or a virtual light's again, paths of up to " + std::to_string(p.lightBounces) +
                                   " faces (the longest found: " + std::to_string(p.longestLightPath) +
                                   "), each light volume stenciled once per face of its path"
                             : std::string())
      << "), each with its light volume" << (p.shadows ? " and shadows" : "") << "\n";
  if (p.lightPathsOverLimit)
    o << "  refused: more than " << kMaxLightPaths << " light paths (lower render.light_bounces)\n";
  if (p.reflections)
    o << "  draw_ref_objects: " << p.refFaces << " faces, recursion depth " << p.recursionDepth
      << (p.shadows ? ", shadows in views up to level " + std::to_string(p.shadowDepth) : std::string()) << "\n";
  o << depthRunsOutText(p, s);
  for (const std::string& n : p.notes) o << "  left out: " << n << "\n";
  o << "predicted (culling off):\n";
  o << "  views (scene renderings): " << countText(p.predictedViews());
  if (p.reflections) {
    o << " =";
    for (int l = 0; l <= p.recursionDepth; ++l) o << (l ? " + " : " ") << countText(p.predictedViewsAtLevel(l));
    o << "  (per level; 1994 eq. (5): n (n-1)^(d-1))";
  }
  o << "\n  lit passes: " << countText(p.predictedLightPasses()) << "\n";
  o << "  shadow-volume passes: " << countText(p.predictedShadowPasses()) << "\n";
  if (p.shadows)
    o << "  shadow generations: " << p.shadowGenerations << " (every light's own volumes; per virtual light its "
      << "own and one set per stretch of its path)\n";
  o << "  1997 eq. (7), shadow generations per light: " << p.paperEq7ShadowGenerations()
    << "; eq. (8), images: " << p.paperEq8Images() << " (the papers' order-of-growth estimates)\n";
  o << "culling " << (p.cull ? "on: faces seen from behind or hidden are skipped, counts never exceed these"
                             : "off") << "\n";
  return o.str();
}

}  // namespace mpr
