#include "reference/ray_tracer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "reference/shading.hpp"
#include "reference/path_limits.hpp"
#include "reference/snell.hpp"
#include "scene/slab_refraction.hpp"

namespace mpr {
namespace {

// With bounces < 0 the specular recursion stops where its weight falls below
// 1/512, or after this many faces (two facing mirrors of reflectance 0.92
// need 75 to get there; the pipeline's recursion_depth stops far earlier).
constexpr int kMaxSpecularDepth = 100;

DVec3 reflectAbout(DVec3 d, DVec3 n) { return d - 2.0 * glm::dot(d, n) * n; }

// The shading normal: the vertex normals interpolated by the barycentrics
// (the pipeline's Gouraud shading interpolates colours instead), the
// geometric normal where they cancel.
DVec3 shadingNormal(const Scene& s, const BvhTriangle& tri, const Hit& h) {
  const Mesh& m = s.objects[tri.object].mesh;
  const auto& t = m.triangles[tri.triangle];
  const DVec3 n = (1.0 - h.b1 - h.b2) * DVec3(m.normals[t[0]]) + h.b1 * DVec3(m.normals[t[1]]) + h.b2 * DVec3(m.normals[t[2]]);
  const double len = glm::length(n);
  return len > 0.0 ? n / len : glm::normalize(glm::cross(tri.e1, tri.e2));
}

}  // namespace

Traced trace(const TraceContext& c, const Ray& ray, double tMin, double tMax, int depth, double weight,
             const PixelSampler& sampler, std::uint32_t sample, RayCounts& counts) {
  // Back faces are skipped as the pipeline culls them (a one-sided quad seen
  // from behind is invisible: the default scene's front wall relies on it).
  const Hit h = c.bvh.closest(ray, tMin, tMax, Facing::FrontOnly);
  if (!h.found()) return {DVec3(0.0), std::numeric_limits<double>::infinity()};  // the clear colour
  const BvhTriangle& tri = c.bvh.triangles()[h.id];
  const SceneMaterial& m = c.scene.materials[static_cast<std::size_t>(c.scene.objects[tri.object].material)];
  const DVec3 p = ray.origin + h.t * ray.direction;
  const DVec3 n = shadingNormal(c.scene, tri, h);
  const ShadingPoint at{p, n, -ray.direction, &m};
  const LightSampling sampling{&sampler, sample, c.lightPointsPerSample, static_cast<std::uint32_t>(depth)};
  const DVec3 local =
      unlitTerm(m, DVec3(c.scene.ambient)) + directLight(c.scene, c.bvh, c.lights, at, c.model, sampling, counts.shadow);
  if (m.kind == MaterialKind::Diffuse) return {local, h.t};

  // A specular face: its lit colour and what it passes on, blended as the
  // pipeline's finishFace does: lit * (1 - t) + through * t (1994 paper,
  // "Object attributes and translucency").
  const double t = m.kind == MaterialKind::Mirror ? m.reflectance : m.transmittance;
  const bool deeper = c.bounces < 0 ? (depth < kMaxSpecularDepth && weight * t >= kMinPathWeight) : depth < c.bounces;
  if (!deeper || !(t > 0.0)) return {local * (1.0 - t), h.t};
  DVec3 through(0.0);
  const auto follow = [&](DVec3 dir, DVec3 from) {
    ++counts.specular;
    return trace(c, Ray{from, dir}, kSurfaceEpsilon, std::numeric_limits<double>::infinity(), depth + 1, weight * t, sampler,
                 sample, counts);
  };
  if (m.kind == MaterialKind::Mirror) {
    DVec3 dir = reflectAbout(ray.direction, n);
    if (m.roughness > 0.0f) {
      // A glossy mirror (1997 Fig. 4): microfacet normals tilted by slope
      // alpha tilt the reflected ray by twice that; a Gaussian of standard
      // deviation 2 alpha in slope along the face's tangents, one tilt per
      // pixel sample (the model the pipeline's sheared mirror views draw).
      const DVec2 g = sampler.gaussian(sample, static_cast<std::uint32_t>(depth));
      const DVec3 u = perpendicular(n), v = glm::cross(n, u);
      dir = glm::normalize(dir + 2.0 * static_cast<double>(m.roughness) * glm::dot(dir, n) * (g.x * u + g.y * v));
    }
    through = follow(dir, p).colour;
  } else {
    // The change of medium (1994): from the front, air into the material.
    const bool front = h.frontFacing;
    const double eta = front ? 1.0 / m.ior : m.ior;
    const DVec3 normal = front ? n : -n;
    // A slab (a thickness, in-out refraction): the ray goes on in its own
    // direction from the face shifted sideways (scene/slab_refraction.hpp).
    const bool slab = m.thickness > 0.0f;
    std::optional<DVec3> refracted = slab ? std::optional<DVec3>(ray.direction) : refractDirection(ray.direction, normal, eta);
    const DVec3 from = slab ? p + slabShift(ray.direction, normal, m.ior, m.thickness) : p;
    if (m.kind == MaterialKind::Frosted && refracted) {
      // Rough transmission, the model the pipeline's stochastic shear (1997
      // §3) draws: the refracted direction tilted by a Gaussian of standard
      // deviation `shear` in slope along the face's tangents (a point z
      // behind the face moves by shear * z sideways), one tilt per pixel
      // sample; the pixel's average is the frosted image.
      const DVec2 g = sampler.gaussian(sample, static_cast<std::uint32_t>(depth));
      const DVec3 u = perpendicular(normal), v = glm::cross(normal, u);
      const double along = -glm::dot(*refracted, normal);  // > 0: into the face
      refracted = glm::normalize(*refracted + static_cast<double>(m.shear) * along * (g.x * u + g.y * v));
    }
    // Past the critical angle the face reflects it all (weight t still).
    const Traced behind = refracted ? follow(*refracted, from) : follow(reflectAbout(ray.direction, normal), p);
    through = behind.colour;
    if ((m.kind == MaterialKind::Translucent || m.kind == MaterialKind::Frosted) && refracted) {
      // The 1994 fog: toward the material's colour with the distance behind
      // the face, full at fog_distance (nothing hit: full fog).
      const double f = std::clamp(1.0 - behind.distance / static_cast<double>(m.fogDistance), 0.0, 1.0);
      through = f * through + (1.0 - f) * DVec3(m.diffuse);
    }
  }
  return {local * (1.0 - t) + through * t, h.t};
}

}  // namespace mpr
