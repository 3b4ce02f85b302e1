#pragma once
// Pixel-by-pixel comparison of MPR's buffers with Mesa's, per buffer, against
// the project's conformance bounds (README, "Conformance").
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "conformance/buffer_set.hpp"
#include "pipeline/gl_script.hpp"

namespace mpr {

struct PixelMismatch {
  int x, y;
  std::array<int, 4> mpr, mesa;  // colour uses 4, depth and stencil 1
};

struct BufferAgreement {
  std::string buffer;  // "color", "depth", "stencil"
  std::size_t pixels = 0, agree = 0;
  int maxDiff = 0;
  std::size_t withinBound = 0;          // pixels whose difference is within the bound
  int bound = 0;                        // allowed difference per value
  double requiredFraction = 1.0;        // of pixels that must be within the bound
  std::vector<PixelMismatch> first;     // the first few mismatches, bottom row first
  bool conforms() const {
    return static_cast<double>(withinBound) >= requiredFraction * static_cast<double>(pixels);
  }
};

struct PointAgreement {
  std::string point;  // "final" or a snapshot name
  BufferAgreement color, depth, stencil;
  bool conforms() const { return color.conforms() && depth.conforms() && stencil.conforms(); }
};

// The bounds a script is held to.
struct ConformanceBounds {
  bool exactCoordinates;  // dyadic coordinates under an orthographic projection
  bool litOrFogged;       // lighting or fog is enabled somewhere
  int colorBound() const { return litOrFogged ? 2 : 1; }
  int depthBound() const { return 1; }
  double stencilFraction() const { return exactCoordinates ? 1.0 : 0.999; }
};

ConformanceBounds boundsFor(const Script& script);

PointAgreement compareBuffers(const BufferSet& mpr, const BufferSet& mesa, const ConformanceBounds& bounds,
                              std::size_t keepMismatches = 10);

}  // namespace mpr
