#include "cli/pixel_history_encoder.hpp"

#include <algorithm>

#include "cli/page_encoding.hpp"
#include "stepper/pixel_history_text.hpp"

namespace mpr::cli {
namespace {

constexpr const char* kFields[] = {"{s0}", "{s1}", "{d0}", "{dz}", "{d1}", "{c0}", "{c1}"};
enum Field { S0, S1, D0, DZ, D1, C0, C1 };

// What decides a line's wording, as bytes: a cheap key for the template cache.
std::string wordingKey(const PixelEvent& e, const FragmentState& s) {
  const StencilState& st = s.stencil;
  std::string k;
  k.reserve(24);
  k += static_cast<char>(e.kind);
  k += static_cast<char>(e.call->call);
  if (e.kind == PixelEvent::Kind::Change) return k;
  k += static_cast<char>(e.fate);
  k += static_cast<char>(st.enabled);
  k += static_cast<char>(st.func);
  k += static_cast<char>(st.sfail);
  k += static_cast<char>(st.dpfail);
  k += static_cast<char>(st.dppass);
  k.append(reinterpret_cast<const char*>(&st.ref), sizeof st.ref);
  k.append(reinterpret_cast<const char*>(&st.valueMask), sizeof st.valueMask);
  k += static_cast<char>(s.depth.enabled);
  k += static_cast<char>(s.depth.func);
  return k;
}

}  // namespace

// A tile's raw events are compressed once they reach this size.
constexpr std::size_t kChunk = std::size_t{256} << 10;

PixelHistoryEncoder::PixelHistoryEncoder(int width, int height, int tileSize, std::size_t byteBudget)
    : width_(width), tile_(tileSize), tilesX_((width + tileSize - 1) / tileSize), budget_(byteBudget) {
  tiles_.resize(static_cast<std::size_t>(tilesX_) * static_cast<std::size_t>((height + tileSize - 1) / tileSize));
  pixels_.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  stopped_ = byteBudget == 0;  // no histories at all
}

const PixelHistoryEncoder::Template& PixelHistoryEncoder::templateFor(const PixelEvent& e, const FragmentState& s) {
  const std::string key = wordingKey(e, s);
  if (auto it = byKey_.find(key); it != byKey_.end()) return it->second;
  const std::string_view call = glCallName(e.call->call);
  const std::string text =
      e.kind == PixelEvent::Kind::Change
          ? changeLine(call, {"{line}", "{s0}", "{s1}", "{d0}", "{d1}", "{c0}", "{c1}"})
          : fragmentLine(call, s, e.fate, {"{line}", "{k}", "{s0}", "{s1}", "{d0}", "{dz}", "{c1}"});
  // Different states can word a line the same (a disabled test's settings do
  // not show): those share one template.
  auto [it, added] = byText_.try_emplace(text, Template{static_cast<int>(templates_.size()), 0});
  if (added) {
    templates_.push_back(text);
    for (int f = 0; f < 7; ++f)
      if (text.find(kFields[f]) != std::string::npos) it->second.fields |= static_cast<std::uint8_t>(1u << f);
  }
  return byKey_.emplace(key, it->second).first->second;
}

void PixelHistoryEncoder::add(const PixelEvent& e, const FragmentState& s) {
  if (stopped_) return;
  const Template& t = templateFor(e, s);
  const int tx = e.x / tile_, ty = e.y / tile_;
  Tile& tile = tiles_[tileIndex(tx, ty)];
  const int tileWidth = std::min(tile_, width_ - tx * tile_);
  const std::int64_t inTile = static_cast<std::int64_t>(e.y - ty * tile_) * tileWidth + (e.x - tx * tile_);
  Pixel& p = pixels_[static_cast<std::size_t>(e.y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(e.x)];
  std::string& out = tile.raw;
  putSigned(out, inTile - tile.pixel);
  putVarint(out, static_cast<std::uint64_t>(t.id));
  putVarint(out, static_cast<std::uint64_t>(e.pass - tile.pass));
  putVarint(out, static_cast<std::uint64_t>(e.call->line - tile.line));
  tile.pixel = inTile;
  tile.pass = e.pass;
  tile.line = e.call->line;
  auto difference = [&](std::uint32_t v, std::uint32_t& last) {
    putSigned(out, static_cast<std::int64_t>(v) - static_cast<std::int64_t>(last));
    last = v;
  };
  auto bytes = [&](const Rgba8& c, Rgba8& last) {
    for (int k = 0; k < 4; ++k) out.push_back(static_cast<char>(static_cast<std::uint8_t>(c[k] - last[k])));
    last = c;
  };
  if (t.fields & (1u << S0)) difference(e.stencilBefore, p.stencil);
  if (t.fields & (1u << S1)) difference(e.stencilAfter, p.stencil);
  if (t.fields & (1u << D0)) difference(e.depthBefore, p.depth);
  if (t.fields & (1u << DZ)) difference(e.depthIncoming, tile.depthIncoming);
  if (t.fields & (1u << D1)) difference(e.depthAfter, p.depth);
  if (t.fields & (1u << C0)) bytes(e.colourBefore, p.colour);
  if (t.fields & (1u << C1)) {
    bytes(e.colourAfter, tile.colourAfter);
    p.colour = e.colourAfter;
  }
  ++events_;
  currentPass_ = e.pass;
  if (out.size() >= kChunk) {
    flush(tile);
    // Far over the budget within one pass: keep the passes before it.
    if (compressed_ > budget_ + budget_ / 2) {
      stopped_ = true;
      recordedPasses_ = currentPass_;
    }
  }
}

void PixelHistoryEncoder::flush(Tile& t) {
  if (t.raw.empty()) return;
  t.chunks.push_back(zlibCompress(t.raw));
  compressed_ += t.chunks.back().size();
  rawCompressed_ += t.raw.size();
  t.raw.clear();
  t.raw.shrink_to_fit();
}

void PixelHistoryEncoder::passEnded(int pass) {
  if (stopped_) return;
  // What is still raw counts at the ratio seen so far.
  const double ratio =
      rawCompressed_ > 0 ? static_cast<double>(compressed_) / static_cast<double>(rawCompressed_) : 1.0;
  std::size_t pending = 0;
  for (const Tile& t : tiles_) pending += t.raw.size();
  if (static_cast<double>(compressed_) + ratio * static_cast<double>(pending) <= static_cast<double>(budget_)) return;
  for (Tile& t : tiles_) flush(t);  // the estimate says over: measure
  if (compressed_ > budget_) {
    stopped_ = true;
    recordedPasses_ = pass + 1;
  }
}

void PixelHistoryEncoder::finish() {
  for (Tile& t : tiles_) flush(t);
}

}  // namespace mpr::cli
