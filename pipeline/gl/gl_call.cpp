#include "pipeline/gl/gl_call.hpp"

#include <GL/gl.h>

namespace mpr {

int glVectorCount(GLCall call, std::uint32_t pname) {
  switch (call) {
    case GLCall::Lightfv:
      switch (pname) {
        case GL_AMBIENT: case GL_DIFFUSE: case GL_SPECULAR: case GL_POSITION: return 4;
        case GL_SPOT_DIRECTION: return 3;
        case GL_SPOT_EXPONENT: case GL_SPOT_CUTOFF: case GL_CONSTANT_ATTENUATION:
        case GL_LINEAR_ATTENUATION: case GL_QUADRATIC_ATTENUATION: return 1;
      }
      return 0;
    case GLCall::Materialfv:
      switch (pname) {
        case GL_AMBIENT: case GL_DIFFUSE: case GL_SPECULAR: case GL_EMISSION: case GL_AMBIENT_AND_DIFFUSE: return 4;
        case GL_COLOR_INDEXES: return 3;
        case GL_SHININESS: return 1;
      }
      return 0;
    case GLCall::Fogfv:
      switch (pname) {
        case GL_FOG_COLOR: return 4;
        case GL_FOG_MODE: case GL_FOG_DENSITY: case GL_FOG_START: case GL_FOG_END: case GL_FOG_INDEX: return 1;
      }
      return 0;
    case GLCall::LightModelfv:
      switch (pname) {
        case GL_LIGHT_MODEL_AMBIENT: return 4;
        case GL_LIGHT_MODEL_LOCAL_VIEWER: case GL_LIGHT_MODEL_TWO_SIDE: return 1;
      }
      return 0;
    default: return 0;
  }
}

}  // namespace mpr
