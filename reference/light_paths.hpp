#pragma once
// Direct light at a surface point, exactly: straight from each light, and
// through every chain of planar specular faces (the paths the 1994 paper's
// virtual lights and light volumes approximate, ref_light.cpp).
//
// - Shadow rays are blocked by any triangle of any object, either side:
//   physical truth, where the pipeline counts only objects that cast shadow
//   volumes. A mirror is opaque; a refracting face lets no straight light
//   through: its light arrives bent, along its own path.
// - An area light (radius > 0) is a sphere; it is sampled on the disc through
//   its centre facing the point (the sphere's silhouette seen from afar), by
//   max(16, samples per pixel) stratified points a pixel (sampler.hpp), each
//   carrying colour / points.
// - A chain is a list of faces from the light to the point, at most 8 (or
//   `bounces`) long, while the product of their weights (reflectance or
//   transmittance) stays at least 1/512. Mirrors unfold: the light's mirror
//   image L' (L'' = image of L' ...) is reached in a straight line from the
//   point across the faces. At most one refracting face a chain: its
//   crossing solves Snell's law between the unfolded light and the unfolded
//   point (snell.hpp). A frosted face scatters what it passes on as it
//   scatters the view through it: the crossing is solved for the point moved
//   along the face by shear times its distance behind it times a normal
//   pair, one per light point and pixel sample (1997 §3's stochastic shear).
// - Attenuation is GL's, by the unfolded path length (the sum of the legs).
//   The spreading of the bent rays (a caustic's Jacobian: L^2 dOmega/dA,
//   by finite differences of the Snell crossing) multiplies it in the
//   physical model only; the pipeline's virtual light has none.
#include <cstdint>
#include <vector>

#include "reference/bvh.hpp"
#include "reference/reference_renderer.hpp"
#include "reference/sampler.hpp"
#include "reference/specular_face.hpp"

namespace mpr {

struct FaceChain {
  std::vector<int> faces;  // faces[0] nearest the light, back() nearest the point
  int refracting = -1;     // index into faces of its refracting face, or -1
  double weight = 1.0;     // product of the faces' weights
};

struct LightPaths {
  std::vector<SpecularFace> faces;
  std::vector<std::vector<FaceChain>> chains;  // per light
};

// The chains of each light that pass a point-independent test (each mirror
// lit from its front, each face reaching the next one's lit side).
// bounces < 0: the 1/512 rule, at most 8 faces.
LightPaths findLightPaths(const Scene& scene, int bounces);

struct ShadingPoint {
  DVec3 position, normal, toViewer;  // unit normal and view direction
  const SceneMaterial* material = nullptr;
};

// Where the area-light points of this sample come from.
struct LightSampling {
  const PixelSampler* sampler = nullptr;
  std::uint32_t sample = 0, perSample = 1, depth = 0;
};

// The sum over lights and chains of lightTerm (shading.hpp); counts shadow rays.
DVec3 directLight(const Scene& scene, const Bvh& bvh, const LightPaths& paths, const ShadingPoint& at,
                  ShadingModel model, const LightSampling& sampling, std::uint64_t& shadowRays);

// Whether the segment a -> b is blocked, its ends excluded.
bool blocked(const Bvh& bvh, DVec3 a, DVec3 b, std::uint64_t& shadowRays);

}  // namespace mpr
