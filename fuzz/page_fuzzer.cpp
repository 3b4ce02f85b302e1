// The stepper page's pixel history encoder and page writer (issue 15). The
// first input byte picks a history budget (none, 1 KiB, 16 KiB, 64 MiB), the
// rest is a GL script, run on a window of at most 32x32. Checked:
//  * every tile's zlib chunks inflate, and their event stream decodes the way
//    web/stepper.js decodes it (cli/pixel_history_encoder.hpp's format) into
//    exactly the events the encoder took, in order, each at its pixel and
//    pass, its template filled in as the page fills it worded exactly as
//    `mpr step --pixel` words it (stepper/pixel_history_text's
//    pixelEventLine); templates name known fields only;
//  * the page (cli/step_page, into a scratch folder replaced every run) is
//    written, holds its files and the marker and nothing else, and its data
//    files never hold "</" (which would close a <script> element).
#include <zlib.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "cli/pixel_history_encoder.hpp"
#include "cli/step_page.hpp"
#include "pipeline/gl/gl_context.hpp"
#include "script/gl_script.hpp"
#include "script/gl_script_runner.hpp"
#include "stepper/pixel_event_recorder.hpp"
#include "stepper/pixel_history_text.hpp"

namespace {

namespace fs = std::filesystem;

[[noreturn]] void broken(const std::string& what) {
  std::cerr << "page_fuzzer: " << what << "\n";
  std::abort();
}

std::string inflateAll(const std::string& z) {
  z_stream s{};
  if (inflateInit(&s) != Z_OK) broken("inflateInit");
  s.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(z.data()));
  s.avail_in = static_cast<uInt>(z.size());
  std::string out;
  char buf[65536];
  int rc = Z_OK;
  while (rc == Z_OK) {
    s.next_out = reinterpret_cast<Bytef*>(buf);
    s.avail_out = sizeof buf;
    rc = inflate(&s, Z_NO_FLUSH);
    out.append(buf, sizeof buf - s.avail_out);
  }
  inflateEnd(&s);
  if (rc != Z_STREAM_END || s.avail_in != 0) broken("a history chunk does not inflate whole");
  return out;
}

struct Reader {
  const std::string& b;
  std::size_t i = 0;
  std::uint64_t varint() {
    std::uint64_t v = 0;
    for (int shift = 0;; shift += 7) {
      if (i >= b.size() || shift > 63) broken("a varint runs past its stream");
      const auto byte = static_cast<std::uint8_t>(b[i++]);
      v |= std::uint64_t{byte & 0x7fu} << shift;
      if (!(byte & 0x80)) return v;
    }
  }
  std::int64_t signedValue() {
    const std::uint64_t v = varint();
    return static_cast<std::int64_t>(v >> 1) ^ -static_cast<std::int64_t>(v & 1);
  }
  std::uint8_t byte() {
    if (i >= b.size()) broken("a colour runs past its stream");
    return static_cast<std::uint8_t>(b[i++]);
  }
};

constexpr const char* kFields[] = {"{s0}", "{s1}", "{d0}", "{dz}", "{d1}", "{c0}", "{c1}"};

std::uint8_t fieldsOf(const std::string& text) {
  std::uint8_t f = 0;
  for (int i = 0; i < 7; ++i)
    if (text.find(kFields[i]) != std::string::npos) f |= static_cast<std::uint8_t>(1u << i);
  // Anything else in braces is a field the page cannot fill.
  for (std::size_t at = text.find('{'); at != std::string::npos; at = text.find('{', at + 1)) {
    const std::string name = text.substr(at, text.find('}', at) - at + 1);
    bool known = name == "{line}" || name == "{k}";
    for (const char* k : kFields) known = known || name == k;
    if (!known) broken("template '" + text + "' names " + name);
  }
  return f;
}

// stepper.js's text.replace(/\{(\w+)\}/g, ...).
std::string filled(const std::string& text, const std::vector<std::pair<std::string, std::string>>& values) {
  std::string o;
  for (std::size_t i = 0; i < text.size();) {
    bool done = false;
    for (const auto& [name, value] : values)
      if (text.compare(i, name.size(), name) == 0) {
        o += value;
        i += name.size();
        done = true;
        break;
      }
    if (!done) o += text[i++];
  }
  return o;
}

std::string rgba(const mpr::Rgba8& c) {
  return "(" + std::to_string(c[0]) + "," + std::to_string(c[1]) + "," + std::to_string(c[2]) + "," + std::to_string(c[3]) + ")";
}

constexpr int kTile = 8;

