#pragma once
// Fog (GL 1.1 section 3.9): the blend factor f from the fog coordinate c, the
// eye-space distance |z_eye| (Mesa's default fog distance mode), and its
// application to a colour. f is clamped to [0, 1].
#include "util/vecmath.hpp"

namespace mpr {

enum class FogMode { Linear, Exp, Exp2 };

struct FogState {
  bool enabled = false;
  FogMode mode = FogMode::Exp;
  float density = 1.0f;
  float start = 0.0f;
  float end = 1.0f;
  Vec4 color{0.0f, 0.0f, 0.0f, 0.0f};
  bool perFragment = true;  // GL_FOG_HINT: GL_NICEST / GL_DONT_CARE per fragment, GL_FASTEST per vertex
};

// f(c): LINEAR (end - c) / (end - start) (as Mesa evaluates it, see
// fog.cpp), EXP e^(-density c), EXP2 e^(-(density c)^2), clamped to
// [0, 1]. LINEAR with end == start, which GL leaves open, is Mesa's
// c - end.
float fogFactor(const FogState& fog, float c);

// C' = f C + (1 - f) C_fog on RGB; alpha is unchanged.
Vec4 applyFog(const FogState& fog, float f, const Vec4& color);

}  // namespace mpr
