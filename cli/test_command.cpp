#include "cli/test_command.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "cli/junit_xml.hpp"
#include "cli/output_set.hpp"
#include "cli/scene_limits.hpp"
#include "cli/scene_test.hpp"
#include "framebuffer/image_writer.hpp"
#include "script/gl_script.hpp"
#include "scene/scene_loader.hpp"
#include "stepper/script_test.hpp"

namespace mpr::cli {
namespace {

namespace fs = std::filesystem;

struct TestOptions {
  std::vector<std::string> inputs;
  std::string profile;
  std::string junit;
  std::string report;
  SceneLimits limits;  // the scenes': their meshes and the passes of their renders
};

// Every line after the first indented, so a multi-line explanation reads as
// part of its script's line.
std::string indentAfterFirst(const std::string& text, const std::string& indent) {
  std::string o;
  for (char c : text) {
    o += c;
    if (c == '\n') o += indent;
  }
  return o;
}

std::string indentAll(const std::string& text, const std::string& indent) {
  std::string o;
  bool start = true;
  for (char c : text) {
    if (start) o += indent;
    o += c;
    start = c == '\n';
  }
  return o;
}

bool isScene(const std::string& path) {
  const std::string ext = fs::path(path).extension().string();
  return ext == ".yaml" || ext == ".yml";
}

// FILE, or every .gls and scene (.yaml, .yml) under DIR (sorted, so the
// order never depends on the file system).
bool collect(const std::string& input, std::vector<std::string>& paths) {
  std::error_code ec;
  if (!fs::is_directory(input, ec)) {
    paths.push_back(input);
    return true;
  }
  std::vector<std::string> found;
  for (auto it = fs::recursive_directory_iterator(input, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec))
    if (it->is_regular_file() && (it->path().extension() == ".gls" || isScene(it->path().string())))
      found.push_back(it->path().string());
  if (ec) {
    std::cerr << "mpr test: cannot read " << input << ": " << ec.message() << "\n";
    return false;
  }
  if (found.empty()) {
    std::cerr << "mpr test: no .gls scripts or .yaml scenes in " << input << "\n";
    return false;
  }
  std::sort(found.begin(), found.end());
  paths.insert(paths.end(), found.begin(), found.end());
  return true;
}

int runTest(const TestOptions& o) {
  // Every script is parsed before the first runs: a script error stops
  // everything, with nothing written.
  std::vector<std::string> paths;
  for (const std::string& in : o.inputs)
    if (!collect(in, paths)) return 2;
  if (!o.profile.empty() && !findProfile(o.profile)) {
    std::cerr << "mpr test: unknown profile '" << o.profile << "' (known: indigo, mesa)\n";
    return 2;
  }
  // Scripts and scenes in one list, in the order given.
  struct Item {
    bool scene = false;
    Script script;
    Scene sceneData;
  };
  std::vector<Item> items;
  bool bad = false;
  for (const std::string& p : paths) {
    Item item;
    try {
      if (isScene(p)) {
        item.scene = true;
        std::vector<std::string> sets;
        if (!o.profile.empty()) sets.push_back("render.profile=" + o.profile);
        item.sceneData = loadSceneFile(p, sets, o.limits.confine);
      } else {
        item.script = loadScript(p);
      }
      items.push_back(std::move(item));
    } catch (const ScriptError& e) {
      std::cerr << e.what() << "\n";
      bad = true;
    } catch (const SceneError& e) {
      std::cerr << e.what() << "\n";
      bad = true;
    }
  }
  if (bad) return 2;
  // The outputs, checked before any test runs: a report or JUnit file must
  // not replace a script or scene it tests, nor each other.
  OutputSet outputs("test");
  for (const Item& it : items) {
    if (it.scene) outputs.addSceneInputs(it.sceneData);
    else outputs.addInput("the script", it.script.file);
  }
  if (!o.junit.empty()) outputs.addFile("--junit", o.junit);
  if (!o.report.empty()) outputs.addFolder("--report", o.report, {}, ".png");  // <script>.line<N>.png
  if (const std::string problem = outputs.problem(); !problem.empty()) {
    std::cerr << problem << "\n";
    return 2;
  }
  std::vector<HardwareProfile> profiles;
  for (const Item& it : items) {
    const std::string name = it.scene ? it.sceneData.render.profile
                                      : (o.profile.empty() ? it.script.profile.value_or("indigo") : o.profile);
    const auto profile = findProfile(name);
    if (!profile) {
      std::cerr << "mpr test: unknown profile '" << name << "' (known: indigo, mesa)\n";
      return 2;
    }
    profiles.push_back(*profile);
  }

  std::size_t passed = 0, failed = 0;
  bool sceneErrors = false;
  std::vector<JUnitCase> cases;
  struct Difference {
    std::string name;
    int width, height;
    std::vector<std::uint8_t> rgb;
  };
  std::vector<Difference> differences;
  for (std::size_t i = 0; i < items.size(); ++i) {
    const std::string file = items[i].scene ? items[i].sceneData.file : items[i].script.file;
    JUnitCase jc;
    jc.name = fs::path(file).filename().string();
    jc.classname = fs::path(file).parent_path().string();
    std::replace(jc.classname.begin(), jc.classname.end(), '/', '.');
    if (jc.classname.empty()) jc.classname = ".";
    if (items[i].scene) {
      // A scene: its expectations, read at their passes of the render.
      SceneTestResult r;
      try {
        r = runSceneTest(items[i].sceneData, passLimitWatch(o.limits));
      } catch (const PassLimitReached& stop) {
        r.errors.push_back(passLimitMessage(items[i].sceneData, stop, o.limits));
      }
      if (r.errors.empty() && r.passed) {
        ++passed;
        std::cout << "ok   " << file << " (" << r.expectations << " expectation" << (r.expectations == 1 ? "" : "s")
                  << ")\n";
        cases.push_back(std::move(jc));
        continue;
      }
      ++failed;
      jc.outcome = JUnitCase::Outcome::Failed;
      if (!r.errors.empty()) {
        sceneErrors = true;
        std::cout << "FAIL " << r.errors.front() << "\n";
        for (std::size_t k = 1; k < r.errors.size(); ++k) std::cout << "     " << r.errors[k] << "\n";
        jc.message = r.errors.front();
        for (const std::string& e : r.errors) jc.text += e + "\n";
      } else {
        std::cout << "FAIL " << r.where << "\n" << sceneFailureText(r, "     ");
        jc.message = r.where + ": " + r.message.substr(0, r.message.find('\n'));
        jc.text = r.message + "\n" + r.history;
        differences.push_back({fs::path(file).stem().string() + ".line" + std::to_string(r.line) + ".png", r.width,
                               r.height, r.difference});
      }
      cases.push_back(std::move(jc));
      continue;
    }
    const Script& s = items[i].script;
    const ScriptTestResult r = runScriptTest(s, profiles[i]);
    if (r.passed) {
      ++passed;
      std::cout << "ok   " << s.file << " (" << r.probes << " probe" << (r.probes == 1 ? "" : "s") << ")\n";
    } else {
      ++failed;
      const std::string where = s.file + ":" + std::to_string(r.failed->line) + ": " + r.failed->label;
      std::cout << "FAIL " << where << "\n"
                << "     " << indentAfterFirst(r.message, "     ") << "\n"
                << indentAll(r.history, "     ");
      jc.outcome = JUnitCase::Outcome::Failed;
      jc.message = where + ": " + r.message.substr(0, r.message.find('\n'));
      jc.text = r.message + "\n" + r.history;
      differences.push_back({fs::path(s.file).stem().string() + ".line" + std::to_string(r.failed->line) + ".png",
                             r.width, r.height, r.difference});
    }
    cases.push_back(std::move(jc));
  }
  std::cout << passed << " passed, " << failed << " failed\n";

  try {
    if (!o.junit.empty()) outputs.write(o.junit, junitXml("mpr test", cases));
    if (!o.report.empty()) {
      outputs.createFolder(o.report);
      for (const Difference& d : differences)
        writeRgbImage(outputs.open((fs::path(o.report) / d.name).string()), d.width, d.height, d.rgb.data());
    }
    outputs.commit();
  } catch (const std::exception& e) {
    std::cerr << "mpr test: " << e.what() << "\n";
    return 2;
  }
  return sceneErrors ? 2 : failed == 0 ? 0 : 1;
}

}  // namespace

void addTestCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<TestOptions>();
  CLI::App* c = app.add_subcommand("test", "Run GL scripts with probes (@expect) and scenes with expect: as tests");
  c->footer(
      "Runs every script (a folder: every .gls and .yaml under it, sorted), evaluates its @expect and\n"
      "@expect-picture probes in order (docs/reference/gl-script-directives.md) and prints one line per\n"
      "script: ok, or FAIL with the first probe that does not hold, the expected and found values,\n"
      "and the history of its first failing pixel up to the probe (as mpr step --pixel words it).\n"
      "Then 'N passed, N failed'. Exit status 0 when every script passes, 1 when one fails, 2 for a\n"
      "script error (every script is parsed first; nothing runs or is written then).\n"
      "A scene (.yaml) runs as a test of its expect: list (docs/reference/scene-format.md): one line per scene,\n"
      "ok or FAIL with the first expectation that does not hold in the render's order, the pass it\n"
      "was read at and its pixel's history; an after: that matched no pass is a located error (exit 2).\n"
      "--junit FILE: JUnit XML, one testcase per script. --report DIR: a difference image per failing\n"
      "probe, DIR/<script>.line<N>.png (probed pixels that hold white, those that do not red, the\n"
      "rest of the window dark grey).");
  c->add_option("inputs", o->inputs, "GL scripts (.gls), scenes (.yaml) or folders of them")->required();
  c->add_option("--profile", o->profile, "hardware profile: indigo or mesa; overrides @profile and render.profile");
  c->add_option("--junit", o->junit, "write JUnit XML to FILE");
  c->add_option("--report", o->report, "write a difference image per failing probe into DIR");
  addSceneLimitOptions(*c, o->limits);
  c->callback([o, &exitCode] { exitCode = runTest(*o); });
}

}  // namespace mpr::cli
