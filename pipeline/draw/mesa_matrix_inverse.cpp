#include "pipeline/draw/mesa_matrix_inverse.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>

namespace mpr {
namespace {

using Floats = std::array<float, 16>;  // Mesa's column-major m[16]

using namespace mesa_matrix;

float& at(Floats& m, int row, int col) { return m[static_cast<std::size_t>(col * 4 + row)]; }
float at(const Floats& m, int row, int col) { return m[static_cast<std::size_t>(col * 4 + row)]; }
float sq(float x) { return x * x; }

Floats identity() {
  Floats m{};
  m[0] = m[5] = m[10] = m[15] = 1.0f;
  return m;
}

// analyse_from_scratch: the class and flags from the entries alone.
std::pair<MatrixClass, unsigned> analyse(const Floats& m) {
  auto zero = [](int i) { return 1u << i; };
  auto one = [](int i) { return 1u << (i + 16); };
  std::uint32_t mask = 0;
  for (int i = 0; i < 16; ++i)
    if (m[static_cast<std::size_t>(i)] == 0.0f) mask |= zero(i);
  if (m[0] == 1.0f) mask |= one(0);
  if (m[5] == 1.0f) mask |= one(5);
  if (m[10] == 1.0f) mask |= one(10);
  if (m[15] == 1.0f) mask |= one(15);
  const std::uint32_t noTranslation = zero(12) | zero(13) | zero(14);
  const std::uint32_t no2dScale = one(0) | one(5);
  const std::uint32_t identityMask = one(0) | zero(4) | zero(8) | zero(12) | zero(1) | one(5) | zero(9) | zero(13) |
                                     zero(2) | zero(6) | one(10) | zero(14) | zero(3) | zero(7) | zero(11) | one(15);
  const std::uint32_t noRotation2d = zero(4) | zero(8) | zero(1) | zero(9) | zero(2) | zero(6) | one(10) | zero(14) |
                                     zero(3) | zero(7) | zero(11) | one(15);
  const std::uint32_t twoD = zero(8) | zero(9) | zero(2) | zero(6) | one(10) | zero(14) | zero(3) | zero(7) |
                             zero(11) | one(15);
  const std::uint32_t noRotation3d = zero(4) | zero(8) | zero(1) | zero(9) | zero(2) | zero(6) | zero(3) | zero(7) |
                                     zero(11) | one(15);
  const std::uint32_t threeD = zero(3) | zero(7) | zero(11) | one(15);
  const std::uint32_t perspective = zero(4) | zero(12) | zero(1) | zero(13) | zero(2) | zero(6) | zero(3) | zero(7) |
                                    zero(15);
  unsigned flags = (mask & noTranslation) != noTranslation ? kTranslation : 0u;
  const float e = sq(1e-6f);
  if (mask == identityMask) return {MatrixClass::Identity, flags};
  if ((mask & noRotation2d) == noRotation2d) {
    if ((mask & no2dScale) != no2dScale) flags |= kGeneralScale;
    return {MatrixClass::NoRotation2d, flags};
  }
  if ((mask & twoD) == twoD) {
    const float mm = m[0] * m[0] + m[1] * m[1], m4m4 = m[4] * m[4] + m[5] * m[5], mm4 = m[0] * m[4] + m[1] * m[5];
    if (sq(mm - 1) > e || sq(m4m4 - 1) > e) flags |= kGeneralScale;
    flags |= sq(mm4) > e ? kGeneral3d : kRotation;
    return {MatrixClass::TwoD, flags};
  }
  if ((mask & noRotation3d) == noRotation3d) {
    if (sq(m[0] - m[5]) < e && sq(m[0] - m[10]) < e) {
      if (sq(m[0] - 1.0f) > e) flags |= kUniformScale;
    } else {
      flags |= kGeneralScale;
    }
    return {MatrixClass::NoRotation3d, flags};
  }
  if ((mask & threeD) == threeD) {
    auto dot3 = [&](int a, int b) {
      const auto i = static_cast<std::size_t>(a), j = static_cast<std::size_t>(b);
      return m[i] * m[j] + m[i + 1] * m[j + 1] + m[i + 2] * m[j + 2];
    };
    const float c1 = dot3(0, 0), c2 = dot3(4, 4), c3 = dot3(8, 8), d1 = dot3(0, 4);
    if (sq(c1 - c2) < e && sq(c1 - c3) < e) {
      if (sq(c1 - 1.0f) > e) flags |= kUniformScale;
    } else {
      flags |= kGeneralScale;
    }
    if (sq(d1) < e) {
      // CROSS3(cp, m, m + 4), minus the third column.
      const float cp0 = m[1] * m[6] - m[2] * m[5] - m[8];
      const float cp1 = m[2] * m[4] - m[0] * m[6] - m[9];
      const float cp2 = m[0] * m[5] - m[1] * m[4] - m[10];
      flags |= cp0 * cp0 + cp1 * cp1 + cp2 * cp2 < e ? kRotation : kGeneral3d;
    } else {
      flags |= kGeneral3d;
    }
    return {MatrixClass::ThreeD, flags};
  }
  if ((mask & perspective) == perspective && m[11] == -1.0f) return {MatrixClass::Perspective, flags | kGeneral};
  return {MatrixClass::General, flags | kGeneral};
}

// util_invert_mat4x4 (u_math.c): Gauss-Jordan elimination with partial
// pivoting on the rows [m | I], in Mesa's operation order.
bool invertGeneral(const Floats& m, Floats& out) {
  std::array<std::array<float, 8>, 4> w{};
  std::array<std::array<float, 8>*, 4> r = {&w[0], &w[1], &w[2], &w[3]};
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) w[i][j] = at(m, i, j);
    w[i][4 + i] = 1.0f;
  }
  auto pivot = [&](int column, int from) {
    for (int i = 3; i > from; --i)
      if (std::fabs((*r[i])[column]) > std::fabs((*r[i - 1])[column])) std::swap(r[i], r[i - 1]);
    return (*r[from])[column] != 0.0f;
  };
  // Eliminate variables 0, 1 and 2 below the diagonal; a zero entry of the
  // pivot row's right half is skipped, as Mesa skips it.
  for (int k = 0; k < 3; ++k) {
    if (!pivot(k, k)) return false;
    std::array<float, 4> mult{};
    for (int i = k + 1; i < 4; ++i) mult[i] = (*r[i])[k] / (*r[k])[k];
    for (int j = k + 1; j < 8; ++j) {
      const float s = (*r[k])[j];
      if (j >= 4 && k < 2 && s == 0.0f) continue;
      for (int i = k + 1; i < 4; ++i) (*r[i])[j] -= mult[i] * s;
    }
  }
  if ((*r[3])[3] == 0.0f) return false;
  // Back substitution, row 3 then 2, 1, 0.
  float s = 1.0f / (*r[3])[3];
  for (int j = 4; j < 8; ++j) (*r[3])[j] *= s;
  for (int row = 2; row >= 0; --row) {
    const float m2 = (*r[row])[row + 1];
    s = 1.0f / (*r[row])[row];
    for (int j = 4; j < 8; ++j) (*r[row])[j] = s * ((*r[row])[j] - (*r[row + 1])[j] * m2);
    for (int above = row - 1; above >= 0; --above) {
      const float ma = (*r[above])[row + 1];
      for (int j = 4; j < 8; ++j) (*r[above])[j] -= (*r[row + 1])[j] * ma;
    }
  }
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) at(out, i, j) = (*r[i])[4 + j];
  return true;
}

