#include "cli/conform_command.hpp"

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include "conformance/buffer_comparison.hpp"
#include "conformance/mesa_replayer.hpp"
#include "conformance/mpr_replay.hpp"
#include "framebuffer/image_writer.hpp"
#include "framebuffer/npy_writer.hpp"

namespace mpr::cli {
namespace {

struct ConformOptions {
  std::string script;
  std::string driver = "llvmpipe";
  std::string reportDir;
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
std::string differencePng(const BufferSet& m, const BufferAgreement& b, const BufferSet& g, const std::string& path) {
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
  writeColorImage(img, path);
  return path;
}

int runConform(const ConformOptions& o) {
  Script script;
  try {
    script = loadScript(o.script);
  } catch (const ScriptError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
  if (o.driver != "llvmpipe" && o.driver != "softpipe") {
    std::cerr << "mpr conform: --driver must be llvmpipe or softpipe\n";
    return 2;
  }
  MesaReplay mesa;
  try {
    mesa = replayOnMesa(script, o.driver);
  } catch (const MesaUnavailable& e) {
    std::cerr << "mpr conform: " << e.what() << "\n";
    return 2;
  }
  const MprReplay ours = replayOnMpr(script, mesaProfile());
  const ConformanceBounds bounds = boundsFor(script);

  std::cout << script.file << " on " << mesa.renderer << "\n"
            << "bounds: stencil " << (bounds.exactCoordinates ? "identical (exact coordinates)" : "identical on 99.9%")
            << ", depth within " << bounds.depthBound() << ", colour within " << bounds.colorBound()
            << (bounds.litOrFogged ? " (lighting or fog)" : "") << "\n";
  std::cout << std::left << std::setw(16) << "point" << std::setw(9) << "buffer" << std::setw(26) << "identical"
            << std::setw(10) << "max diff" << "verdict\n";
  bool all = true;
  std::ostringstream json, mismatchText;
  json << "{\n  \"script\": \"" << script.file << "\",\n  \"driver\": \"" << o.driver << "\",\n  \"renderer\": \""
       << mesa.renderer << "\",\n  \"points\": [\n";
  for (std::size_t k = 0; k < ours.snapshots.size(); ++k) {
    const PointAgreement p = compareBuffers(ours.snapshots[k], mesa.snapshots[k], bounds);
    all = all && p.conforms();
    json << "    {\"point\": \"" << p.point << "\", \"conforms\": " << (p.conforms() ? "true" : "false") << ", \"buffers\": [";
    bool firstBuffer = true;
    for (const BufferAgreement* b : {&p.stencil, &p.depth, &p.color}) {
      std::cout << std::setw(16) << p.point << std::setw(9) << b->buffer << std::setw(26)
                << (std::to_string(b->agree) + "/" + std::to_string(b->pixels) + " (" + percent(b->agree, b->pixels) + ")")
                << std::setw(10) << b->maxDiff << (b->conforms() ? "ok" : "OUT OF BOUNDS") << "\n";
      json << (firstBuffer ? "" : ", ") << "{\"buffer\": \"" << b->buffer << "\", \"pixels\": " << b->pixels
           << ", \"identical\": " << b->agree << ", \"within_bound\": " << b->withinBound << ", \"bound\": " << b->bound
           << ", \"max_diff\": " << b->maxDiff << ", \"conforms\": " << (b->conforms() ? "true" : "false") << "}";
      firstBuffer = false;
      for (const PixelMismatch& mm : b->first)
        mismatchText << "  " << p.point << " " << b->buffer << " (" << mm.x << "," << mm.y << "): mpr "
                     << values(b->buffer, mm.mpr) << ", mesa " << values(b->buffer, mm.mesa) << "\n";
      if (!o.reportDir.empty() && b->agree != b->pixels) {
        std::filesystem::create_directories(o.reportDir);
        differencePng(ours.snapshots[k], *b, mesa.snapshots[k],
                      (std::filesystem::path(o.reportDir) / (p.point + "-" + b->buffer + "-diff.png")).string());
      }
    }
    json << "]}" << (k + 1 < ours.snapshots.size() ? "," : "") << "\n";
  }
  if (!mismatchText.str().empty()) std::cout << "first mismatches:\n" << mismatchText.str();
  if (ours.glErrors != mesa.glErrors) {
    std::cout << "GL errors differ:\n";
    for (const auto& e : ours.glErrors) std::cout << "  mpr  " << e << "\n";
    for (const auto& e : mesa.glErrors) std::cout << "  mesa " << e << "\n";
  }
  json << "  ],\n  \"gl_errors_agree\": " << (ours.glErrors == mesa.glErrors ? "true" : "false")
       << ",\n  \"conforms\": " << (all ? "true" : "false") << "\n}\n";
  if (!o.reportDir.empty()) {
    std::filesystem::create_directories(o.reportDir);
    writeFileAtomically((std::filesystem::path(o.reportDir) / "summary.json").string(), json.str());
  }
  std::cout << (all ? "conforms" : "does NOT conform") << "\n";
  return all ? 0 : 1;
}

}  // namespace

void addConformCommand(CLI::App& app, int& exitCode) {
  auto opts = std::make_shared<ConformOptions>();
  CLI::App* c = app.add_subcommand("conform", "Run a GL script on MPR and on Mesa (OSMesa) and compare every buffer");
  c->footer(
      "Both run the script with the mesa profile (RGBA8, depth 24, stencil 8, accumulation 4x16).\n"
      "Every @snapshot and the final buffers are compared: per buffer the identical pixels, the\n"
      "largest difference and the verdict against the bounds in the README. Exit status 0 when\n"
      "the script conforms, 1 when it does not, 2 for a bad script or no Mesa.");
  c->add_option("script", opts->script, "GL script to run")->required();
  c->add_option("--driver", opts->driver, "Mesa driver: llvmpipe (default) or softpipe");
  c->add_option("--report", opts->reportDir, "write summary.json and difference images here");
  c->callback([opts, &exitCode] { exitCode = runConform(*opts); });
}

}  // namespace mpr::cli
