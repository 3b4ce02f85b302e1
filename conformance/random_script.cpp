#include "conformance/random_script.hpp"

#include <random>
#include <sstream>
#include <vector>

namespace mpr {
namespace {

class Generator {
 public:
  Generator(std::uint64_t seed, int w, int h) : rng_(seed), w_(w), h_(h) {}

  int uniform(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  template <typename T>
  const T& pick(const std::vector<T>& v) { return v[static_cast<size_t>(uniform(0, static_cast<int>(v.size()) - 1))]; }
  // A coordinate on the 1/4-pixel grid, a little beyond the window: exactly
  // representable with 8 sub-pixel bits, and often exactly on pixel centres.
  std::string coord(int extent) {
    const int q = uniform(-8, extent * 4 + 8);
    std::ostringstream o;
    o << q / 4.0;
    return o.str();
  }
  // Colour channels as k/255, so the conversion to bytes is unambiguous.
  std::string channel() {
    std::ostringstream o;
    o << uniform(0, 255);
    return o.str();
  }
  std::string depthCoord() {
    // Object z in [-1, 1] on a 1/64 grid (glOrtho near -1, far 1).
    std::ostringstream o;
    o << uniform(-64, 64) / 64.0;
    return o.str();
  }

  std::string run(int steps) {
    std::ostringstream s;
    s << "# random conformance script\n@framebuffer " << w_ << " " << h_ << "\n@profile mesa\n"
      << "glDisable GL_DITHER\nglMatrixMode GL_PROJECTION\nglOrtho 0 " << w_ << " 0 " << h_ << " -1 1\n"
      << "glMatrixMode GL_MODELVIEW\n";
    const std::vector<std::string>& funcs = compareFunctionNames();
    const std::vector<std::string>& ops = stencilOperationNames();
    const std::vector<std::string>& factors = blendFactorNames();
    const std::vector<std::string> masks = {"0xFF", "0x0F", "0xF0", "0x01", "0x80", "0x7F", "0x00", "0x3C"};
    const std::vector<std::string> bools = {"GL_TRUE", "GL_FALSE"};
    for (int i = 0; i < steps; ++i) {
      switch (uniform(0, 11)) {
        case 0:
          s << "glStencilFunc " << pick(funcs) << " " << uniform(0, 300) - 20 << " " << pick(masks) << "\n";
          break;
        case 1:
          s << "glStencilOp " << pick(ops) << " " << pick(ops) << " " << pick(ops) << "\n";
          break;
        case 2:
          s << "glStencilMask " << pick(masks) << "\n";
          break;
        case 3:
          s << (uniform(0, 1) ? "glEnable" : "glDisable") << " "
            << pick(std::vector<std::string>{"GL_STENCIL_TEST", "GL_DEPTH_TEST", "GL_BLEND", "GL_ALPHA_TEST",
                                              "GL_SCISSOR_TEST", "GL_CULL_FACE"})
            << "\n";
          break;
        case 4:
          s << "glDepthFunc " << pick(funcs) << "\n";
          if (uniform(0, 2) == 0) s << "glDepthMask " << pick(bools) << "\n";
          break;
        case 5:
          s << "glBlendFunc " << pick(factors) << " " << pick(factors) << "\n";
          break;
        case 6:
          s << "glScissor " << uniform(-4, w_) << " " << uniform(-4, h_) << " " << uniform(0, w_) << " "
            << uniform(0, h_) << "\n";
          break;
        case 7: {
          s << "glClearStencil " << uniform(0, 255) << "\nglClearDepth " << uniform(0, 64) / 64.0 << "\n"
            << "glClearColor " << uniform(0, 255) / 255.0 << " 0.5 " << uniform(0, 4) / 4.0 << " "
            << uniform(0, 255) / 255.0 << "\n";
          const std::vector<std::string> bits = {"GL_COLOR_BUFFER_BIT", "GL_DEPTH_BUFFER_BIT", "GL_STENCIL_BUFFER_BIT",
                                                 "GL_COLOR_BUFFER_BIT|GL_DEPTH_BUFFER_BIT|GL_STENCIL_BUFFER_BIT"};
          s << "glClear " << pick(bits) << "\n";
          break;
        }
        case 8:
          s << "glColorMask " << pick(bools) << " " << pick(bools) << " " << pick(bools) << " " << pick(bools) << "\n";
          if (uniform(0, 2) == 0) s << "glColorMask GL_TRUE GL_TRUE GL_TRUE GL_TRUE\n";
          break;
        case 9:
          s << "glAlphaFunc " << pick(funcs) << " " << uniform(0, 4) / 4.0 << "\n";
          break;
        case 10:
          s << "glCullFace " << pick(std::vector<std::string>{"GL_FRONT", "GL_BACK"}) << "\nglFrontFace "
            << pick(std::vector<std::string>{"GL_CW", "GL_CCW"}) << "\n";
          break;
        default: {
          // Geometry, flat coloured so colours stay exact bytes.
          s << "glColor4ub " << channel() << " " << channel() << " " << channel() << " " << channel() << "\n";
          if (uniform(0, 3) == 0) {
            s << "glRectf " << coord(w_) << " " << coord(h_) << " " << coord(w_) << " " << coord(h_) << "\n";
          } else {
            const int n = uniform(1, 3);
            s << "glBegin GL_TRIANGLES\n";
            const std::string z = depthCoord();
            for (int t = 0; t < 3 * n; ++t) s << "glVertex3f " << coord(w_) << " " << coord(h_) << " " << z << "\n";
            s << "glEnd\n";
          }
          break;
        }
      }
    }
    return s.str();
  }

 private:
  std::mt19937_64 rng_;
  int w_, h_;
};

}  // namespace

const std::vector<std::string>& compareFunctionNames() {
  static const std::vector<std::string> f = {"GL_NEVER", "GL_LESS", "GL_EQUAL", "GL_LEQUAL",
                                             "GL_GREATER", "GL_NOTEQUAL", "GL_GEQUAL", "GL_ALWAYS"};
  return f;
}

const std::vector<std::string>& stencilOperationNames() {
  static const std::vector<std::string> o = {"GL_KEEP", "GL_ZERO", "GL_REPLACE", "GL_INCR",
                                             "GL_DECR", "GL_INVERT", "GL_INCR_WRAP", "GL_DECR_WRAP"};
  return o;
}

const std::vector<std::string>& blendFactorNames() {
  static const std::vector<std::string> b = {"GL_ZERO", "GL_ONE", "GL_SRC_COLOR", "GL_ONE_MINUS_SRC_COLOR",
                                             "GL_DST_COLOR", "GL_ONE_MINUS_DST_COLOR", "GL_SRC_ALPHA",
                                             "GL_ONE_MINUS_SRC_ALPHA", "GL_DST_ALPHA", "GL_ONE_MINUS_DST_ALPHA"};
  return b;
}

std::string randomConformanceScript(std::uint64_t seed, int width, int height, int steps) {
  return Generator(seed, width, height).run(steps);
}

}  // namespace mpr
