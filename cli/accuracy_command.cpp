#include "cli/accuracy_command.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>

#include "cli/page_folder.hpp"
#include "cli/scene_arguments.hpp"
#include "cli/scene_limits.hpp"
#include "reference/accuracy/accuracy_plot.hpp"
#include "reference/accuracy/accuracy_report.hpp"
#include "reference/accuracy/pipeline_measurement.hpp"
#include "reference/accuracy/sweep.hpp"
#include "reference/reference_renderer.hpp"
#include "scene/scene_loader.hpp"
#include "util/number_text.hpp"

namespace mpr::cli {
namespace {

constexpr const char* kGenerator = "mpr accuracy";

struct AccuracyOptions {
  std::string scene, reference, report;
  std::vector<std::string> vary, sets;
  bool product = false, quiet = false;
  int repeat = 3, width = 0, height = 0;
  TracerOptions tracer;  // the reference: --spp, --model, --bounces, --threads
  double budget = 600.0;
  SceneLimits limits;
};

struct UserError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

double seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

class AccuracyRun {
 public:
  explicit AccuracyRun(const AccuracyOptions& o) : o_(o), tty_(isatty(2) && !o.quiet) {}

  int run() {
    validateOptions();
    const std::vector<VaryKey> keys = varyKeys();
    for (const VaryKey& k : keys) report_.keys.push_back(k.key);
    base_ = load({}, "");
    report_.scene = base_.file;
    report_.width = base_.render.width;
    report_.height = base_.render.height;
    report_.repeat = o_.repeat;
    if (const std::string p = pageFolderProblem(o_.report, kGenerator); !p.empty())
      throw UserError("mpr accuracy: --report " + p);
    loadSettings(keys);
    Rgb8Image reference = referenceFromFile();
    checkBudget(reference.width == 0);
    if (reference.width == 0) reference = traceReference();
    measureAll(reference);
    writeReport(reference);
    return 0;
  }

 private:
  void validateOptions() const {
    if (!(o_.budget > 0.0)) throw UserError("mpr accuracy: --budget must be a positive number of seconds");
  }

  std::vector<VaryKey> varyKeys() const {
    if (o_.vary.empty()) return defaultSweep();
    std::vector<VaryKey> keys;
    try {
      for (const std::string& v : o_.vary) keys.push_back(parseVary(v));
    } catch (const std::invalid_argument& e) {
      throw UserError(std::string("mpr accuracy: ") + e.what());
    }
    return keys;
  }

  // Loads the scene with the base sets and `more`; `what` names the option in errors.
  Scene load(const std::vector<std::string>& more, const std::string& what) const {
    try {
      return loadCommandScene(o_.scene, o_.sets, o_.width, o_.height, more, o_.limits.confine);
    } catch (const SceneError& e) {
      std::string m = e.what();
      // A bad --vary value is reported by the loader as its --set
      // ("--set K=V:1:1: why"); say it as the option the user gave.
      if (const std::string set = "--set " + (more.empty() ? std::string() : more.back()) + ":";
          !what.empty() && m.rfind(set, 0) == 0 && m.find(": ", set.size()) != std::string::npos)
        m = m.substr(m.find(": ", set.size()) + 2);
      throw UserError(what.empty() ? m : "mpr accuracy: " + what + ": " + m);
    }
  }

  void loadSettings(const std::vector<VaryKey>& keys) {
    std::vector<std::string> seen;
    for (const SweepSetting& s : expandSweep(keys, o_.product)) {
      Scene scene = load(s.sets(), "--vary " + s.label());
      // One reference image for every setting: a setting of another size
      // is refused now, not after the sweep.
      if (scene.render.width != base_.render.width || scene.render.height != base_.render.height)
        throw UserError("mpr accuracy: --vary " + s.label() + ": renders " + std::to_string(scene.render.width) + "x" +
                        std::to_string(scene.render.height) + ", but every setting is compared with one reference of " +
                        std::to_string(base_.render.width) + "x" + std::to_string(base_.render.height) +
                        " (give the size with --width/--height instead)");
      const std::string fp = sceneFingerprint(scene);
      if (std::find(seen.begin(), seen.end(), fp) != seen.end()) continue;
      seen.push_back(fp);
      AccuracyRow row;
      row.label = s.label();
      for (const VaryKey& k : keys) {
        std::string v = "(scene)";
        for (const auto& [key, value] : s.overrides)
          if (key == k.key) v = value;
        if (v == "(scene)")
          if (const auto sv = sceneValue(scene, k.key)) v = *sv;
        row.values.push_back(v);
      }
      rows_.push_back(row);
      scenes_.push_back(std::move(scene));
    }
    singlePassScene_ = load(singlePassSets(), "the single-pass baseline");
  }