void checkHistoryRoundTrip(const mpr::Script& script, const mpr::HardwareProfile& profile, std::size_t budget) {
  mpr::GLContext gl(script.width, script.height, profile);
  mpr::cli::PixelHistoryEncoder history(script.width, script.height, kTile, budget);
  const int tilesX = (script.width + kTile - 1) / kTile;
  struct Raw {
    int tile, pixel, pass;
    std::string line;  // as mpr step --pixel prints it
  };
  std::vector<Raw> raw;
  mpr::PixelEventRecorder recorder(gl, gl.framebuffer().bounds(), [&](const mpr::PixelEvent& e, const mpr::FragmentState& s) {
    const std::size_t before = history.eventCount();
    history.add(e, s);
    if (history.eventCount() == before) return;  // not taken: the budget is spent
    const int tx = e.x / kTile, ty = e.y / kTile, tw = std::min(kTile, script.width - tx * kTile);
    raw.push_back({ty * tilesX + tx, (e.y - ty * kTile) * tw + (e.x - tx * kTile), e.pass, mpr::pixelEventLine(e, s)});
  });
  mpr::ScriptHooks hooks;
  hooks.beforeCall = [&](const mpr::ScriptCommand& c) { recorder.beforeCall(c); };
  hooks.onPass = [&](const mpr::ScriptCommand&) {
    recorder.startPass();
    history.passEnded(recorder.pass() - 1);
  };
  mpr::runScript(script, gl, hooks);
  recorder.finish();
  history.passEnded(recorder.pass());
  history.finish();

  std::vector<std::uint8_t> fields;
  for (const std::string& t : history.templates()) fields.push_back(fieldsOf(t));
  // Decode every tile as stepper.js does; compare with what was added to it.
  for (int t = 0; t < history.tileCount(); ++t) {
    std::string bytes;
    for (const std::string& c : history.tileChunks(t % tilesX, t / tilesX)) bytes += inflateAll(c);
    const int tx = t % tilesX, ty = t / tilesX;
    const int tw = std::min(kTile, script.width - tx * kTile), th = std::min(kTile, script.height - ty * kTile);
    const auto n = static_cast<std::size_t>(tw * th);
    std::vector<std::int64_t> stencil(n), depth(n), rank(n), lastLine(n, -1);
    std::vector<mpr::Rgba8> colour(n);
    std::int64_t pix = 0, dz = 0, pass = 0, line = 0;
    mpr::Rgba8 c1{};
    std::vector<const Raw*> expected;
    for (const Raw& e : raw)
      if (e.tile == t) expected.push_back(&e);
    std::size_t at = 0;
    Reader r{bytes};
    while (r.i < bytes.size()) {
      pix += r.signedValue();
      if (pix < 0 || pix >= static_cast<std::int64_t>(n)) broken("an event's pixel lies outside its tile");
      const std::uint64_t id = r.varint();
      if (id >= fields.size()) broken("an event names a template that does not exist");
      pass += static_cast<std::int64_t>(r.varint());
      line += static_cast<std::int64_t>(r.varint());
      const std::uint8_t f = fields[id];
      const auto p = static_cast<std::size_t>(pix);
      std::vector<std::pair<std::string, std::string>> v = {{"{line}", std::to_string(line)}};
      if (f & 1u) v.push_back({"{s0}", std::to_string(stencil[p] += r.signedValue())});
      if (f & 2u) v.push_back({"{s1}", std::to_string(stencil[p] += r.signedValue())});
      if (f & 4u) v.push_back({"{d0}", std::to_string(depth[p] += r.signedValue())});
      if (f & 8u) v.push_back({"{dz}", std::to_string(dz += r.signedValue())});
      if (f & 16u) v.push_back({"{d1}", std::to_string(depth[p] += r.signedValue())});
      if (f & 32u) {
        for (int k = 0; k < 4; ++k) colour[p][k] = static_cast<std::uint8_t>(colour[p][k] + r.byte());
        v.push_back({"{c0}", rgba(colour[p])});
      }
      if (f & 64u) {
        for (int k = 0; k < 4; ++k) c1[k] = static_cast<std::uint8_t>(c1[k] + r.byte());
        colour[p] = c1;
        v.push_back({"{c1}", rgba(c1)});
      }
      rank[p] = line == lastLine[p] ? rank[p] + 1 : 1;  // a call's fragments at a pixel are consecutive
      lastLine[p] = line;
      v.push_back({"{k}", std::to_string(rank[p])});
      if (at >= expected.size()) broken("a tile decodes to more events than it was given");
      const Raw& e = *expected[at++];
      if (pix != e.pixel || pass != e.pass) broken("an event decodes to another pixel or pass");
      const std::string shown = filled(history.templates()[id], v);
      if (shown != e.line) broken("the page would show '" + shown + "' where mpr step --pixel prints '" + e.line + "'");
    }
    if (at != expected.size()) broken("a tile decodes to fewer events than it was given");
  }
}

fs::path scratch;

void checkPage(const mpr::Script& script, const mpr::HardwareProfile& profile, std::size_t budget) {
  const fs::path dir = scratch / "page";
  mpr::cli::StepPageOptions o{dir.string(), "fuzz.gls", budget};
  if (mpr::cli::writeStepPage(script, profile, o) != 0) broken("the page was not written");
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.insert(entry.path().filename().string());
  for (const char* f : {"index.html", "passes.js", "frames.js", "history.js", ".mpr-page"})
    if (!names.count(f)) broken(std::string("the page lacks ") + f);
  for (const char* f : {"passes.js", "frames.js", "history.js"}) {
    std::ifstream in(dir / f, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    if (text.str().find("</") != std::string::npos) broken(std::string(f) + " holds \"</\"");
  }
  // Nothing beside the page: no temporary or old folder left behind.
  for (const auto& entry : fs::directory_iterator(scratch))
    if (entry.path().filename() != "page") broken("left beside the page: " + entry.path().string());
}

std::stringstream discarded;

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  char name[] = "/tmp/mpr-page-fuzzer-XXXXXX";
  if (!mkdtemp(name)) broken("mkdtemp");
  scratch = name;
  std::cout.rdbuf(discarded.rdbuf());  // the page's one-line summary, every run
  std::atexit([] { std::error_code ec; fs::remove_all(scratch, ec); });
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static constexpr std::size_t kBudgets[] = {0, 1 << 10, 16 << 10, std::size_t{64} << 20};
  const std::size_t budget = kBudgets[data[0] % 4];
  const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  mpr::Script script;
  try {
    script = mpr::parseScript(text, "fuzz.gls");
  } catch (const mpr::ScriptError&) {
    return 0;
  }
  if (script.width > 32 || script.height > 32 || script.callCount() > 2048) return 0;
  const auto profile = mpr::findProfile(script.profile.value_or("indigo"));
  if (!profile) return 0;
  checkHistoryRoundTrip(script, *profile, budget);
  checkPage(script, *profile, budget);
  discarded.str("");
  return 0;
}
