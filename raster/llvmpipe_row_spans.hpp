#pragma once
// The pixels of each row that llvmpipe's fixed-point edges cover for one of
// its triangles (LlvmpipeDepth::Triangle::covers: c + dcdy py - dcdx px > 0
// on every plane, px = 256 x, py = 256 yDown), row after row.
//
// Each row's span is solved from the three half-planes in exact integers
// (solveRow): x <= floor((k - 1) / a) or x >= -floor((k - 1) / -a), k the
// plane's value at x = 0. Walking rows `step` apart, k grows by a constant,
// so each floor is carried from row to row as a quotient and a remainder,
// additions instead of three 64-bit divisions a row (two thirds of the rows
// a clipped triangle's bounding box holds are empty, each paying them: the
// bathroom trace). The quotients are those of solveRow exactly wherever no
// product wraps; a triangle with a vertex far outside (beyond 2^20 pixels,
// where llvmpipe's clamped positions wrap) is solved row by row instead.
#include <algorithm>
#include <array>
#include <cstdint>

#include "raster/llvmpipe_depth.hpp"

namespace mpr {

class LlvmpipeRowSpans {
 public:
  // Rows firstRow, firstRow + step, ... (llvmpipe's y-down rows), each span
  // clipped to the columns [x0, x1].
  LlvmpipeRowSpans(const LlvmpipeDepth::Triangle& t, std::int64_t firstRow, std::int64_t step, std::int64_t x0,
                   std::int64_t x1);

  // The current row's covered columns [lo, hi] (lo > hi: none); then on to
  // the next row. (Inline: it runs once a row.)
  void next(std::int64_t& lo, std::int64_t& hi) {
    lo = x0_;
    hi = x1_;
    if (!carried_) {
      solveRow(t_, row_, lo, hi);
      row_ += step_;
      return;
    }
    bool none = false;
    for (int i = 0; i < 3; ++i) {
      if (kind_[i] > 0) hi = std::min(hi, q_[i]);
      else if (kind_[i] < 0) lo = std::max(lo, -q_[i]);
      else none = none || !(k_[i] > 0);
      // On to the next row: (k - 1) + dk = (q + dq) A + (r + dr), with
      // r + dr < 2A (a horizontal plane's A is never reached).
      q_[i] += dq_[i];
      r_[i] += dr_[i];
      const bool carry = r_[i] >= divisor_[i];
      r_[i] -= carry ? divisor_[i] : 0;
      q_[i] += carry ? 1 : 0;
      k_[i] += dk_[i];
    }
    if (none) hi = lo - 1;
    row_ += step_;
  }

  // The covered columns of row yDown within [lo, hi], solved directly
  // (wrapping as covers() wraps).
  static void solveRow(const LlvmpipeDepth::Triangle& t, std::int64_t yDown, std::int64_t& lo, std::int64_t& hi);

 private:
  const LlvmpipeDepth::Triangle& t_;
  std::int64_t row_, step_, x0_, x1_;
  bool carried_ = false;  // false: solveRow each row
  // Per plane: kind 1 bounds hi by q, -1 bounds lo by -q (q = floor((k-1)/A),
  // remainder r in [0, A)), 0 is horizontal (covered where k > 0).
  std::array<int, 3> kind_{};
  std::array<std::int64_t, 3> q_{}, r_{}, dq_{}, dr_{}, divisor_{}, k_{}, dk_{};
};

}  // namespace mpr
