#include "reference/shading.hpp"

#include <algorithm>
#include <cmath>

namespace mpr {
namespace {

constexpr double kPi = 3.14159265358979323846;

DVec3 wide(Vec3 v) { return DVec3(v); }

// Ward's specular lobe as a fraction of the irradiance (1997 eq. 5, the
// isotropic case of eq. 3), with cos(theta_i) = N.L already multiplied in.
double wardSpecular(double alpha, double nDotL, double nDotV, double nDotH) {
  if (!(nDotV > 0.0) || !(nDotH > 0.0)) return 0.0;
  const double cos2 = nDotH * nDotH;
  const double tan2 = (1.0 - cos2) / cos2;
  return nDotL * std::exp(-tan2 / (alpha * alpha)) / (4.0 * kPi * alpha * alpha * std::sqrt(nDotL * nDotV));
}

}  // namespace

double glAttenuation(const PointLight& light, double d) {
  const DVec3 k(light.attenuation);
  return 1.0 / (k.x + k.y * d + k.z * d * d);
}

DVec3 unlitTerm(const SceneMaterial& m, DVec3 sceneAmbient) { return wide(m.emission) + wide(m.diffuse) * sceneAmbient; }

DVec3 lightTerm(const SceneMaterial& m, ShadingModel model, DVec3 n, DVec3 toViewer, DVec3 toLight, DVec3 colour) {
  const double nDotL = glm::dot(n, toLight);
  if (!(nDotL > 0.0)) return DVec3(0.0);
  DVec3 c = nDotL * wide(m.diffuse);
  const DVec3 sum = toLight + toViewer;
  const double len = glm::length(sum);
  const DVec3 h = len > 0.0 ? sum / len : sum;  // opposite L and V: N.H = 0, as GL's normalise of 0
  const double nDotH = glm::dot(n, h);
  if (model == ShadingModel::Physical && m.roughness > 0.0f) {
    c += wardSpecular(m.roughness, nDotL, glm::dot(n, toViewer), nDotH) * wide(m.wardSpecular);
  } else if (nDotH > 0.0 && m.specular != Vec3(0.0f)) {
    // GL's 0^0 = 1 (shininess 0) is pow's as well.
    c += std::pow(nDotH, static_cast<double>(m.shininess)) * wide(m.specular);
  }
  return c * colour;
}

}  // namespace mpr
