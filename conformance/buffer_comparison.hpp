#pragma once
// Pixel-by-pixel comparison of MPR's buffers with Mesa's, per buffer, against
// the project's conformance bounds (docs/explanation/mesa.md).
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "conformance/buffer_set.hpp"
#include "script/gl_script.hpp"

namespace mpr {

struct PixelMismatch {
  int x, y;
  std::array<int, 4> mpr, mesa;  // colour uses 4, depth and stencil 1
  std::string departure;         // the known Mesa departure that explains it, if one does
};

// A known departure of Mesa 22.3 from GL 1.1 (docs/explanation/mesa.md, "Known Mesa
// departures"): MPR's buffers with the departure emulated, or, where it
// cannot be emulated, the colour of every pixel whose depth and stencil agree
// is taken as explained (`colourWhereDepthAgrees`).
struct DepartureRun {
  std::string name;
  const BufferSet* buffers = nullptr;
  bool colourWhereDepthAgrees = false;
};

struct BufferAgreement {
  std::string buffer;  // "color", "depth", "stencil"
  std::size_t pixels = 0, agree = 0;
  int maxDiff = 0;
  std::size_t withinBound = 0;          // pixels whose difference is within the bound
  int bound = 0;                        // allowed difference per value
  double requiredFraction = 1.0;        // of pixels that must be within the bound
  std::vector<PixelMismatch> first;     // the first few mismatches, bottom row first
  std::size_t explained = 0;            // out of bound, but explained by a known Mesa departure
  bool strict = false;                  // --strict: departures are not excused
  bool conforms() const {
    const std::size_t ok = withinBound + (strict ? 0 : explained);
    return static_cast<double>(ok) >= requiredFraction * static_cast<double>(pixels);
  }
};

struct PointAgreement {
  std::string point;  // "final" or a snapshot name
  BufferAgreement color, depth, stencil;
  std::map<std::string, std::size_t> departures;  // pixels explained, by departure
  bool conforms() const { return color.conforms() && depth.conforms() && stencil.conforms(); }
};

// The bounds a script is held to.
struct ConformanceBounds {
  bool exactCoordinates;  // dyadic coordinates under an orthographic projection
  bool litOrFogged;       // lighting or fog is enabled somewhere
  bool strict = false;    // known Mesa departures fail the script too
  bool exact = false;     // --exact: every buffer identical on every pixel (departures still excused unless strict)
  int colorBound() const { return exact ? 0 : litOrFogged ? 2 : 1; }
  int depthBound() const { return exact ? 0 : 1; }
  double stencilFraction() const { return exact || exactCoordinates ? 1.0 : 0.999; }
};

ConformanceBounds boundsFor(const Script& script);

PointAgreement compareBuffers(const BufferSet& mpr, const BufferSet& mesa, const ConformanceBounds& bounds,
                              std::size_t keepMismatches = 10, const std::vector<DepartureRun>& departures = {});

// The departures a script may show, by its calls (the ones that cannot be
// emulated are recognised here: under two-sided lighting, colour material on
// back faces with a colour inside glBegin/glEnd, or a glMaterial of the back
// face inside glBegin/glEnd).
bool showsColourMaterialBackInBegin(const Script& script);

}  // namespace mpr
