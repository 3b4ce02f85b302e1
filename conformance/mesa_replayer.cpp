#include "conformance/mesa_replayer.hpp"

#include <cstdlib>
#include <memory>

#include "conformance/osmesa_library.hpp"
#include "script/gl_dispatch.hpp"
#include "script/gl_script_runner.hpp"
#include "util/transforms.hpp"

namespace mpr {
namespace {

BufferSet readBuffers(const OSMesaLibrary& gl, const std::string& point, int w, int h) {
  BufferSet b;
  b.point = point;
  b.width = w;
  b.height = h;
  const std::size_t n = static_cast<std::size_t>(w) * h;
  b.color.resize(n * 4);
  b.depth.resize(n);
  b.stencil.resize(n);
  gl.glPixelStorei(GL_PACK_ALIGNMENT, 1);
  gl.glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, b.color.data());
  // 24-bit depth as the top bits of a 32-bit unsigned read.
  gl.glReadPixels(0, 0, w, h, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, b.depth.data());
  for (std::uint32_t& z : b.depth) z >>= 8;
  gl.glReadPixels(0, 0, w, h, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, b.stencil.data());
  return b;
}

// Mesa behind the typed GL API: every call of the table is the C function of
// the same name (generated from pipeline/gl_calls.def); the two GLU calls are
// built here as SGI's GLU builds them.
class MesaApi final : public GLApi {
 public:
  explicit MesaApi(const OSMesaLibrary& gl) : gl_(gl) {}

#define MPR_GL_CALL(Enum, method, cFunction, kinds, params, args) \
  void method params override { gl_.cFunction args; }
#define MPR_GLU_CALL(...)
#include "pipeline/gl/gl_calls.def"

  void perspective(GLdouble fovy, GLdouble aspect, GLdouble zNear, GLdouble zFar) override {
    // SGI GLU's construction, multiplied as GLU does (glMultMatrixd).
    if (const auto m = perspectiveMatrix(fovy, aspect, zNear, zFar)) multMatrix(*m);
  }
  void lookAt(GLdouble ex, GLdouble ey, GLdouble ez, GLdouble cx, GLdouble cy, GLdouble cz, GLdouble ux,
              GLdouble uy, GLdouble uz) override {
    multMatrix(lookAtMatrix(ex, ey, ez, cx, cy, cz, ux, uy, uz));
  }

  void pass(std::string_view) override {}
  // GL has no end-of-pipeline map: a replay draws unmapped, and says so.
  void windowMap(const std::optional<glm::mat3>& map) override { usedWindowMap = usedWindowMap || map.has_value(); }
  void beginFragmentCount() override {}
  std::uint64_t endFragmentCount() override { return 0; }

  bool usedWindowMap = false;

 private:
  void multMatrix(const Mat4& m) { gl_.glMultMatrixf(&m[0][0]); }

  const OSMesaLibrary& gl_;
};

}  // namespace

MesaReplay replayOnMesa(const Script& script, const std::string& driver) {
  return replayOnMesa(script, driver, [&](const std::function<void(const ScriptCommand&)>& replay) {
    for (const ScriptCommand& c : script.commands) replay(c);
  });
}

MesaReplay replayOnMesa(const Script& script, const std::string& driver, const MesaCommandFeed& feed) {
  // Mesa reads GALLIUM_DRIVER when the context's screen is created.
  setenv("GALLIUM_DRIVER", driver.c_str(), 1);
  const OSMesaLibrary& gl = osmesaLibrary();
  const auto destroy = [&gl](osmesa_context* c) { gl.OSMesaDestroyContext(c); };
  std::unique_ptr<osmesa_context, decltype(destroy)> ctx(gl.OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 16, nullptr),
                                                         destroy);
  if (!ctx) throw MesaUnavailable("OSMesa could not create an RGBA context with 24/8/16 bits (" + driver + ")");
  std::vector<std::uint8_t> pixels(static_cast<std::size_t>(script.width) * script.height * 4);
  if (!gl.OSMesaMakeCurrent(ctx.get(), pixels.data(), GL_UNSIGNED_BYTE, script.width, script.height))
    throw MesaUnavailable("OSMesaMakeCurrent failed");
  gl.OSMesaPixelStore(OSMESA_Y_UP, 1);

  MesaReplay out;
  if (const GLubyte* r = gl.glGetString(GL_RENDERER)) out.renderer = reinterpret_cast<const char*>(r);
  bool inBegin = false;
  MesaApi mesa(gl);
  feed([&](const ScriptCommand& c) {
    if (c.kind == ScriptCommand::Kind::Snapshot) {
      gl.glFinish();
      out.snapshots.push_back(readBuffers(gl, c.label, script.width, script.height));
      return;
    }
    dispatch(mesa, c);
    if (c.kind != ScriptCommand::Kind::Call) return;
    if (c.call == GLCall::Begin) inBegin = true;
    if (c.call == GLCall::End) inBegin = false;
    // glGetError is itself an error between glBegin and glEnd.
    if (!inBegin)
      for (GLenum e = gl.glGetError(); e != GL_NO_ERROR; e = gl.glGetError())
        out.glErrors.push_back(glErrorReport(c, e));
  });
  if (mesa.usedWindowMap)
    out.glErrors.push_back("@window_map: the end-of-pipeline map is MPR's emulated stage, not GL; Mesa drew unmapped");
  gl.glFinish();
  out.snapshots.push_back(readBuffers(gl, "final", script.width, script.height));
  return out;
}

}  // namespace mpr
