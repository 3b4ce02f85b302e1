#include "cli/gl_command.hpp"

#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "cli/output_set.hpp"
#include "cli/thread_option.hpp"
#include "framebuffer/image_writer.hpp"
#include "framebuffer/npy_writer.hpp"
#include "pipeline/gl/gl_context.hpp"
#include "pipeline/gl/gl_enums.hpp"
#include "script/gl_script.hpp"
#include "script/script_read_ahead.hpp"
#include "script/script_text.hpp"
#include "script/gl_script_runner.hpp"
#include "framebuffer/script_probe.hpp"

namespace mpr::cli {
namespace {

struct GlOptions {
  std::string script;
  std::string profile;
  std::string dumpDir;
  bool dumpGiven = false;  // --dump '' is an error, not "no dump"
  bool quiet = false;
  int threads = 1;
};

int runGl(const GlOptions& o) {
  // The script runs as it is read (streamScript), and no parsed copy of the
  // whole script is held. Every script error is found before anything is
  // printed or written: with one thread a check of the whole script comes
  // first; with more the run starts from the header, and the reading ahead
  // (streamScriptAhead) is the check, in the same order: every message and
  // file waits until it has read the whole script (a script error ends the
  // run), so the text is parsed once, not twice.
  // The file is read a piece at a time by each pass (ScriptText), the same
  // open file each time: memory holds the buffers and a piece, not the text.
  const bool checkedFirst = o.threads <= 1;
  std::optional<ScriptText> text;
  Script script;
  try {
    text.emplace(ScriptText::ofFile(o.script));
    script = checkedFirst ? checkScript(*text, o.script) : scanScriptHeader(*text, o.script);
  } catch (const ScriptError& e) {
    std::cerr << e.what() << "\n";
    return 2;
  }
  // A script error goes before any other message: true when there is one
  // (printed). Where the run ends before the reading has, the rest is
  // checked now (the whole script: its first error).
  const auto reportScriptError = [&] {
    if (checkedFirst) return false;
    try {
      checkScript(*text, o.script);
    } catch (const ScriptError& e) {
      std::cerr << e.what() << "\n";
      return true;
    }
    return false;
  };
  std::string profileName = o.profile.empty() ? script.profile.value_or("indigo") : o.profile;
  const auto profile = findProfile(profileName);
  if (!profile) {
    if (reportScriptError()) return 2;
    std::cerr << "mpr gl: unknown profile '" << profileName << "' (known: indigo, mesa)\n";
    return 2;
  }
  OutputSet outputs("gl");
  outputs.addInput("the script", o.script);
  if (o.dumpGiven) {
    std::vector<std::string> names = npyDumpFileNames();
    names.push_back("color.png");
    outputs.addFolder("--dump", o.dumpDir, std::move(names), ".npy");  // and NAME-<buffer>.npy per snapshot
  }
  if (const std::string problem = outputs.problem(); !problem.empty()) {
    if (reportScriptError()) return 2;
    std::cerr << problem << "\n";
    return 2;
  }
  std::unique_ptr<GLContext> gl;
  try {
    gl = std::make_unique<GLContext>(script.width, script.height, *profile);
  } catch (const FramebufferSizeError& e) {
    if (reportScriptError()) return 2;
    std::cerr << o.script << ": " << e.what() << "\n";
    return 2;
  }
  gl->setThreads(o.threads);

  // GL error reports met before the whole script is known to have no error
  // are held back, then printed in order; after that, printed as they come.
  std::string heldReports;
  bool checked = checkedFirst;
  const auto releaseReports = [&] {
    std::cerr << heldReports;
    heldReports.clear();
    checked = true;
  };

  // Snapshots are kept in memory and written with the final dumps, so an
  // interrupted run leaves no partial set behind.
  std::vector<NamedBytes> files;
  std::size_t passes = 0;
  ScriptHooks hooks;
  hooks.onPass = [&](const ScriptCommand&) { ++passes; };
  hooks.onGLError = [&](const ScriptCommand& c, std::uint32_t e) {
    const std::string report = script.file + ":" + glErrorReport(c, e) + "\n";
    if (checked) std::cerr << report;
    else heldReports += report;
  };
  if (o.dumpGiven)
    hooks.onSnapshot = [&](const ScriptCommand& c, const GLContext& ctx) {
      for (NamedBytes& nb : framebufferNpyDumps(ctx.framebuffer()))
        files.push_back({c.label + "-" + nb.name + ".npy", std::move(nb.bytes)});
    };
  // A probe that does not hold ends the run (exit status 1, nothing written).
  struct ProbeFailed {};
  std::string probeReport;
  std::size_t probes = 0;
  hooks.onProbe = [&](const ScriptCommand& c, const GLContext& ctx) {
    ++probes;
    const ProbeOutcome p = evaluateProbe(*c.probe, ctx.framebuffer());
    if (p.passed) return;
    probeReport = script.file + ":" + std::to_string(c.line) + ": " + c.label + ": " + p.message + "\n";
    throw ProbeFailed{};
  };
  std::size_t errors = 0, calls = 0;
  try {
    ScriptExecutor executor(*gl, hooks);
    const auto run = [&](ScriptCommand&& c) {
      if (c.kind == ScriptCommand::Kind::Call) ++calls;
      executor.execute(c);
    };
    // With more than one thread the script is parsed ahead on one of them
    // while the calls run (the same commands in the same order).
    // A call goes to the executor as its parts, no command made for it.
    const auto runCall = [&](GLCall call, int line, std::span<const ScriptArg> args) {
      if (!executor.executeCall(call, line, args)) return false;
      ++calls;
      return true;
    };
    if (o.threads > 1) streamScriptAhead(*text, script, run, runCall);
    else streamScript(*text, script, run);
    releaseReports();
    errors = executor.finish();
  } catch (const ProbeFailed&) {
    if (reportScriptError()) return 2;
    releaseReports();
    std::cerr << probeReport;
    return 1;
  } catch (const ScriptError& e) {
    // Met by the stream only when nothing checked it first: the reading is
    // in the script's order, so this is its first error (as checkScript
    // reports it: tests/pipeline/script_stream_test.cpp).
    std::cerr << e.what() << "\n";
    return 2;
  }

  if (o.dumpGiven) {
    // Every file to its temporary first, then all renamed: a full disk or a
    // name the file system refuses leaves no part of a dump.
    try {
      for (NamedBytes& nb : framebufferNpyDumps(gl->framebuffer()))
        files.push_back({nb.name + ".npy", std::move(nb.bytes)});
      for (const NamedBytes& f : files) outputs.write((std::filesystem::path(o.dumpDir) / f.name).string(), f.bytes);
      writeColorImage(gl->framebuffer(), outputs.open((std::filesystem::path(o.dumpDir) / "color.png").string()));
      outputs.commit();
    } catch (const std::exception& e) {
      std::cerr << "mpr gl: " << e.what() << "\n";
      return 1;
    }
  }
  if (!o.quiet) {
    const PipelineCounters& c = gl->counters();
    std::cout << script.file << ": " << calls << " calls, " << passes << " passes, "
              << c.triangles << " triangles, " << c.fragmentsTested << " fragments tested, "
              << c.fragmentsWritten << " written, " << errors << " GL errors"
              << (probes ? ", " + std::to_string(probes) + " probes held" : "") << " (" << profile->name << ", "
              << script.width << "x" << script.height << ")\n";
  }
  return 0;
}

}  // namespace

void addGlCommand(CLI::App& app, int& exitCode) {
  auto opts = std::make_shared<GlOptions>();
  CLI::App* gl = app.add_subcommand("gl", "Run a GL script (.gls) on the emulated pipeline");
  gl->footer(
      "The script format is docs/reference/gl-script.md: one OpenGL 1.x call per line, @framebuffer W H,\n"
      "@profile NAME, @pass LABEL, @snapshot NAME. Script errors print FILE:LINE:COLUMN and exit\n"
      "with status 2 before anything is written. Calls GL rejects are reported as\n"
      "FILE:LINE: GL_INVALID_... in glX and the run goes on.\n"
      "Probes (@expect stencil|depth|color|accum X Y V..., ... all V..., ... rect X Y W H V...,\n"
      "@expect-picture stencil X Y ... @end; docs/reference/gl-script-directives.md) are evaluated where they\n"
      "stand: the first that does not hold prints FILE:LINE: the probe: expected and found, and\n"
      "exits with status 1, writing nothing. mpr test runs scripts with probes as tests.\n"
      "With --dump DIR: color.npy depth.npy stencil.npy accum.npy color.png, and\n"
      "NAME-<buffer>.npy for every @snapshot NAME.");
  gl->add_option("script", opts->script, "GL script to run")->required();
  gl->add_option("--profile", opts->profile, "hardware profile: indigo (default) or mesa; overrides @profile");
  auto dump = gl->add_option("--dump", opts->dumpDir, "write the final buffers (and snapshots) into this folder");
  gl->add_flag("-q,--quiet", opts->quiet, "print no summary line");
  addThreadsOption(*gl, opts->threads);
  gl->callback([opts, dump, &exitCode] {
    opts->dumpGiven = dump->count() > 0;
    exitCode = runGl(*opts);
  });
}

}  // namespace mpr::cli