void translationPart(const Floats& in, Floats& out) {
  for (int i = 0; i < 3; ++i)
    at(out, i, 3) = -(at(in, 0, 3) * at(out, i, 0) + at(in, 1, 3) * at(out, i, 1) + at(in, 2, 3) * at(out, i, 2));
}

// invert_matrix_3d_general: the upper 3x3 by cofactors over a determinant
// summed positive and negative terms apart.
bool invert3dGeneral(const Floats& in, Floats& out) {
  float pos = 0.0f, neg = 0.0f;
  auto add = [&](float t) { (t >= 0.0f ? pos : neg) += t; };
  add(at(in, 0, 0) * at(in, 1, 1) * at(in, 2, 2));
  add(at(in, 1, 0) * at(in, 2, 1) * at(in, 0, 2));
  add(at(in, 2, 0) * at(in, 0, 1) * at(in, 1, 2));
  add(-at(in, 2, 0) * at(in, 1, 1) * at(in, 0, 2));
  add(-at(in, 1, 0) * at(in, 0, 1) * at(in, 2, 2));
  add(-at(in, 0, 0) * at(in, 2, 1) * at(in, 1, 2));
  float det = pos + neg;
  if (std::fabs(det) < 1e-25f) return false;
  det = 1.0f / det;
  at(out, 0, 0) = (at(in, 1, 1) * at(in, 2, 2) - at(in, 2, 1) * at(in, 1, 2)) * det;
  at(out, 0, 1) = -(at(in, 0, 1) * at(in, 2, 2) - at(in, 2, 1) * at(in, 0, 2)) * det;
  at(out, 0, 2) = (at(in, 0, 1) * at(in, 1, 2) - at(in, 1, 1) * at(in, 0, 2)) * det;
  at(out, 1, 0) = -(at(in, 1, 0) * at(in, 2, 2) - at(in, 2, 0) * at(in, 1, 2)) * det;
  at(out, 1, 1) = (at(in, 0, 0) * at(in, 2, 2) - at(in, 2, 0) * at(in, 0, 2)) * det;
  at(out, 1, 2) = -(at(in, 0, 0) * at(in, 1, 2) - at(in, 1, 0) * at(in, 0, 2)) * det;
  at(out, 2, 0) = (at(in, 1, 0) * at(in, 2, 1) - at(in, 2, 0) * at(in, 1, 1)) * det;
  at(out, 2, 1) = -(at(in, 0, 0) * at(in, 2, 1) - at(in, 2, 0) * at(in, 0, 1)) * det;
  at(out, 2, 2) = (at(in, 0, 0) * at(in, 1, 1) - at(in, 1, 0) * at(in, 0, 1)) * det;
  translationPart(in, out);
  return true;
}

