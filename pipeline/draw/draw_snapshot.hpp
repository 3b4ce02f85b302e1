#pragma once
// What a draw reads of the GL state, frozen when the GL context hands a draw
// on (each piece of a glBegin/glEnd block that Mesa's vbo draws, and the
// GL_QUADS draw it closes at a flush): the draw stage (draw_stage.hpp) sees
// the GL state through this struct only, so it can be driven, and tested,
// without a GL context. Filled by GLContext::drawSnapshot; a test fills one
// by hand.
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "framebuffer/fragment_ops.hpp"
#include "framebuffer/fragment_pipeline.hpp"
#include "framebuffer/framebuffer.hpp"
#include "raster/clip_vertex.hpp"
#include "raster/fog.hpp"
#include "raster/llvmpipe_depth.hpp"
#include "util/vecmath.hpp"

namespace mpr {

// A fragment event for observers (the pass stepper's pixel history).
struct FragmentEvent {
  int x, y;
  std::uint8_t stencilBefore, stencilAfter;
  std::uint32_t depthBefore, depthIncoming;
  FragmentFate fate;
  Rgba8 colorAfter;
};
using FragmentObserver = std::function<void(const FragmentEvent&)>;

// glCullFace's faces.
enum class CullFace : std::uint8_t { Front, Back, FrontAndBack };

struct DrawSnapshot {
  // --- per-fragment operations --------------------------------------------
  FragmentState frag;
  FragmentPipeline pipeline{};  // chooseFragmentPipeline(frag): chosen once per draw
  // Set: every fragment is shown to it, and the draw runs on the calling
  // thread as it comes (never queued for the row threads). Not owned.
  const FragmentObserver* observer = nullptr;

  // --- facing and culling (GL 1.1 section 2.13.1, 3.5.1) ---------------------
  bool cullEnabled = false;
  CullFace cullFace = CullFace::Back;
  bool frontFaceCcw = true;      // glFrontFace(GL_CCW)
  bool twoSidedColors = false;   // lighting on with GL_LIGHT_MODEL_TWO_SIDE: a back face takes the back colours

  // --- shading -----------------------------------------------------------------
  bool flatShading = false;
  // Every fragment of the draw takes one colour as it is: flat shading, or
  // (unlit, with no colour in the vbo's vertex format) Mesa's current colour
  // read as a uniform by its fixed-function fragment program
  // (ff_fragment_shader.cpp get_gl_Color; current_colour_exact.gls). Every
  // vertex of such a draw holds that colour.
  bool uniformColor = false;
  FogState fog;

  // --- window ------------------------------------------------------------------
  WindowTransform window{};    // the viewport and depth range; fbHeight the framebuffer's
  PixelRect drawRegion;        // viewport ∩ scissor box ∩ framebuffer: where fragments may land
  // llvmpipe's draw region for a triangle whose fixed-point steps wrap
  // (lp_setup.c draw_regions): the framebuffer within the scissor box, not
  // the viewport.
  PixelRect scissoredFramebuffer;
  // The end-of-pipeline map (GLContext::setWindowMap): a 3x3 projective map
  // of normalised device x, y applied before the viewport.
  std::optional<glm::mat3> windowMap;

  // --- clipping ------------------------------------------------------------------
  // In clip coordinates: the view volume's six (the window map's four sides
  // in place of x and y with a map), then the enabled user planes.
  std::vector<ClipPlane> clipPlanes;
  std::vector<ClipPlane> userPlanes;  // clipPlanes after the first six: what Mesa's draw module masks with

  static constexpr std::size_t kViewVolumePlanes = 6;
};

// Whether `s`'s pipeline is the one chosen for its fragment state (the
// invariant a snapshot keeps; for MPR_DCHECK).
inline bool pipelineMatches(const DrawSnapshot& s) {
  const FragmentPipeline chosen = chooseFragmentPipeline(s.frag);
  return chosen.fragment == s.pipeline.fragment && chosen.span == s.pipeline.span &&
         chosen.stencilRejectsAll == s.pipeline.stencilRejectsAll;
}

}  // namespace mpr
