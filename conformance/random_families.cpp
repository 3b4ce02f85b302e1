// The random script families of `mpr conform --random N --family NAME`
// (docs/explanation/mesa.md): arbitrary float coordinates, perspective and
// orthographic views, and per family one part of the pipeline stressed.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "conformance/random_script.hpp"

namespace mpr {
namespace {

// What a script step does; each family draws its steps from a weighted list.
enum class Step {
  Projection, Modelview, MatrixChain, LoadMatrix, MultMatrix, PushPop, Viewport, DepthRange,
  FragmentState, Stencil, Blend, CullShade, Clear, Snapshot, Geometry,
  Light, LightModel, Material, ColorMaterial, Normalize,
  Fog, ClipPlane, Accum, Toggle,
  // fragment_ops: every value of the per-fragment state, scissor and masks.
  Scissor, WriteMasks, StencilAny, BlendAny, AlphaAny, DepthAny, ClearAny,
};

struct Weighted {
  Step step;
  int weight;
};

class FamilyGenerator {
 public:
  FamilyGenerator(std::uint64_t seed, int w, int h) : rng_(seed), w_(w), h_(h) {}

  int uniform(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
  // A uniform double in [lo, hi), from the generator's bits alone (no
  // library-specific real distribution), so the scripts are the same everywhere.
  double real(double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(rng_() >> 11) * 0x1p-53;
  }
  bool chance(int percent) { return uniform(0, 99) < percent; }
  template <typename T>
  const T& pick(const std::vector<T>& v) { return v[static_cast<size_t>(uniform(0, static_cast<int>(v.size()) - 1))]; }

  // An arbitrary float, written with 6 significant digits.
  static std::string num(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.6g", v);
    std::string s = b;
    return s == "-0" ? "0" : s;
  }
  std::string nums(std::initializer_list<double> v) {
    std::string s;
    for (double x : v) {
      if (!s.empty()) s += ' ';
      s += num(x);
    }
    return s;
  }
  std::string colour4() { return nums({real(0, 1), real(0, 1), real(0, 1), real(0, 1)}); }

  // lit, fogged: the percentage of scripts that start with lighting (fog) on.
  std::string run(const std::vector<Weighted>& steps, int count, int litPercent, int fogPercent, bool accum) {
    const bool lit = chance(litPercent), fogged = chance(fogPercent);
    threeComponents_ = chance(25);
    lit_ = litPercent > 0;
    s_ << "# random conformance script\n@framebuffer " << w_ << " " << h_ << "\n@profile mesa\n"
       << "glDisable GL_DITHER\n";
    if (accum) s_ << "glClearAccum " << nums({real(-0.5, 1), real(-0.5, 1), real(-0.5, 1), real(0, 1)}) << "\n";
    s_ << "glClearColor " << colour4() << "\nglClear GL_COLOR_BUFFER_BIT|GL_DEPTH_BUFFER_BIT|GL_STENCIL_BUFFER_BIT"
       << (accum ? "|GL_ACCUM_BUFFER_BIT" : "") << "\n";
    projection();
    modelview();
    s_ << "glEnable GL_DEPTH_TEST\n";
    if (lit_) {
      s_ << (lit ? "glEnable" : "glDisable") << " GL_LIGHTING\n";
      light(0);
      s_ << "glEnable GL_LIGHT0\n";
    }
    if (fogged) {
      s_ << "glEnable GL_FOG\n";
      fog();
    }
    int total = 0;
    for (const Weighted& w : steps) total += w.weight;
    for (int i = 0; i < count; ++i) {
      int r = uniform(0, total - 1);
      for (const Weighted& w : steps) {
        if (r < w.weight) {
          step(w.step);
          break;
        }
        r -= w.weight;
      }
    }
    while (depth_[0] > 0) pop(0);
    while (depth_[1] > 0) pop(1);
    return s_.str();
  }

 private:
  void step(Step k) {
    switch (k) {
      case Step::Projection: projection(); break;
      case Step::Modelview: modelview(); break;
      case Step::MatrixChain: chain(); break;
      case Step::LoadMatrix: loadMatrix(); break;
      case Step::MultMatrix: multMatrix(); break;
      case Step::PushPop: pushPop(); break;
      case Step::Viewport:
        if (chance(40)) s_ << "glViewport 0 0 " << w_ << " " << h_ << "\n";
        else s_ << "glViewport " << uniform(-w_ / 2, w_ / 2) << " " << uniform(-h_ / 2, h_ / 2) << " "
                << uniform(w_ / 4, w_ * 3 / 2) << " " << uniform(h_ / 4, h_ * 3 / 2) << "\n";
        break;
      case Step::DepthRange:
        if (chance(30)) s_ << "glDepthRange 0 1\n";
        else s_ << "glDepthRange " << nums({real(0, 1), real(0, 1)}) << "\n";
        break;
      case Step::FragmentState:
        s_ << "glDepthFunc " << pick(std::vector<std::string>{"GL_LESS", "GL_LEQUAL", "GL_GREATER", "GL_ALWAYS",
                                                              "GL_NOTEQUAL", "GL_GEQUAL", "GL_LESS", "GL_LEQUAL"})
           << "\n";
        if (chance(25)) s_ << "glDepthMask " << (chance(70) ? "GL_TRUE" : "GL_FALSE") << "\n";
        if (chance(15)) s_ << (chance(50) ? "glEnable" : "glDisable") << " GL_DEPTH_TEST\n";
        if (chance(15)) s_ << (chance(50) ? "glEnable" : "glDisable") << " GL_ALPHA_TEST\nglAlphaFunc "
                           << pick(std::vector<std::string>{"GL_LESS", "GL_GEQUAL", "GL_GREATER"}) << " "
                           << num(real(0, 1)) << "\n";
        break;
      case Step::Stencil:
        s_ << (chance(80) ? "glEnable" : "glDisable") << " GL_STENCIL_TEST\nglStencilFunc "
           << pick(std::vector<std::string>{"GL_ALWAYS", "GL_EQUAL", "GL_NOTEQUAL", "GL_LESS", "GL_GEQUAL"}) << " "
           << uniform(0, 8) << " 0xFF\nglStencilOp "
           << pick(std::vector<std::string>{"GL_KEEP", "GL_INCR", "GL_INVERT"}) << " "
           << pick(std::vector<std::string>{"GL_KEEP", "GL_INCR", "GL_DECR", "GL_ZERO"}) << " "
           << pick(std::vector<std::string>{"GL_INCR", "GL_REPLACE", "GL_INCR_WRAP", "GL_DECR_WRAP", "GL_INVERT"})
           << "\n";
        break;
      case Step::Blend:
        if (chance(30)) {
          s_ << "glDisable GL_BLEND\n";
        } else {
          s_ << "glEnable GL_BLEND\nglBlendFunc "
             << pick(std::vector<std::string>{"GL_SRC_ALPHA", "GL_ONE", "GL_DST_COLOR", "GL_ZERO"}) << " "
             << pick(std::vector<std::string>{"GL_ONE_MINUS_SRC_ALPHA", "GL_ONE", "GL_ZERO", "GL_SRC_COLOR"}) << "\n";
        }
        break;
      case Step::CullShade:
        if (chance(50)) s_ << (chance(60) ? "glEnable" : "glDisable") << " GL_CULL_FACE\n";
        if (chance(50)) s_ << "glCullFace " << pick(std::vector<std::string>{"GL_FRONT", "GL_BACK", "GL_FRONT_AND_BACK"}) << "\n";
        if (chance(50)) s_ << "glFrontFace " << pick(std::vector<std::string>{"GL_CW", "GL_CCW"}) << "\n";
        if (chance(50)) s_ << "glShadeModel " << pick(std::vector<std::string>{"GL_FLAT", "GL_SMOOTH"}) << "\n";
        break;
      case Step::Clear: {
        if (chance(50)) s_ << "glClearColor " << colour4() << "\n";
        if (chance(50)) s_ << "glClearDepth " << num(real(0, 1)) << "\n";
        if (chance(30)) s_ << "glClearStencil " << uniform(0, 255) << "\n";
        s_ << "glClear " << pick(std::vector<std::string>{"GL_DEPTH_BUFFER_BIT", "GL_COLOR_BUFFER_BIT|GL_DEPTH_BUFFER_BIT",
                                                          "GL_STENCIL_BUFFER_BIT|GL_DEPTH_BUFFER_BIT"})
           << "\n";
        break;
      }
      case Step::Snapshot: s_ << "@snapshot s" << ++snapshots_ << "\n"; break;
      case Step::Geometry: geometry(); break;
      case Step::Light: {
        const int l = uniform(0, 7);
        light(l);
        s_ << (chance(85) ? "glEnable" : "glDisable") << " GL_LIGHT" << l << "\n";
        break;
      }
      case Step::LightModel:
        switch (uniform(0, 2)) {
          case 0: s_ << "glLightModelfv GL_LIGHT_MODEL_AMBIENT " << nums({real(0, 0.4), real(0, 0.4), real(0, 0.4), real(0, 1)}) << "\n"; break;
          case 1: s_ << "glLightModeli GL_LIGHT_MODEL_LOCAL_VIEWER " << uniform(0, 1) << "\n"; break;
          default: s_ << (chance(50) ? "glLightModeli" : "glLightModelf") << " GL_LIGHT_MODEL_TWO_SIDE " << uniform(0, 1) << "\n"; break;
        }
        break;
      case Step::Material: material(); break;
      case Step::ColorMaterial:
        if (chance(30)) {
          s_ << "glDisable GL_COLOR_MATERIAL\n";
        } else {
          s_ << "glColorMaterial " << pick(std::vector<std::string>{"GL_FRONT", "GL_BACK", "GL_FRONT_AND_BACK"}) << " "
             << pick(std::vector<std::string>{"GL_AMBIENT", "GL_DIFFUSE", "GL_SPECULAR", "GL_EMISSION",
                                              "GL_AMBIENT_AND_DIFFUSE"})
             << "\nglEnable GL_COLOR_MATERIAL\n";
        }
        break;
      case Step::Normalize: s_ << (chance(50) ? "glEnable" : "glDisable") << " GL_NORMALIZE\n"; break;
      case Step::Fog:
        if (chance(15)) s_ << (chance(70) ? "glEnable" : "glDisable") << " GL_FOG\n";
        fog();
        break;
      case Step::ClipPlane: clipPlane(); break;
      case Step::Accum: accum(); break;
      case Step::Toggle:
        s_ << (chance(60) ? "glEnable " : "glDisable ") << (chance(50) ? "GL_LIGHTING" : "GL_FOG") << "\n";
        break;
      case Step::Scissor:
        if (chance(25)) {
          s_ << "glDisable GL_SCISSOR_TEST\n";
        } else {
          s_ << "glEnable GL_SCISSOR_TEST\n";
          if (chance(20)) s_ << "glScissor 0 0 " << w_ << " " << h_ << "\n";  // the window: Mesa clears it unscissored
          else s_ << "glScissor " << uniform(-4, w_) << " " << uniform(-4, h_) << " " << uniform(0, w_ + 4) << " "
                  << uniform(0, h_ + 4) << "\n";
        }
        break;
      case Step::WriteMasks:
        s_ << "glColorMask";
        for (int i = 0; i < 4; ++i) s_ << (chance(70) ? " GL_TRUE" : " GL_FALSE");
        s_ << "\nglStencilMask " << pick(masks()) << "\n";
        if (chance(30)) s_ << "glDepthMask " << (chance(70) ? "GL_TRUE" : "GL_FALSE") << "\n";
        break;
      case Step::StencilAny:
        s_ << (chance(85) ? "glEnable" : "glDisable") << " GL_STENCIL_TEST\nglStencilFunc " << pick(compareFunctionNames()) << " "
           << uniform(-20, 300) << " " << pick(masks()) << "\nglStencilOp " << pick(stencilOperationNames()) << " "
           << pick(stencilOperationNames()) << " " << pick(stencilOperationNames()) << "\n";
        break;
      case Step::BlendAny: {
        // GL_SRC_ALPHA_SATURATE is a source factor only.
        static const std::vector<std::string> src = [] {
          std::vector<std::string> f = blendFactorNames();
          f.push_back("GL_SRC_ALPHA_SATURATE");
          return f;
        }();
        s_ << (chance(80) ? "glEnable" : "glDisable") << " GL_BLEND\nglBlendFunc " << pick(src) << " "
           << pick(blendFactorNames()) << "\n";
        break;
      }
      case Step::AlphaAny:
        s_ << (chance(75) ? "glEnable" : "glDisable") << " GL_ALPHA_TEST\nglAlphaFunc " << pick(compareFunctionNames()) << " "
           << num(real(-0.2, 1.2)) << "\n";
        break;
      case Step::DepthAny:
        s_ << (chance(85) ? "glEnable" : "glDisable") << " GL_DEPTH_TEST\nglDepthFunc " << pick(compareFunctionNames()) << "\n";
        break;
      case Step::ClearAny:
        if (chance(50)) s_ << "glClearColor " << nums({real(-0.2, 1.2), real(0, 1), real(0, 1), real(0, 1)}) << "\n";
        if (chance(60)) s_ << "glClearDepth " << num(real(0, 1)) << "\n";
        if (chance(50)) s_ << "glClearStencil " << uniform(0, 300) << "\n";
        if (chance(20)) s_ << "glClearAccum " << nums({real(-1, 1), real(-1, 1), real(-1, 1), real(-1, 1)}) << "\n";
        s_ << "glClear " << pick(std::vector<std::string>{
                                "GL_COLOR_BUFFER_BIT", "GL_DEPTH_BUFFER_BIT", "GL_STENCIL_BUFFER_BIT",
                                "GL_DEPTH_BUFFER_BIT|GL_STENCIL_BUFFER_BIT", "GL_ACCUM_BUFFER_BIT",
                                "GL_COLOR_BUFFER_BIT|GL_DEPTH_BUFFER_BIT|GL_STENCIL_BUFFER_BIT|GL_ACCUM_BUFFER_BIT"})
           << "\n";
        break;
    }
  }
  static const std::vector<std::string>& masks() {
    static const std::vector<std::string> m = {"0xFF", "0x0F", "0xF0", "0x01", "0x80", "0x7F", "0x00", "0x3C", "0xAA"};
    return m;
  }

  // The view: the objects live in [-2, 2]^3 about the origin, which the
  // modelview puts at a distance of 4 to 8 in front of the eye.
  void projection() {
    s_ << "glMatrixMode GL_PROJECTION\n";
    if (depth_[1] > 0 && chance(30)) pop(1);
    else if (depth_[1] < 2 && chance(20)) push(1);
    s_ << "glLoadIdentity\n";
    const double n = real(0.5, 3.5), f = real(8, 14);
    switch (uniform(0, 3)) {
      case 0: {
        const double a = real(1.5, 3.5), b = a * real(0.6, 1.2), dx = real(-0.5, 0.5), dy = real(-0.5, 0.5);
        s_ << "glOrtho " << nums({-a + dx, a + dx, -b + dy, b + dy, real(-2, 3), f}) << "\n";
        break;
      }
      case 1: {
        const double k = real(0.2, 0.6), dx = real(-0.15, 0.15), dy = real(-0.15, 0.15);
        s_ << "glFrustum " << nums({n * (-k + dx), n * (k + dx), n * (-k * 0.85 + dy), n * (k * 0.85 + dy), n, f}) << "\n";
        break;
      }
      default:
        s_ << "gluPerspective " << nums({real(25, 75), real(0.8, 1.6), n, f}) << "\n";
        break;
    }
    s_ << "glMatrixMode GL_MODELVIEW\n";
  }
  void modelview() {
    s_ << "glMatrixMode GL_MODELVIEW\nglLoadIdentity\n";
    if (chance(50)) {
      const double d = real(4, 8), th = real(0, 6.283), ph = real(-1.2, 1.2);
      s_ << "gluLookAt "
         << nums({d * std::cos(ph) * std::sin(th), d * std::sin(ph), d * std::cos(ph) * std::cos(th), real(-0.5, 0.5),
                  real(-0.5, 0.5), real(-0.5, 0.5), real(-0.3, 0.3), 1, real(-0.3, 0.3)})
         << "\n";
    } else {
      s_ << "glTranslatef " << nums({real(-0.5, 0.5), real(-0.5, 0.5), -real(4, 8)}) << "\n";
      if (chance(80)) rotate();
    }
  }
  void rotate() {
    s_ << (chance(80) ? "glRotatef " : "glRotated ")
       << nums({real(-180, 180), real(-1, 1), real(-1, 1), real(-1, 1)}) << "\n";
  }
  // A chain of transformations about the current modelview.
  void chain() {
    const int n = uniform(1, 4);
    for (int i = 0; i < n; ++i) {
      switch (uniform(0, 2)) {
        case 0: s_ << (chance(80) ? "glTranslatef " : "glTranslated ") << nums({real(-1, 1), real(-1, 1), real(-1, 1)}) << "\n"; break;
        case 1: rotate(); break;
        default: {
          const double sx = real(0.5, 1.6) * (chance(15) ? -1 : 1);
          s_ << (chance(80) ? "glScalef " : "glScaled ") << nums({sx, real(0.5, 1.6), real(0.5, 1.6)}) << "\n";
          break;
        }
      }
    }
  }
  // A rotation about a random axis, scaled, then moved into view, as 16
  // column-major numbers; a projective bottom row now and then.
  std::vector<double> affine(double dist, double scaleLo, double scaleHi) {
    double ax = real(-1, 1), ay = real(-1, 1), az = real(-1, 1);
    const double len = std::sqrt(ax * ax + ay * ay + az * az) + 1e-3;
    ax /= len, ay /= len, az /= len;
    const double t = real(-3.2, 3.2), c = std::cos(t), si = std::sin(t), k = 1 - c;
    const double sc = real(scaleLo, scaleHi);
    const double r[3][3] = {{c + ax * ax * k, ax * ay * k - az * si, ax * az * k + ay * si},
                            {ay * ax * k + az * si, c + ay * ay * k, ay * az * k - ax * si},
                            {az * ax * k - ay * si, az * ay * k + ax * si, c + az * az * k}};
    std::vector<double> m(16, 0.0);
    for (int col = 0; col < 3; ++col)
      for (int row = 0; row < 3; ++row) m[col * 4 + row] = r[row][col] * sc * (row == 0 && col == 0 ? real(0.7, 1.3) : 1);
    m[12] = real(-0.5, 0.5), m[13] = real(-0.5, 0.5), m[14] = -dist, m[15] = 1;
    return m;
  }
  void writeMatrix(const std::vector<double>& m) {
    for (std::size_t i = 0; i < m.size(); ++i) s_ << (i ? " " : "") << num(m[i]);
    s_ << "\n";
  }
  void loadMatrix() {
    s_ << "glMatrixMode GL_MODELVIEW\n" << (chance(50) ? "glLoadMatrixf " : "glLoadMatrixd ");
    writeMatrix(affine(real(4, 8), 0.6, 1.4));
  }
  void multMatrix() {
    std::vector<double> m = affine(0, 0.7, 1.3);
    m[12] = real(-0.7, 0.7), m[13] = real(-0.7, 0.7), m[14] = real(-0.7, 0.7);
    if (chance(10)) m[3] = real(-0.05, 0.05), m[7] = real(-0.05, 0.05);  // projective
    s_ << (chance(50) ? "glMultMatrixf " : "glMultMatrixd ");
    writeMatrix(m);
  }
  void push(int which) {
    s_ << "glPushMatrix\n";
    ++depth_[which];
  }
  void pop(int which) {
    s_ << (which ? "glMatrixMode GL_PROJECTION\n" : "glMatrixMode GL_MODELVIEW\n") << "glPopMatrix\n";
    --depth_[which];
    if (which) s_ << "glMatrixMode GL_MODELVIEW\n";
  }
  void pushPop() {
    if (depth_[0] > 0 && chance(45)) pop(0);
    else if (depth_[0] < 6) s_ << "glMatrixMode GL_MODELVIEW\n", push(0);
    else if (chance(30)) s_ << "glMatrixMode GL_MODELVIEW\nglLoadIdentity\nglPopMatrix\n", --depth_[0];
    if (depth_[0] == 0 && chance(5)) s_ << "glMatrixMode GL_MODELVIEW\nglPopMatrix\n";  // GL_STACK_UNDERFLOW
  }

  void light(int l) {
    const std::string L = "GL_LIGHT" + std::to_string(l);
    const int n = uniform(2, 6);
    for (int i = 0; i < n; ++i) {
      switch (uniform(0, 9)) {
        case 0: s_ << "glLightfv " << L << " GL_AMBIENT " << nums({real(0, 0.5), real(0, 0.5), real(0, 0.5), 1}) << "\n"; break;
        case 1: case 2: s_ << "glLightfv " << L << " GL_DIFFUSE " << colour4() << "\n"; break;
        case 3: s_ << "glLightfv " << L << " GL_SPECULAR " << colour4() << "\n"; break;
        case 4: case 5:
          s_ << "glLightfv " << L << " GL_POSITION "
             << nums({real(-6, 6), real(-6, 6), real(-6, 6), static_cast<double>(chance(60) ? 1 : 0)}) << "\n";
          break;
        case 6:
          s_ << "glLightfv " << L << " GL_SPOT_DIRECTION " << nums({real(-1, 1), real(-1, 1), real(-1, 1)}) << "\n";
          s_ << "glLightf " << L << " GL_SPOT_CUTOFF " << (chance(20) ? std::string("180") : num(real(5, 90))) << "\n";
          break;
        case 7: s_ << "glLightf " << L << " GL_SPOT_EXPONENT " << num(real(0, 64)) << "\n"; break;
        case 8:
          s_ << "glLightf " << L << " "
             << pick(std::vector<std::string>{"GL_CONSTANT_ATTENUATION", "GL_LINEAR_ATTENUATION", "GL_QUADRATIC_ATTENUATION"})
             << " " << num(real(0, 1.5)) << "\n";
          break;
        default: s_ << "glLightf " << L << " GL_CONSTANT_ATTENUATION " << num(real(0.5, 2)) << "\n"; break;
      }
    }
  }
  std::string face() { return pick(std::vector<std::string>{"GL_FRONT", "GL_BACK", "GL_FRONT_AND_BACK"}); }
  void material() {
    switch (uniform(0, 6)) {
      case 0: s_ << "glMaterialfv " << face() << " GL_AMBIENT " << colour4() << "\n"; break;
      case 1: s_ << "glMaterialfv " << face() << " GL_DIFFUSE " << colour4() << "\n"; break;
      case 2: s_ << "glMaterialfv " << face() << " GL_SPECULAR " << colour4() << "\n"; break;
      case 3: s_ << "glMaterialfv " << face() << " GL_EMISSION " << nums({real(0, 0.4), real(0, 0.4), real(0, 0.4), 1}) << "\n"; break;
      case 4: s_ << "glMaterialfv " << face() << " GL_AMBIENT_AND_DIFFUSE " << colour4() << "\n"; break;
      default: s_ << "glMaterialf " << face() << " GL_SHININESS " << num(real(0, 128)) << "\n"; break;
    }
  }
  void fog() {
    const int n = uniform(1, 4);
    for (int i = 0; i < n; ++i) {
      switch (uniform(0, 5)) {
        case 0: s_ << "glFogi GL_FOG_MODE " << pick(std::vector<std::string>{"GL_LINEAR", "GL_EXP", "GL_EXP2"}) << "\n"; break;
        case 1: s_ << "glFogf GL_FOG_START " << num(real(0, 7)) << "\n"; break;
        case 2: s_ << "glFogf GL_FOG_END " << num(real(3, 14)) << "\n"; break;
        case 3: s_ << "glFogf GL_FOG_DENSITY " << num(real(0, 0.5)) << "\n"; break;
        case 4: s_ << "glFogfv GL_FOG_COLOR " << colour4() << "\n"; break;
        default: s_ << "glHint GL_FOG_HINT " << pick(std::vector<std::string>{"GL_NICEST", "GL_FASTEST", "GL_DONT_CARE"}) << "\n"; break;
      }
    }
  }
  void clipPlane() {
    const int p = uniform(0, 5);
    if (chance(40)) chain();
    s_ << "glClipPlane GL_CLIP_PLANE" << p << " " << nums({real(-1, 1), real(-1, 1), real(-1, 1), real(-1, 1)}) << "\n";
    s_ << (chance(80) ? "glEnable" : "glDisable") << " GL_CLIP_PLANE" << p << "\n";
  }
  void accum() {
    switch (uniform(0, 5)) {
      case 0: case 1: s_ << "glAccum GL_ACCUM " << num(real(-1, 1.5)) << "\n"; break;
      case 2: s_ << "glAccum GL_LOAD " << num(real(-1, 1.5)) << "\n"; break;
      case 3: s_ << "glAccum GL_MULT " << num(real(-1, 2)) << "\n"; break;
      case 4: s_ << "glAccum GL_ADD " << num(real(-0.7, 0.7)) << "\n"; break;
      default: s_ << "glAccum GL_RETURN " << num(real(0, 2)) << "\n"; break;
    }
  }

  struct P {
    double x, y, z;
  };
  P box(double e = 2.0) { return {real(-e, e), real(-e, e), real(-e, e)}; }
  void attributes(bool first) {
    if (lit_ && (first || chance(70))) {
      const double sc = chance(30) ? real(0.2, 3) : 1;
      double x = real(-1, 1), y = real(-1, 1), z = real(-1, 1);
      const double len = std::sqrt(x * x + y * y + z * z) + 1e-3;
      s_ << "glNormal3f " << nums({x / len * sc, y / len * sc, z / len * sc}) << "\n";
    }
    if (first || chance(60)) {
      // A script keeps to three or to four components: Mesa's vbo, when
      // glColor3 follows glColor4 inside glBegin, gives alphas that are not
      // the simple color3_alpha departure (and cannot be excused;
      // tests/conformance/repro/color3_alpha_in_begin.gls).
      const bool ub = chance(25);
      if (threeComponents_ && ub) s_ << "glColor3ub " << uniform(0, 255) << " " << uniform(0, 255) << " " << uniform(0, 255) << "\n";
      else if (threeComponents_) s_ << "glColor3f " << nums({real(0, 1), real(0, 1), real(0, 1)}) << "\n";
      else if (ub) s_ << "glColor4ub " << uniform(0, 255) << " " << uniform(0, 255) << " " << uniform(0, 255) << " " << uniform(0, 255) << "\n";
      else s_ << "glColor4f " << colour4() << "\n";
    }
    if (lit_ && chance(4)) material();
  }
  void vertex(const P& p) {
    switch (uniform(0, 9)) {
      case 0: {
        const double w = real(0.5, 2);
        s_ << "glVertex4f " << nums({p.x * w, p.y * w, p.z * w, w}) << "\n";
        break;
      }
      case 1: s_ << "glVertex2f " << nums({p.x, p.y}) << "\n"; break;
      default: s_ << "glVertex3f " << nums({p.x, p.y, p.z}) << "\n"; break;
    }
  }
  // A convex planar outline: n points on an ellipse in a random plane.
  std::vector<P> outline(int n) {
    const P c = box(1.5), u = box(1.6), v = box(1.6);
    std::vector<double> a;
    for (int i = 0; i < n; ++i) a.push_back(real(0, 6.2831853));
    std::sort(a.begin(), a.end());
    if (chance(50)) std::reverse(a.begin(), a.end());
    std::vector<P> out;
    for (double t : a) out.push_back({c.x + u.x * std::cos(t) + v.x * std::sin(t), c.y + u.y * std::cos(t) + v.y * std::sin(t),
                                      c.z + u.z * std::cos(t) + v.z * std::sin(t)});
    return out;
  }
  void geometry() {
    if (chance(8)) {
      attributes(true);
      s_ << "glRectf " << nums({real(-2.5, 2.5), real(-2.5, 2.5), real(-2.5, 2.5), real(-2.5, 2.5)}) << "\n";
      return;
    }
    const std::vector<std::string> modes = {"GL_TRIANGLES", "GL_TRIANGLE_STRIP", "GL_TRIANGLE_FAN",
                                            "GL_QUADS", "GL_QUAD_STRIP", "GL_POLYGON"};
    const std::string mode = pick(modes);
    std::vector<P> pts;
    if (mode == "GL_TRIANGLES") {
      const int n = uniform(1, 3);
      for (int t = 0; t < n; ++t) {
        const P c = box(1.6);
        for (int k = 0; k < 3; ++k) pts.push_back({c.x + real(-1.5, 1.5), c.y + real(-1.5, 1.5), c.z + real(-1.5, 1.5)});
      }
      if (chance(5)) pts.push_back(box());  // an incomplete triangle, ignored
    } else if (mode == "GL_QUADS") {
      const int n = uniform(1, 2);
      for (int t = 0; t < n; ++t) {
        std::vector<P> q = outline(4);
        pts.insert(pts.end(), q.begin(), q.end());
      }
    } else if (mode == "GL_POLYGON" || mode == "GL_TRIANGLE_FAN") {
      pts = outline(uniform(3, 7));
    } else {  // strips: two rails
      const P a = box(1.5), d = box(0.8), o = box(1.0);
      const int n = uniform(mode == "GL_QUAD_STRIP" ? 2 : 3, 5);
      for (int i = 0; i < n; ++i)
        for (int side = 0; side < 2; ++side)
          pts.push_back({a.x + d.x * i + o.x * side + real(-0.2, 0.2), a.y + d.y * i + o.y * side + real(-0.2, 0.2),
                         a.z + d.z * i + o.z * side + real(-0.2, 0.2)});
      if (mode == "GL_TRIANGLE_STRIP" && chance(50)) pts.pop_back();
    }
    s_ << "glBegin " << mode << "\n";
    for (std::size_t i = 0; i < pts.size(); ++i) {
      attributes(i == 0);
      vertex(pts[i]);
    }
    s_ << "glEnd\n";
  }

  std::mt19937_64 rng_;
  int w_, h_;
  std::ostringstream s_;
  bool lit_ = false;
  bool threeComponents_ = false;  // the script's colour calls: glColor3* only, or glColor4* only
  int depth_[2] = {0, 0};  // pushes on the modelview and projection stacks
  int snapshots_ = 0;
};

struct Family {
  const char* name;
  std::vector<Weighted> steps;
  int count;
  int litPercent, fogPercent;  // of scripts that start lit (fogged)
  bool accum;
};

const std::vector<Family>& families() {
  using S = Step;
  static const std::vector<Family> f = {
      {"perspective",
       {{S::Projection, 2}, {S::Modelview, 2}, {S::Geometry, 10}, {S::FragmentState, 2}, {S::Stencil, 2},
        {S::Blend, 1}, {S::Clear, 1}, {S::Snapshot, 1}},
       30, 0, 0, false},
      {"matrices",
       {{S::Projection, 2}, {S::Modelview, 1}, {S::MatrixChain, 3}, {S::LoadMatrix, 2}, {S::MultMatrix, 2},
        {S::PushPop, 3}, {S::Viewport, 2}, {S::DepthRange, 2}, {S::Geometry, 8}, {S::Stencil, 1}, {S::Snapshot, 1}},
       36, 0, 0, false},
      {"primitives",
       {{S::Projection, 1}, {S::Modelview, 2}, {S::CullShade, 4}, {S::Geometry, 12}, {S::Stencil, 1},
        {S::FragmentState, 1}, {S::Snapshot, 1}},
       32, 0, 0, false},
      {"lighting",
       {{S::Modelview, 1}, {S::Projection, 1}, {S::Light, 4}, {S::LightModel, 2}, {S::Material, 3},
        {S::ColorMaterial, 2}, {S::Normalize, 2}, {S::CullShade, 1}, {S::Geometry, 10}, {S::Snapshot, 1}},
       36, 100, 0, false},
      {"fog",
       {{S::Projection, 2}, {S::Modelview, 2}, {S::Fog, 5}, {S::Geometry, 10}, {S::CullShade, 1}, {S::Blend, 1},
        {S::Snapshot, 1}},
       30, 0, 100, false},
      {"clip_planes",
       {{S::Projection, 1}, {S::Modelview, 2}, {S::MatrixChain, 2}, {S::PushPop, 2}, {S::ClipPlane, 5},
        {S::Geometry, 10}, {S::Stencil, 1}, {S::Snapshot, 1}},
       32, 0, 0, false},
      {"accumulation",
       {{S::Projection, 1}, {S::Modelview, 2}, {S::Geometry, 6}, {S::Accum, 6}, {S::Clear, 2}, {S::Blend, 1},
        {S::Snapshot, 3}},
       30, 0, 0, true},
      {"mixed",
       {{S::Projection, 2}, {S::Modelview, 2}, {S::MatrixChain, 1}, {S::LoadMatrix, 1}, {S::MultMatrix, 1},
        {S::PushPop, 1}, {S::Viewport, 1}, {S::DepthRange, 1}, {S::FragmentState, 1}, {S::Stencil, 1},
        {S::Blend, 1}, {S::CullShade, 2}, {S::Clear, 1}, {S::Snapshot, 1}, {S::Geometry, 12}, {S::Light, 2},
        {S::LightModel, 1}, {S::Material, 1}, {S::ColorMaterial, 1}, {S::Normalize, 1}, {S::Fog, 2},
        {S::ClipPlane, 2}, {S::Accum, 2}, {S::Toggle, 2}},
       40, 50, 40, true},
      {"fragment_ops",
       {{S::Projection, 1}, {S::Modelview, 2}, {S::Geometry, 10}, {S::Scissor, 2}, {S::WriteMasks, 2},
        {S::StencilAny, 3}, {S::BlendAny, 2}, {S::AlphaAny, 1}, {S::DepthAny, 2}, {S::ClearAny, 2}, {S::Accum, 1},
        {S::CullShade, 1}, {S::Toggle, 1}, {S::Snapshot, 1}},
       40, 30, 20, true},
  };
  return f;
}

}  // namespace

const std::vector<std::string>& randomFamilies() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n = {"default"};
    for (const Family& f : families()) n.push_back(f.name);
    return n;
  }();
  return names;
}

std::string randomFamilyScript(const std::string& family, std::uint64_t seed) {
  if (family == "default") return randomConformanceScript(seed);
  for (const Family& f : families())
    if (family == f.name) {
      FamilyGenerator g(seed, 48, 40);
      return g.run(f.steps, f.count, f.litPercent, f.fogPercent, f.accum);
    }
  throw std::invalid_argument("unknown random family '" + family + "'");
}

}  // namespace mpr