// invert_matrix_3d: transposed (and scaled) when angle preserving.
bool invert3d(const Floats& in, Floats& out, unsigned flags) {
  if ((flags & ~(kRotation | kTranslation | kUniformScale)) != 0) return invert3dGeneral(in, out);
  if (flags & kUniformScale) {
    float scale = at(in, 0, 0) * at(in, 0, 0) + at(in, 0, 1) * at(in, 0, 1) + at(in, 0, 2) * at(in, 0, 2);
    if (scale == 0.0f) return false;
    scale = 1.0f / scale;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) at(out, j, i) = scale * at(in, i, j);
  } else if (flags & kRotation) {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) at(out, j, i) = at(in, i, j);
  } else {
    out = identity();
    for (int i = 0; i < 3; ++i) at(out, i, 3) = -at(in, i, 3);
    return true;
  }
  if (flags & kTranslation) translationPart(in, out);
  else at(out, 0, 3) = at(out, 1, 3) = at(out, 2, 3) = 0.0f;
  return true;
}

// analyse_from_flags: the class from the geometry flags the calls since the
// last analysis added (TEST_MAT_FLAGS), and a few entries.
MatrixClass classFromFlags(const Floats& m, unsigned flags) {
  auto only = [flags](unsigned allowed) { return (kGeometry & ~allowed & flags) == 0; };
  if (only(0)) return MatrixClass::Identity;
  if (only(kTranslation | kUniformScale | kGeneralScale))
    return m[10] == 1.0f && m[14] == 0.0f ? MatrixClass::NoRotation2d : MatrixClass::NoRotation3d;
  if (only(kRotation | kTranslation | kUniformScale | kGeneralScale | kGeneral3d))
    return m[8] == 0.0f && m[9] == 0.0f && m[2] == 0.0f && m[6] == 0.0f && m[10] == 1.0f && m[14] == 0.0f
               ? MatrixClass::TwoD
               : MatrixClass::ThreeD;
  if (m[4] == 0.0f && m[12] == 0.0f && m[1] == 0.0f && m[13] == 0.0f && m[2] == 0.0f && m[6] == 0.0f &&
      m[3] == 0.0f && m[7] == 0.0f && m[11] == -1.0f && m[15] == 0.0f)
    return MatrixClass::Perspective;
  return MatrixClass::General;
}

