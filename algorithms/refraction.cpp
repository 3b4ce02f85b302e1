#include "algorithms/refraction.hpp"

#include <algorithm>
#include <cmath>

#include "algorithms/quad_to_quad.hpp"
#include "scene/slab_refraction.hpp"

namespace mpr {
namespace {

// gluPerspective * gluLookAt of the scene camera, in double.
DMat4 cameraMatrix(const Camera& c, double aspect) {
  const DMat4 proj = glm::perspective(glm::radians(static_cast<double>(c.fovY)), aspect, static_cast<double>(c.near),
                                      static_cast<double>(c.far));
  const DMat4 view = glm::lookAt(DVec3(c.position), DVec3(c.lookAt), DVec3(c.up));
  return proj * view;
}

// Rotation about `axis` (unit) by `angle` about the point `p`, inverted: the
// world transform of a camera turned by that rotation about p.
DMat4 turnAbout(DVec3 p, DVec3 axis, double angle) {
  const DMat4 toP = glm::translate(DMat4(1.0), p), fromP = glm::translate(DMat4(1.0), -p);
  return toP * glm::rotate(DMat4(1.0), -angle, axis) * fromP;
}

// In-out refraction through a slab (scene/slab_refraction.hpp): air on
// both sides, so no critical angle; the view axis's ray where it meets the
// plane (else the ray to the centre) is shifted sideways by the slab, and
// the camera with it: the view through the face is the outer view moved by
// that shift, not turned, and needs no image map (every ray of a slab leaves
// parallel to itself; one shift, that of one incidence, for the whole face,
// as the 1994 rule takes one angle).
RefractedView slabView(const ViewCamera& outer, const Camera&, const RefFace& face, int faceIndex, double ior,
                       DVec3 eye, DVec3 axis, DVec3 n) {
  RefractedView r;
  DVec3 d = glm::normalize(face.centre - eye);
  if (glm::dot(axis, n) < 0.0) {
    const double t = (face.offset - glm::dot(face.normal, eye)) / glm::dot(face.normal, axis);
    if (t > 0.0 && std::isfinite(t)) d = axis;
  }
  const double cosI = std::min(1.0, -glm::dot(d, n));
  r.incidence = std::acos(cosI);
  r.refracted = std::asin(std::min(1.0, std::sin(r.incidence) / ior));
  const DVec3 shift = slabShift(d, n, ior, face.thickness);
  ViewCamera v = outer;
  v.level = outer.level + 1;
  v.throughFace = faceIndex;
  v.near = 0.0;  // the camera's: a mirror's bound (mirrorNear) does not hold once the view is bent or shifted
  v.clip = true;
  v.clipPlane = DVec4(-n, glm::dot(n, face.centre));  // keep what lies beyond the face
  // The camera moved by the shift: the world moved by minus it.
  v.world = outer.world * glm::translate(DMat4(1.0), -shift);
  r.view = v;
  return r;
}

}  // namespace

std::optional<DVec2> screenOf(const ViewCamera& view, const Camera& camera, double aspect, DVec3 p) {
  const DVec4 clip = cameraMatrix(camera, aspect) * view.world * DVec4(p, 1.0);
  if (!(clip.w > 0.0)) return std::nullopt;
  DVec2 ndc(clip.x / clip.w, clip.y / clip.w);
  if (view.mapped) ndc = applyProjectiveMap(view.imageMap, ndc);
  return ndc;
}

std::optional<RefractedView> refractedView(const ViewCamera& outer, const Camera& camera, const RefFace& face,
                                           int faceIndex, double ior, double aspect) {
  RefractedView r;
  const DMat4 back = glm::inverse(outer.world);
  const DVec3 eye = outer.eye(camera);
  const DVec3 axis = glm::normalize(DVec3(back * DVec4(glm::normalize(DVec3(camera.lookAt) - DVec3(camera.position)), 0.0)));
  // The normal on the eye's side, and the ratio n_eye / n_other.
  const bool eyeInFront = face.side(eye) > 0.0;
  const DVec3 n = eyeInFront ? face.normal : -face.normal;
  if (face.thickness > 0.0) return slabView(outer, camera, face, faceIndex, ior, eye, axis, n);
  const double eta = eyeInFront ? 1.0 / ior : ior;

  // The face centre decides against the critical angle. Only eta > 1 has
  // one: at eta = 1 (ior 1) the ray goes straight on, yet within about 1e-8
  // rad of grazing cos^2 vanishes beside 1, sin rounds to 1 and 1 * 1 >= 1
  // would make a plain transparent face a mirror (refraction_hard_cases_test).
  const DVec3 toCentre = glm::normalize(face.centre - eye);
  const double cosC = std::min(1.0, std::fabs(glm::dot(toCentre, n)));
  const double sinC = std::sqrt(std::max(0.0, 1.0 - cosC * cosC));
  if (eta > 1.0 && eta * sinC >= 1.0) {
    r.totalReflection = true;
    return r;
  }
  // Snell's law at the view axis's incidence, where it meets the plane.
  DVec3 d = toCentre, at = face.centre;
  const double along = glm::dot(axis, n);
  if (along < 0.0) {
    const double t = (face.offset - glm::dot(face.normal, eye)) / glm::dot(face.normal, axis);
    const double cosA = -along, sinA = std::sqrt(std::max(0.0, 1.0 - cosA * cosA));
    if (t > 0.0 && std::isfinite(t) && eta * sinA < 1.0) d = axis, at = eye + axis * t;
  }
  const double c1 = std::min(1.0, -glm::dot(d, n));
  const double s1 = std::sqrt(std::max(0.0, 1.0 - c1 * c1));
  const double s2 = eta * s1;
  r.incidence = std::asin(std::min(1.0, s1));
  r.refracted = std::asin(std::min(1.0, s2));

  ViewCamera v = outer;
  v.level = outer.level + 1;
  v.throughFace = faceIndex;
  v.near = 0.0;  // the camera's: a mirror's bound (mirrorNear) does not hold once the view is bent or shifted
  v.clip = true;
  v.clipPlane = DVec4(-n, glm::dot(n, face.centre));  // keep what lies beyond the face
  if (ior != 1.0) {
    // Turn the camera about the incidence point by theta_i - theta_t, in the
    // plane of incidence, so that its axis becomes the refracted ray.
    const DVec3 rotAxis = glm::cross(d, -n);
    if (glm::length(rotAxis) > 1e-12) {
      // Bending toward the normal (eta < 1) turns d toward -n.
      v.world = outer.world * turnAbout(at, glm::normalize(rotAxis), r.incidence - r.refracted);
    }
    // M3: the refracted camera's image of the face onto where the outer view shows it.
    if (face.polygon.size() < 4) return std::nullopt;
    const std::size_t k = face.polygon.size();
    Quad from, to;
    for (int i = 0; i < 4; ++i) {
      const DVec3 corner(face.polygon[static_cast<std::size_t>(i) * k / 4]);
      ViewCamera raw = v;
      raw.mapped = false;
      const auto a = screenOf(raw, camera, aspect, corner), b = screenOf(outer, camera, aspect, corner);
      if (!a || !b) return std::nullopt;
      from[static_cast<std::size_t>(i)] = *a;
      to[static_cast<std::size_t>(i)] = *b;
    }
    try {
      // A projective map is defined up to a factor; take the one whose w is 1
      // at the centre of the screen, so that depth (divided by that w when
      // the map is loaded with Z kept) stays close to the camera's own.
      v.imageMap = quadToQuad(from, to);
      const double i = v.imageMap[2][2];
      if (!(std::fabs(i) > 0.0)) return std::nullopt;
      v.imageMap /= i;
      v.mapped = true;
      // The map's denominator over the face's image in this camera (affine,
      // so least at a corner): view_camera.hpp, depthScale.
      for (const DVec2& c : from) {
        const double den = v.imageMap[2][0] * c.x + v.imageMap[2][1] * c.y + v.imageMap[2][2];
        if (!(den > 0.0)) return std::nullopt;
        v.depthScale = std::min(v.depthScale, den);
      }
    } catch (const DegenerateQuadError&) {
      return std::nullopt;
    }
  }
  r.view = v;
  return r;
}

}  // namespace mpr
