#pragma once
// The inverse Mesa 22.3 keeps beside each matrix (math/m_matrix.c): the
// matrix is classified (from its entries, analyse_from_scratch, or from the
// flags its calls added, analyse_from_flags) and inverted by the routine of
// its class, in single precision. User clip planes go through it twice
// (glClipPlane by the modelview's inverse, then into clip space by the
// projection's), so llvmpipe's clipper cuts where these inverses say.
#include "util/vecmath.hpp"

namespace mpr {

namespace mesa_matrix {
// m_matrix.h's geometry flags and dirty bits.
enum : unsigned {
  kGeneral = 1u << 0, kRotation = 1u << 1, kTranslation = 1u << 2, kUniformScale = 1u << 3,
  kGeneralScale = 1u << 4, kGeneral3d = 1u << 5, kPerspective = 1u << 6, kSingular = 1u << 7,
  kDirtyType = 1u << 8, kDirtyFlags = 1u << 9, kDirtyInverse = 1u << 10,
  kGeometry = 0xFFu, kDirty = kDirtyType | kDirtyFlags | kDirtyInverse,
};
}  // namespace mesa_matrix

// m_matrix.h's matrix classes.
enum class MatrixClass { General, Identity, NoRotation3d, Perspective, TwoD, NoRotation2d, ThreeD };

// What Mesa keeps beside a matrix (GLmatrix): its flags, class and inverse.
// The calls that change the matrix add geometry flags and dirty bits
// (_math_matrix_translate adds MAT_FLAG_TRANSLATION, glLoadMatrix makes it
// general and wholly dirty, glLoadIdentity clears only the dirty bits);
// mesaAnalyse classifies it when Mesa does, from the entries when the flags
// are dirty and from the flags otherwise, and inverts it by its class. So
// the inverse depends on the calls that made the matrix, not on its entries
// alone (tests/conformance/repro/matrix_flags_after_load_identity.gls).
struct MesaMatrixState {
  unsigned flags = 0;  // _math_matrix_ctr: identity, no flags
  MatrixClass type = MatrixClass::Identity;
  Mat4 inverse{1.0f};
};

// _math_matrix_analyse.
void mesaAnalyse(const Mat4& m, MesaMatrixState& state);


// _mesa_transform_vector: the row vector v times m, each sum left to right.
Vec4 mesaTransformRowVector(const Vec4& v, const Mat4& m);

// m p as Mesa sums it, ((m0 x + m1 y) + m2 z) + m3 w over m's columns:
// TRANSFORM_POINT on the CPU, and the fixed-function program's MUL and
// unfused MADs on llvmpipe (glm would add the two halves pairwise).
inline Vec4 mesaTransformPoint(const Mat4& m, const Vec4& p) {
  return ((m[0] * p.x + m[1] * p.y) + m[2] * p.z) + m[3] * p.w;
}

}  // namespace mpr
