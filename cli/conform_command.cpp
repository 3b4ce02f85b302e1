#include "cli/conform_command.hpp"

#include "cli/output_set.hpp"
#include "cli/scene_limits.hpp"

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

#include "conformance/buffer_comparison.hpp"
#include "cli/thread_option.hpp"
#include "conformance/mesa_replayer.hpp"
#include "conformance/mpr_replay.hpp"
#include "conformance/random_script.hpp"
#include "framebuffer/image_writer.hpp"
#include "framebuffer/npy_writer.hpp"
#include "pipeline/gl/gl_context.hpp"

namespace mpr::cli {
namespace {

struct ConformOptions {
  std::vector<std::string> scripts;
  std::string driver = "llvmpipe";
  std::string reportDir;
  int random = 0;               // number of random scripts
  std::uint64_t seed = 1;       // first seed
  std::string family = "default";  // the random scripts' family
  bool quiet = false;           // only the summary table
  bool strict = false;          // known Mesa departures fail too
  bool exact = false;           // every buffer identical, no tolerance
  bool print = false;           // print the random scripts, run nothing
  double minWithin = 100.0;     // exit 0 when at least this percentage of scripts is within bounds
  int threads = 1;              // MPR's (--threads)
};

// Mesa 22.3's known departures from GL 1.1 that MPR can emulate, by the
// name of their reproducer (docs/explanation/mesa.md).
struct EmulatedDeparture {
  const char* name;
  unsigned bits;
};
constexpr EmulatedDeparture kEmulatedDepartures[] = {
    {"color3_alpha", kColor3KeepsAlpha},
    {"lighting_vertex_w", kLightingUndividedEye},
    {"fog_hint_fastest", kFogHintIgnored},
    {"scalar_call_vector_param", kScalarCallVectorParam},
    {"shininess0_attenuated", kShininess0Attenuated},
    {"projective_normal_matrix", kProjectiveNormalMatrix},
};

// Totals over many scripts, per buffer: the agreement table.
struct Totals {
  std::size_t scripts = 0, conforming = 0;
  std::map<std::string, std::size_t> pixels, identical;
  std::map<std::string, int> maxDiff;
  std::vector<std::string> failures;
};

std::string percent(std::size_t a, std::size_t n) {
  std::ostringstream o;
  o << std::fixed << std::setprecision(3) << (n ? 100.0 * static_cast<double>(a) / static_cast<double>(n) : 100.0) << "%";
  return o.str();
}

std::string values(const std::string& buffer, const std::array<int, 4>& v) {
  if (buffer != "color") return std::to_string(v[0]);
  return "(" + std::to_string(v[0]) + "," + std::to_string(v[1]) + "," + std::to_string(v[2]) + "," +
         std::to_string(v[3]) + ")";
}

// A difference image: MPR's colour dimmed to grey, mismatching pixels red.
Framebuffer differenceImage(const BufferSet& m, const BufferAgreement& b, const BufferSet& g) {
  Framebuffer img(m.width, m.height, mesaProfile());
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * m.width + x;
      bool differs;
      if (b.buffer == "color")
        differs = !std::equal(&m.color[i * 4], &m.color[i * 4 + 4], &g.color[i * 4]);
      else if (b.buffer == "depth")
        differs = m.depth[i] != g.depth[i];
      else
        differs = m.stencil[i] != g.stencil[i];
      const auto grey = static_cast<std::uint8_t>((m.color[i * 4] + m.color[i * 4 + 1] + m.color[i * 4 + 2]) / 12 + 32);
      img.color(x, y) = differs ? Rgba8{255, 0, 0, 255} : Rgba8{grey, grey, grey, 255};
    }
  return img;
}

// Compares one script; prints its report unless quiet. 0 conforms, 1 not, 2 no Mesa.
// With several scripts a report is written only for those out of bounds.
int conformScript(const Script& script, const ConformOptions& o, const std::string& reportDir, bool reportFailuresOnly,
                  Totals& totals) {
  std::vector<std::pair<std::size_t, BufferAgreement>> differing;  // difference images to write
  MesaReplay mesa;
  try {
    mesa = replayOnMesa(script, o.driver);
  } catch (const MesaUnavailable& e) {
    std::cerr << "mpr conform: " << e.what() << "\n";
    return 2;
  }
  const MprReplay ours = replayOnMpr(script, mesaProfile(), 0, o.threads);
  ConformanceBounds bounds = boundsFor(script);
  bounds.strict = o.strict;
  bounds.exact = o.exact;
  // Where MPR and Mesa disagree, replay MPR with each known departure of
  // Mesa's emulated: a pixel (or a GL error list) that then agrees differs
  // because of that departure.
  bool plainConforms = ours.glErrors == mesa.glErrors;
  for (std::size_t k = 0; k < ours.snapshots.size() && plainConforms; ++k)
    plainConforms = compareBuffers(ours.snapshots[k], mesa.snapshots[k], bounds, 0).conforms();
  std::vector<std::pair<std::string, MprReplay>> departureRuns;
  if (!plainConforms) {
    unsigned allBits = 0;
    for (const EmulatedDeparture& d : kEmulatedDepartures) {
      departureRuns.emplace_back(d.name, replayOnMpr(script, mesaProfile(), d.bits, o.threads));
      allBits |= d.bits;
    }
    // Last, all of them at once: a vertex lit at w != 1 under an attenuated
    // light shows two departures in one value.
    departureRuns.emplace_back("combined", replayOnMpr(script, mesaProfile(), allBits, o.threads));
  }
  const bool colourMaterialBack = !plainConforms && showsColourMaterialBackInBegin(script);
  std::string errorsDeparture;
  if (ours.glErrors != mesa.glErrors)
    for (const auto& [name, run] : departureRuns)
      if (run.glErrors == mesa.glErrors) {
        errorsDeparture = name;
        break;
      }
  std::ostringstream out;
  out << script.file << " on " << mesa.renderer << "\n"
            << (bounds.exact ? std::string("bounds: every buffer identical (--exact)")
                             : std::string("bounds: stencil ") +
                                   (bounds.exactCoordinates ? "identical (exact coordinates)" : "identical on 99.9%") +
                                   ", depth within " + std::to_string(bounds.depthBound()) + ", colour within " +
                                   std::to_string(bounds.colorBound()) + (bounds.litOrFogged ? " (lighting or fog)" : ""))
            << "\n";
  out << std::left << std::setw(16) << "point" << std::setw(9) << "buffer" << std::setw(26) << "identical"
            << std::setw(10) << "max diff" << "verdict\n";
  bool all = true;
  std::ostringstream json, mismatchText;
  json << "{\n  \"script\": \"" << script.file << "\",\n  \"driver\": \"" << o.driver << "\",\n  \"renderer\": \""
       << mesa.renderer << "\",\n  \"points\": [\n";
  for (std::size_t k = 0; k < ours.snapshots.size(); ++k) {
    std::vector<DepartureRun> runs;
    for (const auto& [name, run] : departureRuns) runs.push_back({name, &run.snapshots[k], false});
    if (colourMaterialBack) runs.push_back({"colour_material_back_in_begin", nullptr, true});
    const PointAgreement p = compareBuffers(ours.snapshots[k], mesa.snapshots[k], bounds, 10, runs);
    all = all && p.conforms();
    json << "    {\"point\": \"" << p.point << "\", \"conforms\": " << (p.conforms() ? "true" : "false") << ", \"buffers\": [";
    bool firstBuffer = true;
    for (const BufferAgreement* b : {&p.stencil, &p.depth, &p.color}) {
      totals.pixels[b->buffer] += b->pixels;
      totals.identical[b->buffer] += b->agree;
      totals.maxDiff[b->buffer] = std::max(totals.maxDiff[b->buffer], b->maxDiff);
      out << std::setw(16) << p.point << std::setw(9) << b->buffer << std::setw(26)
                << (std::to_string(b->agree) + "/" + std::to_string(b->pixels) + " (" + percent(b->agree, b->pixels) + ")")
                << std::setw(10) << b->maxDiff
                << (b->conforms() ? (b->explained && !o.strict ? "ok (known Mesa departure)" : "ok") : "OUT OF BOUNDS")
                << "\n";
      json << (firstBuffer ? "" : ", ") << "{\"buffer\": \"" << b->buffer << "\", \"pixels\": " << b->pixels
           << ", \"identical\": " << b->agree << ", \"within_bound\": " << b->withinBound << ", \"bound\": " << b->bound
           << ", \"max_diff\": " << b->maxDiff << ", \"conforms\": " << (b->conforms() ? "true" : "false") << "}";
      firstBuffer = false;
      for (const PixelMismatch& mm : b->first)
        mismatchText << "  " << p.point << " " << b->buffer << " (" << mm.x << "," << mm.y << "): mpr "
                     << values(b->buffer, mm.mpr) << ", mesa " << values(b->buffer, mm.mesa)
                     << (mm.departure.empty() ? "" : " - known Mesa departure (" + mm.departure + ")") << "\n";
      if (b->agree != b->pixels) differing.emplace_back(k, *b);
    }
    json << "], \"known_mesa_departures\": {";
    bool firstDeparture = true;
    for (const auto& [name, count] : p.departures) {
      out << std::setw(16) << p.point << "known Mesa departure (" << name << "): " << count << " pixels\n";
      json << (firstDeparture ? "" : ", ") << "\"" << name << "\": " << count;
      firstDeparture = false;
    }
    json << "}}" << (k + 1 < ours.snapshots.size() ? "," : "") << "\n";
  }
  if (!mismatchText.str().empty()) out << "first mismatches:\n" << mismatchText.str();
  if (ours.glErrors != mesa.glErrors) {
    if (o.strict || errorsDeparture.empty()) all = false;
    out << "GL errors differ" << (errorsDeparture.empty() ? "" : " - known Mesa departure (" + errorsDeparture + ")")
        << ":\n";
    for (const auto& e : ours.glErrors) out << "  mpr  " << e << "\n";
    for (const auto& e : mesa.glErrors) out << "  mesa " << e << "\n";
  }
  json << "  ],\n  \"gl_errors_agree\": " << (ours.glErrors == mesa.glErrors ? "true" : "false")
       << ",\n  \"conforms\": " << (all ? "true" : "false") << "\n}\n";
  if (!reportDir.empty() && (!all || !reportFailuresOnly)) {
    // One output writer, as every command's: files made from the folder's
    // held descriptor, renamed into place together.
    OutputSet outputs("conform");
    const std::filesystem::path dir(reportDir);
    outputs.createFolder(reportDir);
    for (const auto& [k, b] : differing)
      writeColorImage(differenceImage(ours.snapshots[k], b, mesa.snapshots[k]),
                      outputs.open((dir / (ours.snapshots[k].point + "-" + b.buffer + "-diff.png")).string()));
    outputs.write((dir / "summary.json").string(), json.str());
    if (!all) outputs.write((dir / "script.gls").string(), script.text);
    outputs.commit();
  }
  out << (all ? "conforms" : "does NOT conform") << "\n";
  ++totals.scripts;
  if (all) ++totals.conforming;
  else totals.failures.push_back(script.file);
  if (!o.quiet || !all) std::cout << out.str();
  return all ? 0 : 1;
}

int runConform(const ConformOptions& o) {
  if (o.driver != "llvmpipe" && o.driver != "softpipe") {
    std::cerr << "mpr conform: --driver must be llvmpipe or softpipe\n";
    return 2;
  }
  if (o.scripts.empty() && o.random == 0) {
    std::cerr << "mpr conform: give one or more scripts, or --random N\n";
    return 2;
  }
  const std::vector<std::string>& families = randomFamilies();
  if (std::find(families.begin(), families.end(), o.family) == families.end()) {
    std::cerr << "mpr conform: --family must be one of";
    for (const std::string& f : families) std::cerr << " " << f;
    std::cerr << "\n";
    return 2;
  }
  // Parse everything first: a bad script stops the run before anything is compared.
  std::vector<Script> scripts;
  try {
    for (const std::string& path : o.scripts) scripts.push_back(loadScript(path));
    for (int i = 0; i < o.random; ++i) {
      const std::uint64_t seed = o.seed + static_cast<std::uint64_t>(i);
      const std::string name = o.family == "default" ? "random-seed-" : "random-" + o.family + "-seed-";
      scripts.push_back(parseScript(randomFamilyScript(o.family, seed), name + std::to_string(seed) + ".gls"));
    }
  } catch (const ScriptError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
  if (o.print) {
    for (const Script& s : scripts) std::cout << "# " << s.file << "\n" << s.text;
    return 0;
  }
  // The report folders (one per script when there are several), checked
  // before anything runs: none may replace a script or share a file.
  const auto reportFolder = [&](std::size_t i) {
    std::string dir = o.reportDir;
    if (!dir.empty() && scripts.size() > 1)
      dir = (std::filesystem::path(dir) / std::filesystem::path(scripts[i].file).stem()).string();
    return dir;
  };
  if (!o.reportDir.empty()) {
    OutputSet outputs("conform");
    for (const std::string& path : o.scripts) outputs.addInput("the script", path);
    for (std::size_t i = 0; i < scripts.size(); ++i)
      outputs.addFolder("--report", reportFolder(i), {"summary.json", "script.gls"}, ".png");
    if (const std::string problem = outputs.problem(); !problem.empty()) {
      std::cerr << problem << "\n";
      return 2;
    }
  }
  Totals totals;
  int worst = 0;
  for (std::size_t i = 0; i < scripts.size(); ++i) {
    if (scripts.size() > 1 && isatty(2)) std::cerr << "\r[" << i + 1 << "/" << scripts.size() << "] " << std::flush;
    const int rc = conformScript(scripts[i], o, reportFolder(i), scripts.size() > 1, totals);
    if (rc == 2) return 2;
    worst = std::max(worst, rc);
  }
  if (scripts.size() > 1) {
    if (isatty(2)) std::cerr << "\r";
    std::cout << "\nagreement over " << totals.scripts << " scripts on " << o.driver << " (" << totals.conforming
              << " within bounds)\n"
              << std::left << std::setw(9) << "buffer" << std::setw(28) << "identical pixels" << "max diff\n";
    for (const std::string b : {"stencil", "depth", "color"})
      std::cout << std::setw(9) << b << std::setw(28)
                << (std::to_string(totals.identical[b]) + "/" + std::to_string(totals.pixels[b]) + " (" +
                    percent(totals.identical[b], totals.pixels[b]) + ")")
                << totals.maxDiff[b] << "\n";
    for (const std::string& f : totals.failures) std::cout << "out of bounds: " << f << "\n";
  }
  if (worst == 1 && o.minWithin < 100.0 &&
      100.0 * static_cast<double>(totals.conforming) >= o.minWithin * static_cast<double>(totals.scripts))
    return 0;
  return worst;
}

}  // namespace

void addConformCommand(CLI::App& app, int& exitCode) {
  auto opts = std::make_shared<ConformOptions>();
  CLI::App* c = app.add_subcommand("conform", "Run a GL script on MPR and on Mesa (OSMesa) and compare every buffer");
  c->footer(
      "Both run the script with the mesa profile (RGBA8, depth 24, stencil 8, accumulation 4x16).\n"
      "Every @snapshot and the final buffers are compared: per buffer the identical pixels, the\n"
      "largest difference and the verdict against the bounds (docs/reference/commands/conform.md). Exit status 0 when\n"
      "the script conforms, 1 when it does not, 2 for a bad script or no Mesa.");
  c->add_option("scripts", opts->scripts, "GL scripts to run");
  c->add_option("--random", opts->random, "also run N random scripts (seeded, dyadic coordinates)")
      ->check(CLI::Range(0, 100000000));
  c->add_option("--seed", opts->seed, "first seed of --random (default 1)")->check(wholeNumberFrom(0));
  c->add_option("--family", opts->family,
                "family of the --random scripts: default (dyadic, orthographic), perspective, matrices, "
                "primitives, lighting, fog, clip_planes, accumulation, mixed, fragment_ops");
  c->add_option("--min-within", opts->minWithin,
                 "exit 0 when at least this percentage of the scripts is within bounds (default 100)")
      ->check(CLI::Range(0.0, 100.0));
  c->add_flag("--print", opts->print, "print the --random scripts instead of running them");
  c->add_flag("-q,--quiet", opts->quiet, "print only scripts out of bounds and the table");
  c->add_flag("--strict", opts->strict, "known Mesa departures from GL 1.1 fail a script too");
  c->add_flag("--exact", opts->exact,
              "hold every buffer to identical bytes on every pixel instead of the documented bounds");
  c->add_option("--driver", opts->driver, "Mesa driver: llvmpipe (default) or softpipe")
      ->check(CLI::IsMember({"llvmpipe", "softpipe"}));
  addThreadsOption(*c, opts->threads);
  c->add_option("--report", opts->reportDir,
                 "write summary.json and difference images here (one folder per script when several)");
  c->callback([opts, &exitCode] { exitCode = runConform(*opts); });
}

}  // namespace mpr::cli
