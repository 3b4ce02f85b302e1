#pragma once
// Every pixel's history for the stepper page, compact enough for a whole
// 640x480 multi-pass frame: clicking any pixel shows the lines `mpr step
// --pixel` prints, without running anything in the browser.
//
// A line's wording depends only on the call and the per-fragment state it ran
// with (pipeline/pixel_history_text), so each distinct wording is stored once
// as a template with placeholders ({line} {k} {s0} {s1} {d0} {dz} {d1} {c0}
// {c1}), formatted by the same code as the command line's lines.
//
// Events are kept per square tile of pixels, in the order they happened, as
// one byte stream per tile cut into independently zlib'd chunks (so memory
// holds compressed data, not raw events). An event is:
//   zig-zag varint pixel - previous event's pixel (index within the tile,
//   rows from the tile's lowest), varint template, varint pass - previous
//   pass, varint line - previous line, then the template's values in the
//   order s0 s1 d0 dz d1 c0 c1:
//     s0 s1 d0 d1: zig-zag varints of the difference to what the pixel last
//       held (s1 to s0, d1 to d0),
//     dz: zig-zag varint of the difference to the tile's previous dz,
//     c0: 4 wrapping byte differences to the pixel's last colour (its
//       last c0 or c1),
//     c1: 4 wrapping byte differences to the tile's previous c1.
// "Previous" and "last" start at 0. {k}, a fragment's rank within its call,
// is not stored: it is one more than the pixel's previous event's when both
// have the same line (one call per line).
//
// Size is bounded: once the compressed events pass `byteBudget`, recording
// stops at a pass boundary and the page says which passes it covers.
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "stepper/pixel_event_recorder.hpp"

namespace mpr::cli {

class PixelHistoryEncoder {
 public:
  PixelHistoryEncoder(int width, int height, int tileSize, std::size_t byteBudget);

  void add(const PixelEvent& e, const FragmentState& s);
  // Pass `pass` is over: stop after it if the budget is spent.
  void passEnded(int pass);
  // Compresses what is still raw; call once, after the last pass.
  void finish();

  bool stopped() const { return stopped_; }
  // When stopped: histories are complete for passes 0 .. recordedPasses() - 1 only.
  int recordedPasses() const { return recordedPasses_; }
  std::size_t eventCount() const { return events_; }
  std::size_t compressedBytes() const { return compressed_; }
  const std::vector<std::string>& templates() const { return templates_; }
  int tilesAcross() const { return tilesX_; }
  // The zlib chunks of tile (tx, ty), in order; their inflated bytes concatenate into one event stream.
  const std::vector<std::string>& tileChunks(int tx, int ty) const { return tiles_[tileIndex(tx, ty)].chunks; }
  int tileCount() const { return static_cast<int>(tiles_.size()); }

 private:
  struct Pixel {  // what the pixel's last event left
    std::uint32_t stencil = 0, depth = 0;
    Rgba8 colour{};
  };
  struct Tile {
    std::string raw;
    std::vector<std::string> chunks;
    std::int64_t pixel = 0;
    int pass = 0, line = 0;
    std::uint32_t depthIncoming = 0;
    Rgba8 colourAfter{};
  };
  struct Template {
    int id;
    std::uint8_t fields;  // bit i: field i of s0 s1 d0 dz d1 c0 c1 is present
  };
  const Template& templateFor(const PixelEvent& e, const FragmentState& s);
  std::size_t tileIndex(int tx, int ty) const { return static_cast<std::size_t>(ty) * tilesX_ + tx; }
  void flush(Tile& t);

  int width_, tile_, tilesX_;
  std::size_t budget_;
  std::vector<Tile> tiles_;
  std::vector<Pixel> pixels_;
  std::vector<std::string> templates_;
  std::unordered_map<std::string, Template> byKey_;
  std::unordered_map<std::string, Template> byText_;
  std::size_t events_ = 0, compressed_ = 0, rawCompressed_ = 0;
  int currentPass_ = 0;
  bool stopped_ = false;
  int recordedPasses_ = 0;
};

}  // namespace mpr::cli
