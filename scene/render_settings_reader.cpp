// The scene's render: section (image size, recursion, effects, hardware
// profile), and the limits the finished scene is held to: what the
// profile's stencil and accumulation buffers can hold, and the triangles
// render.tessellation would make.
#include <cstdint>
#include <string>

#include "framebuffer/framebuffer.hpp"
#include "framebuffer/profile.hpp"
#include "scene/scene_loader.hpp"
#include "scene/scene_section_readers.hpp"
#include "scene/tessellation.hpp"

namespace mpr {
namespace {

// darkness_levels (1994's second soft-shadow method) sums its levels in the
// accumulation buffer (glAccum LOAD, ACCUM 1/S, RETURN inside each view),
// so it cannot also sum whole images there (antialiasing, depth of field,
// frosted glass, glossy mirrors): one accumulation buffer. And every
// sample's volume is counted above SHAD_ZERO at once: a point in all S
// volumes of one caster holds SHAD_ZERO + S, at most the stencil's maximum.
void checkDarknessLevels(const SceneNodeReader& in, const YAML::Node& doc, const Scene& s, const HardwareProfile& p) {
  const YAML::Node at = doc["render"]["soft_shadow_method"] ? doc["render"]["soft_shadow_method"] : doc;
  const int samples = s.render.softShadowSamples;
  bool areaLight = false;
  for (const PointLight& l : s.lights) areaLight = areaLight || l.radius > 0.0f;
  if (!areaLight || samples <= 1) return;  // hard shadows: no levels
  const int above = static_cast<int>(p.stencilMax() - (p.stencilMax() + 1) / 4 * 3);
  if (samples > above)
    in.fail(at, "render.soft_shadow_method darkness_levels counts all " + std::to_string(samples) +
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
    in.fail(at, "render.soft_shadow_method darkness_levels sums its levels in the accumulation buffer, which " + other +
                    " needs for its images: one accumulation buffer holds one sum (use the images method, or "
                    "render.frosted: false / antialias_samples: 1)");
}

}  // namespace

void readRenderSettings(const SceneNodeReader& in, const YAML::Node& n, RenderSettings& r) {
  in.checkKeys(n, scene_format::kRenderKeys, "render");
  if (n["width"]) r.width = in.integer(n["width"], "render.width", 1, Framebuffer::kMaxSide);
  if (n["height"]) r.height = in.integer(n["height"], "render.height", 1, Framebuffer::kMaxSide);
  if (n["recursion_depth"]) r.recursionDepth = in.integer(n["recursion_depth"], "render.recursion_depth", 0, 1 << 20);
  if (n["shadow_recursion_depth"])
    r.shadowRecursionDepth = in.integer(n["shadow_recursion_depth"], "render.shadow_recursion_depth", 0, 1 << 20);
  if (n["light_bounces"]) r.lightBounces = in.integer(n["light_bounces"], "render.light_bounces", 1, 16);
  if (n["soft_shadow_samples"]) r.softShadowSamples = in.integer(n["soft_shadow_samples"], "render.soft_shadow_samples", 1, 1024);
  if (n["antialias_samples"]) r.antialiasSamples = in.integer(n["antialias_samples"], "render.antialias_samples", 1, 1024);
  if (n["soft_shadow_method"]) {
    const std::string m = in.string(n["soft_shadow_method"], "render.soft_shadow_method");
    if (m == "darkness_levels") r.softShadowMethod = SoftShadowMethod::DarknessLevels;
    else if (m == "pivot") r.softShadowMethod = SoftShadowMethod::Pivot;
    else if (m != "images")
      in.fail(n["soft_shadow_method"], "unknown soft_shadow_method '" + m + "' (known: images, darkness_levels, pivot)");
  }
  if (n["shadows"]) r.shadows = in.boolean(n["shadows"], "render.shadows");
  if (n["reflections"]) r.reflections = in.boolean(n["reflections"], "render.reflections");
  if (n["refractions"]) r.refractions = in.boolean(n["refractions"], "render.refractions");
  if (n["translucency"]) r.translucency = in.boolean(n["translucency"], "render.translucency");
  if (n["frosted"]) r.frosted = in.boolean(n["frosted"], "render.frosted");
  if (n["profile"]) {
    r.profile = in.string(n["profile"], "render.profile");
    if (!findProfile(r.profile)) in.fail(n["profile"], "unknown profile '" + r.profile + "' (known: indigo, mesa)");
  }
  if (n["tessellation"]) {
    if (n["tessellation"].IsScalar() && n["tessellation"].Scalar() == "auto") r.tessellation = kAutoTessellation;
    else r.tessellation = static_cast<float>(in.number(n["tessellation"], "render.tessellation", 0.0, 1e6));
  }
  if (n["refraction_map"]) {
    const std::string m = in.string(n["refraction_map"], "render.refraction_map");
    if (m == "projection") r.refractionMap = RefractionMap::ProjectionKeptZ;
    else if (m == "projection_zeroed_z") r.refractionMap = RefractionMap::ProjectionZeroedZ;
    else if (m == "end_of_pipeline") r.refractionMap = RefractionMap::EndOfPipeline;
    else
      in.fail(n["refraction_map"], "unknown refraction_map '" + m +
                                       "' (known: projection, projection_zeroed_z, end_of_pipeline)");
  }
}

void checkRenderLimits(const SceneNodeReader& in, const YAML::Node& doc, const Scene& s) {
  // render.tessellation splits lit faces at render time: the scene it
  // makes is held to the same budget as the one the file describes.
  if (s.render.tessellation != 0.0f) {
    const std::uint64_t n = tessellatedTriangleCount(s, s.render.tessellation);
    const YAML::Node key = doc["render"] && doc["render"]["tessellation"] ? doc["render"]["tessellation"] : doc;
    if (n > kMaxSceneTriangles)
      in.fail(key, "render.tessellation " + (key == doc ? std::string("auto") : key.Scalar()) +
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
    in.fail(at, "render.recursion_depth " + std::to_string(s.render.recursionDepth) + " needs more stencil levels than the " +
                    std::to_string(p.stencilBits) + "-bit stencil of profile '" + p.name + "' holds: recursion levels lie below SHAD_MIN = " +
                    std::to_string(shadMin) + ", so the deepest is " + std::to_string(maxDepth));
  }
  if (s.render.softShadowMethod == SoftShadowMethod::DarknessLevels) checkDarknessLevels(in, doc, s, p);
}

}  // namespace mpr
