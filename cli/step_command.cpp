#include "cli/step_command.hpp"

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "algorithms/gl_command_stream.hpp"
#include "algorithms/scene_renderer.hpp"
#include "pipeline/gl_script_runner.hpp"
#include "pipeline/gl_state_json.hpp"
#include "scene/scene_loader.hpp"

namespace mpr::cli {
namespace {

struct StepOptions {
  std::string input;
  std::string pixel;
  int state = -1;
};

// A script, or the trace of a scene's render read back as one.
Script loadInput(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext != ".yaml" && ext != ".yml") return loadScript(path);
  const Scene scene = loadSceneFile(path);
  GLContext gl(scene.render.width, scene.render.height, *findProfile(scene.render.profile));
  GLCommandStream stream(gl, true);
  renderScene(scene, stream);
  return parseScript(stream.trace(), path + " (its render's GL calls)");
}

std::string bits8(unsigned v) {
  std::string s;
  for (int b = 7; b >= 0; --b) s += ((v >> b) & 1) ? '1' : '0';
  return s;
}

std::string rgba(const Rgba8& c) {
  return "(" + std::to_string(c[0]) + "," + std::to_string(c[1]) + "," + std::to_string(c[2]) + "," +
         std::to_string(c[3]) + ")";
}

std::string stencilTestText(const StencilState& s, unsigned before) {
  if (!s.enabled) return "stencil test off";
  std::ostringstream o;
  o << "stencil " << compareFuncName(s.func) << " (" << s.ref << " & 0x" << std::hex << s.valueMask << std::dec
    << " vs " << before << " & 0x" << std::hex << s.valueMask << std::dec << ")";
  return o.str();
}

int runStep(const StepOptions& o) {
  Script script;
  try {
    script = loadInput(o.input);
  } catch (const ScriptError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  } catch (const SceneError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
  const auto profile = findProfile(script.profile.value_or("indigo"));
  int px = -1, py = -1;
  if (!o.pixel.empty()) {
    char extra = 0;
    if (std::sscanf(o.pixel.c_str(), "%d,%d%c", &px, &py, &extra) != 2 || px < 0 || py < 0 || px >= script.width ||
        py >= script.height) {
      std::cerr << "mpr step: --pixel must be X,Y inside the " << script.width << "x" << script.height
                << " window (origin bottom-left), not '" << o.pixel << "'\n";
      return 2;
    }
  }
  GLContext gl(script.width, script.height, *profile);

  // Passes: 0 is everything before the first @pass.
  std::vector<std::string> labels = {"(before the first @pass)"};
  std::vector<int> firstLine = {1};
  for (const ScriptCommand& c : script.commands)
    if (c.kind == ScriptCommand::Kind::Pass) {
      labels.push_back(c.label);
      firstLine.push_back(c.line);
    }
  if (o.state >= static_cast<int>(labels.size())) {
    std::cerr << "mpr step: --state " << o.state << " is past the last pass (" << labels.size() - 1 << ")\n";
    return 2;
  }

  int pass = 0;
  std::optional<std::string> stateAtEnd;
  std::ostringstream history;
  const ScriptCommand* current = nullptr;
  int fragmentsThisCall = 0;
  struct PixelValues {
    unsigned stencil;
    std::uint32_t depth;
    Rgba8 color;
    bool operator==(const PixelValues&) const = default;
  } before{};
  auto read = [&] { return PixelValues{gl.stencilAt(px, py), gl.depthAt(px, py), gl.colorAt(px, py)}; };
  bool passHeaderPrinted = false;
  auto header = [&] {
    if (passHeaderPrinted) return;
    history << "pass " << pass << " \"" << labels[static_cast<std::size_t>(pass)] << "\"\n";
    passHeaderPrinted = true;
  };
  // Changes not made by fragments (clears, accumulation returns) are reported per call.
  auto closeCall = [&] {
    if (px < 0 || !current) return;
    const PixelValues now = read();
    if (fragmentsThisCall == 0 && !(now == before)) {
      header();
      history << "  line " << current->line << " " << glCallName(current->call) << ": stencil " << before.stencil
              << " -> " << now.stencil << ", depth " << before.depth << " -> " << now.depth << ", colour "
              << rgba(before.color) << " -> " << rgba(now.color) << "\n";
    }
  };
  if (px >= 0)
    gl.fragmentObserver = [&](const FragmentEvent& e) {
      if (e.x != px || e.y != py) return;
      ++fragmentsThisCall;
      header();
      const FragmentState& s = gl.fragmentState();
      history << "  line " << current->line << " " << glCallName(current->call) << ", fragment " << fragmentsThisCall
              << ": " << stencilTestText(s.stencil, e.stencilBefore);
      switch (e.fate) {
        case FragmentFate::AlphaFailed: history << "; alpha test failed: nothing written"; break;
        case FragmentFate::StencilFailed:
          history << " failed; sfail " << stencilOpName(s.stencil.sfail);
          break;
        case FragmentFate::DepthFailed:
          history << (s.stencil.enabled ? " passed" : "") << "; depth " << compareFuncName(s.depth.func) << " ("
                  << e.depthIncoming << " vs " << e.depthBefore << ") failed";
          if (s.stencil.enabled) history << "; dpfail " << stencilOpName(s.stencil.dpfail);
          break;
        case FragmentFate::Written:
          history << (s.stencil.enabled ? " passed" : "");
          if (s.depth.enabled)
            history << "; depth " << compareFuncName(s.depth.func) << " (" << e.depthIncoming << " vs " << e.depthBefore
                    << ") passed";
          else
            history << "; depth test off";
          if (s.stencil.enabled) history << "; dppass " << stencilOpName(s.stencil.dppass);
          history << "; colour " << rgba(e.colorAfter);
          break;
      }
      history << "; stencil " << unsigned{e.stencilBefore} << " -> " << unsigned{e.stencilAfter} << "\n";
    };

  ScriptHooks hooks;
  hooks.beforeCall = [&](const ScriptCommand& c) {
    closeCall();
    current = &c;
    fragmentsThisCall = 0;
    if (px >= 0) before = read();
  };
  hooks.onPass = [&](const ScriptCommand&) {
    closeCall();
    current = nullptr;
    if (pass == o.state) stateAtEnd = glStateJson(gl);
    ++pass;
    passHeaderPrinted = false;
  };
  runScript(script, gl, hooks);
  closeCall();
  if (pass == o.state) stateAtEnd = glStateJson(gl);

  if (o.state >= 0) {
    std::cout << *stateAtEnd;
    return 0;
  }
  if (px >= 0) {
    const unsigned s = gl.stencilAt(px, py);
    std::cout << "pixel (" << px << "," << py << ") of " << script.file << "\n" << history.str() << "final: stencil "
              << s << " = 0x" << std::hex << s << std::dec << " = 0b" << bits8(s) << ", depth " << gl.depthAt(px, py)
              << ", colour " << rgba(gl.colorAt(px, py)) << "\n";
    return 0;
  }
  for (std::size_t i = 0; i < labels.size(); ++i)
    std::cout << "pass " << i << " (line " << firstLine[i] << "): " << labels[i] << "\n";
  return 0;
}

}  // namespace

void addStepCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<StepOptions>();
  CLI::App* c = app.add_subcommand("step", "Walk a GL script (or a scene's GL calls) pass by pass");
  c->footer(
      "With no option: the list of passes (pass 0 is what comes before the first @pass).\n"
      "--pixel X,Y (window coordinates, origin bottom-left): every fragment that reached the pixel,\n"
      "pass by pass, with the stencil and depth tests and the operation applied, and every clear or\n"
      "accumulation return that changed it; then its final stencil in decimal, hex and binary.\n"
      "--state N: the GL state at the end of pass N, as JSON.");
  c->add_option("input", o->input, "a GL script (.gls) or a scene (.yaml)")->required();
  auto pixel = c->add_option("--pixel", o->pixel, "X,Y: the pixel's history");
  c->add_option("--state", o->state, "N: the GL state at the end of pass N, as JSON")->excludes(pixel);
  c->callback([o, &exitCode] { exitCode = runStep(*o); });
}

}  // namespace mpr::cli
