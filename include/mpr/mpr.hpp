#pragma once
// MPR in one include, for test authors outside this repository:
//
//   find_package(MPR CONFIG REQUIRED)
//   target_link_libraries(my_tests PRIVATE MPR::testing)   # or MPR::gl, MPR::algorithms
//
//   #include <mpr/mpr.hpp>
//
// MPR::gl (the emulated pipeline): GLContext and GL's enum values, the GL
// script parser and runner, probes, stencil pictures. MPR::algorithms adds
// the 1994 algorithm on it (draw_window, apply_stencil, shadow volumes, the
// scene model). MPR::testing adds the GoogleTest helpers (mpr::testing::
// HasStencilPicture, StencilAt, stencilBuffersEqual, ...). Each target sets
// the macro that brings its part in here.
#include <GL/gl.h>  // the enum values GLContext's methods take

#include "framebuffer/framebuffer.hpp"
#include "framebuffer/profile.hpp"
#include "framebuffer/stencil_picture.hpp"
#include "pipeline/gl/gl_api.hpp"
#include "pipeline/gl/gl_context.hpp"
#include "pipeline/gl/gl_emulator.hpp"
#include "pipeline/gl/gl_enums.hpp"
#include "script/gl_script.hpp"
#include "script/gl_script_runner.hpp"
#include "script/gl_trace_writer.hpp"
#include "framebuffer/script_probe.hpp"

#if defined(MPR_WITH_ALGORITHMS)
#include "algorithms/apply_stencil.hpp"
#include "algorithms/draw_window.hpp"
#include "algorithms/gl_command_stream.hpp"
#include "algorithms/pass_state.hpp"
#include "algorithms/scene_renderer.hpp"
#include "algorithms/shadow_volume.hpp"
#include "algorithms/stencil_levels.hpp"
#include "scene/scene.hpp"
#include "scene/scene_loader.hpp"
#endif

#if defined(MPR_WITH_TESTING)
#include "testing/gtest_helpers.hpp"
#endif
