#pragma once
// Vector and matrix types of the pipeline: GLM's float types, column-major
// like GL. Float, not double, because GL implementations (and Mesa, our
// reference) keep matrices and vertex arithmetic in single precision.
#include <glm/glm.hpp>

namespace mpr {

using Vec3 = glm::vec3;
using Vec4 = glm::vec4;
using Mat4 = glm::mat4;
using DMat3 = glm::dmat3;
using DMat4 = glm::dmat4;
using DVec2 = glm::dvec2;
using DVec3 = glm::dvec3;
using DVec4 = glm::dvec4;

}  // namespace mpr