bool invertNoRotation(const Floats& in, Floats& out, unsigned flags, int dims) {
  for (int i = 0; i < dims; ++i)
    if (at(in, i, i) == 0.0f) return false;
  out = identity();
  for (int i = 0; i < dims; ++i) at(out, i, i) = 1.0f / at(in, i, i);
  if (flags & kTranslation)
    for (int i = 0; i < dims; ++i) at(out, i, 3) = -(at(in, i, 3) * at(out, i, i));
  return true;
}

Floats floatsOf(const Mat4& matrix) {
  Floats m{};
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) at(m, r, c) = matrix[c][r];
  return m;
}

// matrix_invert: the routine of the class (inv_mat_tab: the perspective
// class by the general routine, 2D by the 3D one); false where singular.
// `out` holds the inverse computed before, and the 3D routines write only
// the upper 3x4: its bottom row stays whatever an earlier inversion of this
// matrix (a perspective one, say) left there (matrix_inverse_stale_row.gls).
bool invertByClass(const Floats& m, MatrixClass kind, unsigned flags, Floats& out) {
  switch (kind) {
    case MatrixClass::Identity: out = identity(); return true;
    case MatrixClass::General:
    case MatrixClass::Perspective: return invertGeneral(m, out);
    case MatrixClass::TwoD:
    case MatrixClass::ThreeD: return invert3d(m, out, flags);
    case MatrixClass::NoRotation3d: return invertNoRotation(m, out, flags, 3);
    case MatrixClass::NoRotation2d: return invertNoRotation(m, out, flags, 2);
  }
  return false;
}

Mat4 matrixOf(const Floats& out) {
  Mat4 result;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) result[c][r] = at(out, r, c);
  return result;
}

}  // namespace

void mesaAnalyse(const Mat4& matrix, MesaMatrixState& state) {
  if (!(state.flags & kDirty)) return;  // nothing changed since the last analysis
  const Floats m = floatsOf(matrix);
  if (state.flags & kDirtyType) {
    if (state.flags & kDirtyFlags) {
      const auto [kind, flags] = analyse(m);
      state.type = kind;
      state.flags = (state.flags & ~kGeometry) | flags;
    } else {
      state.type = classFromFlags(m, state.flags);
    }
  }
  if (state.flags & kDirtyInverse) {
    Floats out = floatsOf(state.inverse);  // mat->inv, written over in part
    if (invertByClass(m, state.type, state.flags & kGeometry, out)) {  // TEST_MAT_FLAGS: geometry bits only
      state.flags &= ~kSingular;
    } else {
      state.flags |= kSingular;  // matrix_invert: MAT_FLAG_SINGULAR, the identity
      out = identity();
    }
    state.inverse = matrixOf(out);
  }
  state.flags &= ~(kDirtyType | kDirtyFlags | kDirtyInverse);
}

Vec4 mesaTransformRowVector(const Vec4& v, const Mat4& m) {
  Vec4 u;
  for (int j = 0; j < 4; ++j) u[j] = v.x * m[j][0] + v.y * m[j][1] + v.z * m[j][2] + v.w * m[j][3];
  return u;
}

}  // namespace mpr
