#pragma once
// The local model at a surface point: what one light adds there, and the
// part that needs no light (emission and the scene ambient).
#include "util/vecmath.hpp"
#include "reference/reference_renderer.hpp"
#include "scene/scene.hpp"

namespace mpr {

// GL's attenuation 1 / (kc + kl d + kq d^2) (GL 1.1 §2.13.1).
double glAttenuation(const PointLight& light, double distance);

// Emission + material ambient * scene ambient; the pipeline sets the
// material's ambient to its diffuse colour (draw_window.cpp, setMaterial).
DVec3 unlitTerm(const SceneMaterial& m, DVec3 sceneAmbient);

// What one light adds at a point with unit normal `n`, unit `toViewer` and
// unit `toLight`, the light's colour already scaled by its attenuation (and
// any path weights). GL sets the light's GL_DIFFUSE and GL_SPECULAR both to
// its colour, so one colour serves both terms.
//
// Pipeline: GL 1.1 §2.13's sum term, diffuse * max(0, N.L) + specular *
// max(0, N.H)^shininess, the specular only where N.L > 0, H the Blinn half
// vector of L and V. GL's V is the infinite viewer (eye-space (0, 0, 1),
// GL_LIGHT_MODEL_LOCAL_VIEWER false); the reference takes the true direction
// to the viewer (-ray direction) instead: one of the approximations the
// accuracy measure reports.
//
// Physical: where the material gives a Ward roughness alpha, the specular is
// Ward's isotropic Gaussian (1997 eq. 5) times the irradiance,
//   rho_s cos(theta_i) exp(-tan^2(delta) / alpha^2) / (4 pi alpha^2 sqrt(cos theta_i cos theta_r)),
// delta the angle between N and H; elsewhere the same as Pipeline.
DVec3 lightTerm(const SceneMaterial& m, ShadingModel model, DVec3 n, DVec3 toViewer, DVec3 toLight, DVec3 lightColour);

}  // namespace mpr