  Rgb8Image referenceFromFile() {
    if (o_.reference.empty()) return {};
    Rgb8Image im;
    try {
      im = readRgb8Image(o_.reference);
    } catch (const std::exception& e) {
      throw UserError("mpr accuracy: --reference: " + std::string(e.what()));
    }
    if (im.width != base_.render.width || im.height != base_.render.height)
      throw UserError("mpr accuracy: --reference " + o_.reference + " is " + std::to_string(im.width) + "x" +
                      std::to_string(im.height) + ", the scene renders " + std::to_string(base_.render.width) + "x" +
                      std::to_string(base_.render.height) + " (give --width/--height or another reference)");
    report_.reference = "the file " + o_.reference;
    return im;
  }

  ReferenceOptions referenceOptions() const {
    ReferenceOptions r;
    r.samplesPerPixel = o_.tracer.spp;
    r.model = o_.tracer.model == "physical" ? ShadingModel::Physical : ShadingModel::Pipeline;
    r.bounces = o_.tracer.bounces;
    r.threads = o_.tracer.threads;
    return r;
  }

  // Before anything long starts: one single-pass render calibrates what a
  // pass costs on this machine, a 1-sample trace of a sixteenth of the
  // pixels what the reference costs; the planner's pass counts (culling off,
  // so an upper bound) give each setting's estimate.
  void checkBudget(bool withReference) {
    const PipelineMeasurement calib = measureWithinLimits(singlePassScene_, 1);
    const double perPass = calib.seconds / std::max(1.0, predictedPasses(singlePassScene_));
    double total = calib.seconds * o_.repeat, worst = -1.0;
    std::size_t worstRow = 0;
    for (std::size_t i = 0; i < rows_.size(); ++i) {
      rows_[i].estimatedSeconds = perPass * predictedPasses(scenes_[i]);
      total += rows_[i].estimatedSeconds * o_.repeat;
      if (rows_[i].estimatedSeconds > worst) worst = rows_[i].estimatedSeconds, worstRow = i;
    }
    double referenceEstimate = 0.0;
    if (withReference) {
      Scene probe = base_;
      probe.render.width = std::max(1, base_.render.width / 4);
      probe.render.height = std::max(1, base_.render.height / 4);
      ReferenceOptions r = referenceOptions();
      r.samplesPerPixel = 1;
      const auto t0 = std::chrono::steady_clock::now();
      renderReference(probe, r);
      referenceEstimate = seconds(t0) * 16.0 * o_.tracer.spp;
      total += referenceEstimate;
    }
    if (total <= o_.budget) return;
    std::ostringstream m;
    m << "mpr accuracy: the sweep would take about " << fixedText(total, 0) << " s, over --budget " << fixedText(o_.budget, 0)
      << " s (" << rows_.size() << " settings x " << o_.repeat << " runs";
    if (withReference) m << ", the reference about " << fixedText(referenceEstimate, 0) << " s";
    m << "). The most costly setting is " << rows_[worstRow].label << ": about "
      << fixedText(rows_[worstRow].estimatedSeconds, 1) << " s a run, " << fixedText(predictedPasses(scenes_[worstRow]), 0)
      << " passes predicted by the planner. Drop it, lower --repeat, or raise --budget.";
    throw UserError(m.str());
  }

  Rgb8Image traceReference() {
    ReferenceOptions r = referenceOptions();
    if (tty_) r.progress = [](int done, int rows) {
      std::cerr << "\raccuracy: reference, row " << done << " of " << rows << "   " << std::flush;
    };
    const auto t0 = std::chrono::steady_clock::now();
    const ReferenceImage im = renderReference(base_, r);
    report_.referenceSeconds = seconds(t0);
    report_.reference = std::to_string(o_.tracer.spp) + " spp, " + o_.tracer.model + " model, " +
                        (o_.tracer.bounces < 0 ? std::string("bounces until below 1/512") : std::to_string(o_.tracer.bounces) + " bounces");
    if (tty_) std::cerr << "\r" << std::string(60, ' ') << "\r";
    if (!o_.quiet) std::cerr << "accuracy: reference traced in " << fixedText(report_.referenceSeconds, 2) << " s\n";
    return quantiseReference(im);
  }

  // A setting whose render passes --max-passes stops the sweep, nothing written.
  PipelineMeasurement measureWithinLimits(const Scene& scene, int repeat) const {
    try {
      return measurePipeline(scene, repeat, passLimitWatch(o_.limits));
    } catch (const PassLimitReached& stop) {
      throw UserError("mpr accuracy: " + passLimitMessage(scene, stop, o_.limits));
    }
  }

  void measure(AccuracyRow& row, const Scene& scene, const Rgb8Image& reference, const std::string& name) {
    const PipelineMeasurement m = measureWithinLimits(scene, o_.repeat);
    row.seconds = m.seconds;
    row.views = m.views;
    row.lightPasses = m.lightPasses;
    row.shadowPasses = m.shadowPasses;
    row.glCalls = m.glCalls;
    row.fragments = m.fragments;
    row.error = compareLuminance(m.image, reference);
    row.image = name + ".png";
    row.difference = name + "-difference.png";
    files_.emplace_back(row.image, encodePng(m.image));
    files_.emplace_back(row.difference, encodePng(luminanceDifferenceImage(m.image, reference)));
  }

