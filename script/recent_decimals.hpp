#pragma once
// The numbers a trace repeats, read once: a mesh's coordinates come back
// with every triangle that shares the vertex, its normals are a few values
// over and over (nine in ten of the bathroom trace's numbers are the same
// text as one of the last few thousand). A number read is kept by its
// token's bytes in a direct-mapped table; the same bytes again give the
// same double without reading them (shortDecimalAt is a function of the
// bytes alone, so the answer is bit for bit the one it would give).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string_view>

namespace mpr {

class RecentDecimals {
 public:
  // shortDecimalAt(t, limit, value): the same answer, from the table where
  // these bytes were read before.
  bool read(std::string_view t, const char* limit, double& value);

 private:
  struct Entry {
    std::uint64_t low = 0, high = 0;  // the token's bytes, zeros past its end
    double value = 0.0;
    std::uint32_t size = 0;  // 0: empty (a token has at least one byte)
  };
  static constexpr int kSlotBits = 11;
  std::unique_ptr<Entry[]> entries_;  // 2^kSlotBits, allocated at the first read
};

}  // namespace mpr
