// The report's forms: the Pareto front, the CSV columns, the plot's marks.
#include "reference/accuracy/accuracy_report.hpp"

#include <gtest/gtest.h>

#include "reference/accuracy/accuracy_plot.hpp"

namespace mpr {
namespace {

AccuracyRow row(const std::string& label, double seconds, double rms) {
  AccuracyRow r;
  r.label = label;
  r.seconds = seconds;
  r.error.rmsPercent = rms;
  r.values = {label};
  return r;
}

// (1 s, 9 %) (2 s, 5 %) (3 s, 6 %) (4 s, 2 %) (2 s, 5 %): the third is beaten
// by the second (faster and better); the fifth ties the second exactly and
// is not beaten by it, so both stay.
TEST(AccuracyReport, ParetoFront) {
  const std::vector<AccuracyRow> rows = {row("a", 1, 9), row("b", 2, 5), row("c", 3, 6), row("d", 4, 2),
                                         row("e", 2, 5)};
  EXPECT_EQ(paretoFront(rows), (std::vector<std::size_t>{0, 1, 3, 4}));
}

AccuracyReport sample() {
  AccuracyReport r;
  r.scene = "s.yaml";
  r.width = 4;
  r.height = 3;
  r.repeat = 3;
  r.keys = {"render.recursion_depth"};
  r.rows = {row("scene", 0.5, 4.0), row("render.recursion_depth=0", 0.1, 12.0)};
  r.rows[0].values = {"2"};
  r.rows[1].values = {"0"};
  r.rows[1].views = 1;
  r.singlePass = row("single pass", 0.05, 14.5);
  r.referenceSeconds = 10.0;
  return r;
}

TEST(AccuracyReport, CsvHasTheKeysThenTheMeasures) {
  const std::string csv = resultsCsv(sample());
  const std::string header = csv.substr(0, csv.find('\n'));
  EXPECT_EQ(header,
            "setting,render.recursion_depth,seconds,estimated_seconds,views,light_passes,shadow_passes,gl_calls,"
            "fragments,rms_percent,max_error_percent,share_over_5_percent,single_pass_rms_percent,"
            "speedup_over_reference");
  // 10 s of reference over 0.1 s of pipeline: 100x.
  EXPECT_NE(csv.find("\nrender.recursion_depth=0,0,0.1000,0.000,1,0,0,0,0,12.000,0.000,0.000,14.500,100.00\n"),
            std::string::npos)
      << csv;
}

TEST(AccuracyReport, JsonAndHtmlNameEverySetting) {
  const AccuracyReport r = sample();
  const std::string json = resultsJson(r), html = reportHtml(r, accuracyPlotSvg(r));
  for (const char* s : {"\"render.recursion_depth=0\"", "\"single_pass\"", "\"rms_percent\": 12.000"})
    EXPECT_NE(json.find(s), std::string::npos) << s;
  EXPECT_NE(html.find("<meta name=\"generator\" content=\"mpr accuracy\">"), std::string::npos);
  EXPECT_NE(html.find("<svg"), std::string::npos);
}

// Two settings and the baseline: two circles and a square; all three are on
// the front (each faster one is less accurate), joined by one line.
TEST(AccuracyReport, PlotMarksEverySettingAndTheFront) {
  const std::string svg = accuracyPlotSvg(sample());
  std::size_t circles = 0, pos = 0;
  while ((pos = svg.find("<circle", pos)) != std::string::npos) ++circles, ++pos;
  EXPECT_EQ(circles, 2u);
  EXPECT_NE(svg.find("fill=\"#d22\""), std::string::npos);
  EXPECT_NE(svg.find("<polyline"), std::string::npos);
  EXPECT_NE(svg.find("single pass"), std::string::npos);
  const std::string png = accuracyPlotPng(sample());
  EXPECT_EQ(png.substr(1, 3), "PNG");
}

}  // namespace
}  // namespace mpr
