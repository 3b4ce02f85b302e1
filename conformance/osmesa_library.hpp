#pragma once
// Mesa's OSMesa, opened with dlopen when a replay first needs it. Linking it
// would load libLLVM (410 000 relocations, 3 400 page faults: about 23 ms)
// into every mpr process, `mpr gl` and `mpr render` included, which never
// call Mesa.
#include <GL/gl.h>
#include <GL/osmesa.h>

namespace mpr {

// Every C function the replay calls, by its own name: the GL calls of
// pipeline/gl_calls.def (the GLU ones are built by the replay) and the few
// the replay needs beside them.
struct OSMesaLibrary {
#define MPR_GL_CALL(Enum, method, cFunction, kinds, params, args) decltype(&::cFunction) cFunction = nullptr;
#define MPR_GLU_CALL(...)
#include "pipeline/gl/gl_calls.def"
#undef MPR_GL_CALL
  decltype(&::glReadPixels) glReadPixels = nullptr;
  decltype(&::glPixelStorei) glPixelStorei = nullptr;
  decltype(&::glGetError) glGetError = nullptr;
  decltype(&::glGetString) glGetString = nullptr;
  decltype(&::OSMesaCreateContextExt) OSMesaCreateContextExt = nullptr;
  decltype(&::OSMesaMakeCurrent) OSMesaMakeCurrent = nullptr;
  decltype(&::OSMesaPixelStore) OSMesaPixelStore = nullptr;
  decltype(&::OSMesaDestroyContext) OSMesaDestroyContext = nullptr;
};

// The library, opened once per process (MPR_OSMESA names another file to
// open, alone). Throws MesaUnavailable, naming what was tried, when it cannot be
// opened or lacks one of the functions.
const OSMesaLibrary& osmesaLibrary();

}  // namespace mpr
