#pragma once
// The inverse Mesa 22.3 keeps beside each matrix (math/m_matrix.c): the
// matrix is classified (analyse_from_scratch) and inverted by the routine of
// its class, in single precision. User clip planes go through it twice
// (glClipPlane by the modelview's inverse, then into clip space by the
// projection's), so llvmpipe's clipper cuts where these inverses say.
#include "util/vecmath.hpp"

namespace mpr {

// Mesa's inverse of m; the identity where Mesa finds m singular.
Mat4 mesaInverse(const Mat4& m);

// _mesa_transform_vector: the row vector v times m, each sum left to right.
Vec4 mesaTransformRowVector(const Vec4& v, const Mat4& m);

}  // namespace mpr
