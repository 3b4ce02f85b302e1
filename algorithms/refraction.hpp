#pragma once
// The virtual refracted camera of the 1994 paper ("Refractions"): one
// incident angle for the whole face, chosen by the paper's two-angle rule,
// and the projective image mapping M3 that puts the refracted image where the
// face is on the screen (eqs. 1-3, the Appendix's quad-to-quad map).
#include <optional>

#include "algorithms/ref_face.hpp"
#include "algorithms/view_camera.hpp"
#include "scene/scene.hpp"

namespace mpr {

struct RefractedView {
  bool totalReflection = false;  // past the critical angle: the face is a mirror
  ViewCamera view;               // the refracted camera (when not totalReflection)
  double incidence = 0.0;        // radians, the angle Snell's law was applied to
  double refracted = 0.0;        // radians
};

// `outer` is the view the face is seen in; `ior` the material's index of
// refraction (relative to the side the eye is not on: an eye in front of the
// face looks from air into the material). Rule (1994): the ray from the eye to
// the face centre decides against the critical angle; below it, Snell's law is
// applied at the incidence of the view axis where it meets the face's plane
// (the centre's when the axis misses the plane or exceeds the critical angle).
// The refracted camera turns about that point. Returns nothing when the face's
// image cannot be mapped (a corner behind either camera, a degenerate quad).
std::optional<RefractedView> refractedView(const ViewCamera& outer, const Camera& camera, const RefFace& face,
                                           int faceIndex, double ior, double aspect);

// Normalised device coordinates of `p` as `view` draws it (its image map included).
std::optional<DVec2> screenOf(const ViewCamera& view, const Camera& camera, double aspect, DVec3 p);

}  // namespace mpr
