// Row spans of one llvmpipe triangle (see llvmpipe_row_spans.hpp).
#include "raster/llvmpipe_row_spans.hpp"

#include <algorithm>
#include <cstdlib>
#include <limits>

#include "raster/fixed_point.hpp"

namespace mpr {
namespace {

// Positions (1/256 pixel) below which no product of the walk wraps: |a|,
// |b| < 2^37, |c| < 2^59, and b times a row (below 2^24) under 2^61.
constexpr std::int64_t kCarriedLimit = std::int64_t{1} << 28;

}  // namespace

void LlvmpipeRowSpans::solveRow(const LlvmpipeDepth::Triangle& t, std::int64_t yDown, std::int64_t& lo,
                                std::int64_t& hi) {
  for (int i = 0; i < 3 && lo <= hi; ++i) {
    const int j = (i + 1) % 3;
    const std::int64_t a = (t.fixedY[i] - t.fixedY[j]) * 256;
    // Wrapping as covers() wraps: only a NaN or huge vertex's clamped position overflows.
    const std::int64_t k = wrappingAdd(t.c[i], (t.fixedX[i] - t.fixedX[j]) * (yDown * 256));
    const std::int64_t km1 = wrappingSub(k, 1);
    if (a > 0) hi = std::min(hi, floorDivide(km1, a));         // a x <= k - 1
    else if (a < 0) lo = std::max(lo, -floorDivide(km1, -a));  // -a x >= 1 - k
    else if (!(k > 0)) hi = lo - 1;
  }
}

LlvmpipeRowSpans::LlvmpipeRowSpans(const LlvmpipeDepth::Triangle& t, std::int64_t firstRow, std::int64_t step,
                                   std::int64_t x0, std::int64_t x1)
    : t_(t), row_(firstRow), step_(step), x0_(x0), x1_(x1) {
  carried_ = std::abs(firstRow) < (std::int64_t{1} << 23) && step > 0 && step < (std::int64_t{1} << 16);
  for (int i = 0; i < 3; ++i)
    carried_ = carried_ && std::abs(t.fixedX[i]) < kCarriedLimit && std::abs(t.fixedY[i]) < kCarriedLimit;
  if (!carried_) return;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const std::int64_t a = (t.fixedY[i] - t.fixedY[j]) * 256, b = (t.fixedX[i] - t.fixedX[j]) * 256;
    k_[i] = t.c[i] + b * firstRow;  // the plane at x = 0 on the first row
    dk_[i] = b * step;
    kind_[i] = a > 0 ? 1 : a < 0 ? -1 : 0;
    if (a == 0) {
      divisor_[i] = std::numeric_limits<std::int64_t>::max();  // no carry
      continue;
    }
    const std::int64_t divisor = a > 0 ? a : -a;
    divisor_[i] = divisor;
    q_[i] = floorDivide(k_[i] - 1, divisor);
    r_[i] = (k_[i] - 1) - q_[i] * divisor;
    dq_[i] = floorDivide(dk_[i], divisor);
    dr_[i] = dk_[i] - dq_[i] * divisor;
  }
}

}  // namespace mpr
