#pragma once
// make_all_shadows of the 1994 paper's Figure 4: the shadow volumes of every
// casting object for one light, counted in the stencil about SHAD_ZERO
// (in-out principle, Heidmann). Front faces in front of the visible surface
// increment, back faces decrement (z-pass); where the eye (or the near
// plane) is inside a volume z-pass fails, and that volume is counted
// behind the surface instead (z-fail, with its caps). Only pixels holding a
// shadow value (>= SHAD_MIN) are counted, so the recursion levels below
// SHAD_MIN are never touched.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/gl_command_stream.hpp"
#include "algorithms/render_plan.hpp"
#include "algorithms/shadow_volume.hpp"
#include "algorithms/stencil_levels.hpp"
#include "algorithms/view_camera.hpp"
#include "scene/scene.hpp"

namespace mpr {

// One object's shadow volume for one light, world space: sides and caps as
// triangles, counter-clockwise seen from outside the volume.
struct VolumeGeometry {
  ShadowVolume volume;
  std::vector<std::array<Vec3, 3>> sides, caps;
  bool closed = true;
  // Counted by z-fail with caps in every view: the caster is not drawn (a
  // mirror image), so nothing hides the light cap as z-pass assumes.
  bool alwaysZFail = false;
  std::string object;
  int objectIndex = -1;  // in scene.objects, for a face that must not count its own volume
};

// Counts `volumes` into the stencil as seen by `view`, only on pixels holding a
// shadow value: z-pass, or z-fail with caps where the near rectangle is in or
// across a volume. `inverted` swaps increment and decrement (light volumes,
// whose inside must end one below the outside); `alwaysZFail` counts every
// volume behind the surface with its caps (light volumes: their near cap is a
// mirror, which is not in the depth buffer). `volumeByVolume` draws each
// volume's increments and decrements before the next volume's (for many
// volumes at once: the darkness levels). Returns the z-fail count.
std::uint64_t countVolumes(GLApi& gl, const std::vector<const VolumeGeometry*>& volumes,
                           const ViewCamera& view, const Camera& camera, double aspect, const StencilLevels& levels,
                           bool inverted, bool alwaysZFail = false, bool volumeByVolume = false);

// What an object does in draw_all_shadows (make_all_shadows(ALWAYS)): a
// caster (casts_shadows, not specular); a specular face (a mirror, a
// refracting face), whose light goes on only through its light volume
// (draw_ref_shadows), so it shadows the direct light like any caster ("the
// second pass ... captures the shadow effect caused by the refractive
// surface itself", 1994 "Refractive shadows"; a mirror is opaque: what lies
// behind it gets none of the light it reflects); or nothing (casts_shadows
// false). A specular face is not in the depth buffer where its shadows are
// counted (the view through it is) and has two sides.
enum class ShadowRole { None, Caster, SpecularFace };
ShadowRole shadowRole(const SceneObject& object, const Scene& scene);

// The volume of `object` in its role (not None) from `light`: a specular
// face's two-sided and counted by z-fail. Shared by draw_all_shadows and
// the virtual lights' casters (ref_light.cpp).
VolumeGeometry casterShadowVolume(const SceneObject& object, ShadowRole role, Vec3 light,
                                  const BoundingSphere& receivers);

class ShadowPass {
 public:
  ShadowPass(const Scene& scene, const RenderPlan& plan);
  // The pivot method (1997 §4.4, Fig. 7; shadow_pivot.hpp). With
  // `pivotBase` the volumes of lights with a radius are built to be pivoted
  // (far nodes pushed out for jitters up to the radius): build this once,
  // from the lights' centres. The second form takes an image's scene (its
  // lights at their samples) and such a base: every volume is the base's
  // with its far nodes pivoted by the light's jitter, nothing rebuilt.
  ShadowPass(const Scene& scene, const RenderPlan& plan, bool pivotBase);
  ShadowPass(const Scene& sampled, const ShadowPass& base);

  // Draws light `light`'s volumes as seen by `view` (GL state: the view is set
  // up by the caller), all but object `exclude`'s. Returns how many volumes
  // needed z-fail.
  std::uint64_t drawVolumes(GLApi& gl, int light, const ViewCamera& view, const Camera& camera,
                            const StencilLevels& levels, int exclude = -1);
  const std::vector<std::string>& warnings() const { return warnings_; }
  const std::vector<VolumeGeometry>& volumes(int light) const { return volumes_[static_cast<std::size_t>(light)]; }

 private:
  const Scene& scene_;
  std::vector<std::vector<VolumeGeometry>> volumes_;  // per light
  std::vector<Vec3> lightsAt_;                         // where each light's volumes were built from
  std::vector<std::string> warnings_;
};

}  // namespace mpr
