#include "conformance/osmesa_library.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "conformance/mesa_replayer.hpp"

namespace mpr {
namespace {

struct Loaded {
  OSMesaLibrary library;
  std::string problem;  // empty when every function was found
};

template <typename Function>
void bind(void* handle, const char* name, Function& to, std::string& missing) {
  // POSIX guarantees that a dlsym result converts to a function pointer.
  to = reinterpret_cast<Function>(dlsym(handle, name));
  if (!to) missing += (missing.empty() ? "" : ", ") + std::string(name);
}

Loaded load() {
  Loaded out;
  std::vector<std::string> candidates;
  if (const char* path = std::getenv("MPR_OSMESA"); path && *path) {
    candidates.emplace_back(path);  // the user's choice, alone
  } else {
    candidates.emplace_back(MPR_OSMESA_SONAME);
    candidates.emplace_back(MPR_OSMESA_LINKED);
  }
  std::string tried;
  void* handle = nullptr;
  for (const std::string& c : candidates) {
    // The handle stays open for the process: the GL functions are used until exit.
    handle = dlopen(c.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle) break;
    const char* e = dlerror();
    tried += (tried.empty() ? "" : ", ") + c + " (" + (e ? e : "cannot open") + ")";
  }
  if (!handle) {
    out.problem = "cannot open Mesa's OSMesa (tried " + tried + "); install libosmesa6 or set MPR_OSMESA to its path";
    return out;
  }
  OSMesaLibrary& l = out.library;
  std::string missing;
#define MPR_GL_CALL(Enum, method, cFunction, kinds, params, args) bind(handle, #cFunction, l.cFunction, missing);
#define MPR_GLU_CALL(...)
#include "pipeline/gl/gl_calls.def"
#undef MPR_GL_CALL
  bind(handle, "glReadPixels", l.glReadPixels, missing);
  bind(handle, "glPixelStorei", l.glPixelStorei, missing);
  bind(handle, "glGetError", l.glGetError, missing);
  bind(handle, "glGetString", l.glGetString, missing);
  bind(handle, "OSMesaCreateContextExt", l.OSMesaCreateContextExt, missing);
  bind(handle, "OSMesaMakeCurrent", l.OSMesaMakeCurrent, missing);
  bind(handle, "OSMesaPixelStore", l.OSMesaPixelStore, missing);
  bind(handle, "OSMesaDestroyContext", l.OSMesaDestroyContext, missing);
  if (!missing.empty()) out.problem = "Mesa's OSMesa library lacks " + missing;
  return out;
}

}  // namespace

const OSMesaLibrary& osmesaLibrary() {
  static const Loaded loaded = load();
  if (!loaded.problem.empty()) throw MesaUnavailable(loaded.problem);
  return loaded.library;
}

}  // namespace mpr