  void measureAll(const Rgb8Image& reference) {
    report_.singlePass.label = "single pass";
    report_.singlePass.values.assign(report_.keys.size(), "");
    measure(report_.singlePass, singlePassScene_, reference, "single-pass");
    for (std::size_t i = 0; i < rows_.size(); ++i) {
      if (tty_)
        std::cerr << "\raccuracy: setting " << i + 1 << " of " << rows_.size() << " (" << rows_[i].label << ")"
                  << std::string(20, ' ') << std::flush;
      char name[32];
      std::snprintf(name, sizeof name, "setting-%02zu", i);
      measure(rows_[i], scenes_[i], reference, name);
      if (!o_.quiet && !tty_)
        std::cerr << "accuracy: " << rows_[i].label << ": " << fixedText(rows_[i].seconds, 3) << " s, "
                  << fixedText(rows_[i].error.rmsPercent, 2) << " % RMS\n";
    }
    if (tty_) std::cerr << "\r" << std::string(80, ' ') << "\r";
    report_.rows = rows_;
  }

  void writeReport(const Rgb8Image& reference) {
    report_.referenceImage = "reference.png";
    files_.emplace_back("reference.png", encodePng(reference));
    const std::string svg = accuracyPlotSvg(report_);
    files_.emplace_back("plot.svg", svg);
    files_.emplace_back("plot.png", accuracyPlotPng(report_));
    files_.emplace_back("results.csv", resultsCsv(report_));
    files_.emplace_back("results.json", resultsJson(report_));
    files_.emplace_back("report.html", reportHtml(report_, svg));
    writePageFolder(o_.report, kGenerator, files_);
    if (!o_.quiet) {
      std::cerr << "accuracy: " << report_.rows.size() << " settings of " << report_.scene << "; single pass "
                << fixedText(report_.singlePass.error.rmsPercent, 2) << " % RMS; report in " << o_.report << "/report.html\n";
    }
  }

  const AccuracyOptions& o_;
  bool tty_;
  Scene base_, singlePassScene_;
  std::vector<Scene> scenes_;
  std::vector<AccuracyRow> rows_;
  AccuracyReport report_;
  std::vector<PageFile> files_;
};

}  // namespace

void addAccuracyCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<AccuracyOptions>();
  CLI::App* c = app.add_subcommand("accuracy", "Measure what accuracy costs: a sweep of settings against the reference");
  c->footer(
      "Renders the pipeline once per setting (one --vary key at a time around the scene's own values, or every\n"
      "combination with --product; without --vary: render.recursion_depth 0..3, render.shadow_recursion_depth\n"
      "0..2, render.light_bounces 1..3, render.shadows, render.refraction_map, render.tessellation 1, 0.5, 0.25,\n"
      "render.antialias_samples 4, 16, render.soft_shadow_samples 4, 16), times each (median of --repeat), and\n"
      "measures it against the ray-traced reference (mpr reference) and the single-pass baseline: RMS of\n"
      "luminance over the reference's luminance range (1997 paper, section 7.4). Writes DIR/results.csv,\n"
      "results.json, report.html, plot.svg, plot.png and the images. A sweep estimated to take longer than\n"
      "--budget is refused before it starts.");
  c->add_option("scene", o->scene, "scene file (YAML); none measures the default scene");
  c->add_option("--vary", o->vary, "KEY=V1,V2,... a scene key and its values (repeatable)");
  c->add_flag("--product", o->product, "render every combination of the --vary values");
  c->add_option("--reference", o->reference, "compare with this image (PNG/TIFF/EXR, e.g. from mpr reference)");
  addTracerOptions(*c, o->tracer);
  c->add_option("--repeat", o->repeat, "pipeline runs per setting; the median is reported (default 3)")
      ->check(CLI::Range(1, 1000));
  c->add_option("--width", o->width, "image width (overrides render.width)")->check(CLI::Range(1, 16384));
  c->add_option("--height", o->height, "image height (overrides render.height)")->check(CLI::Range(1, 16384));
  c->add_option("--set", o->sets, "override a scene value for every setting: key.path=value (repeatable)");
  c->add_option("--budget", o->budget, "refuse a sweep estimated to take longer, in seconds (default 600)");
  c->add_option("--report", o->report, "folder to write the report to")->required();
  c->add_flag("-q,--quiet", o->quiet, "no progress or summary on standard error");
  addSceneLimitOptions(*c, o->limits);
  c->callback([o, &exitCode] {
    try {
      exitCode = AccuracyRun(*o).run();
    } catch (const UserError& e) {
      std::cerr << e.what() << "\n";
      exitCode = 2;
    } catch (const std::exception& e) {
      std::cerr << "mpr accuracy: " << e.what() << "\n";
      exitCode = 1;
    }
  });
}

}  // namespace mpr::cli
