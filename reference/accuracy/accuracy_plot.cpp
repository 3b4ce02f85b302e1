#include "reference/accuracy/accuracy_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "util/image_io.hpp"

namespace mpr {
namespace {

// Everything both forms draw, in pixels of a 720x480 canvas (y down).
struct PlotPoint {
  double x, y;
  std::string label, title;  // title: the hover text (SVG)
  bool front = false, baseline = false;
};
struct Tick {
  double pos;
  std::string text;
};
struct PlotLayout {
  static constexpr int W = 720, H = 480, left = 72, right = 24, top = 36, bottom = 60;
  std::vector<PlotPoint> points;
  std::vector<std::pair<double, double>> frontLine;
  std::vector<Tick> xTicks, yTicks;
  std::string xTitle, yTitle, title;
};

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

std::string escaped(const std::string& s) {
  std::string o;
  for (char c : s) o += c == '<' ? std::string("&lt;") : c == '&' ? std::string("&amp;") : std::string(1, c);
  return o;
}

double niceStep(double range) {
  const double raw = range / 5.0, p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * p >= raw) return m * p;
  return 10.0 * p;
}

PlotLayout layout(const AccuracyReport& r) {
  PlotLayout L;
  std::vector<const AccuracyRow*> all;
  for (const AccuracyRow& w : r.rows) all.push_back(&w);
  all.push_back(&r.singlePass);
  double tMin = 1e300, tMax = 0.0, eMax = 0.0;
  for (const AccuracyRow* w : all) {
    tMin = std::min(tMin, std::max(w->seconds, 1e-4));
    tMax = std::max(tMax, std::max(w->seconds, 1e-4));
    eMax = std::max(eMax, w->error.rmsPercent);
  }
  // Seconds on a log scale when they span a decade or more (Table 3 spans 20x).
  const bool logX = tMax / tMin >= 10.0;
  double x0, x1;
  if (logX) {
    x0 = std::floor(std::log10(tMin));
    x1 = std::ceil(std::log10(tMax));
    for (double d = x0; d <= x1 + 1e-9; d += 1.0)
      for (double m : {1.0, 2.0, 5.0})
        if (d + std::log10(m) <= x1 + 1e-9) L.xTicks.push_back({d + std::log10(m), num(m * std::pow(10.0, d))});
  } else {
    const double step = niceStep(std::max(tMax, 1e-3));
    x0 = 0.0;
    x1 = std::ceil(tMax * 1.05 / step) * step;
    for (double t = 0.0; t <= x1 + 1e-12; t += step) L.xTicks.push_back({t, num(t)});
  }
  const double yStep = niceStep(std::max(eMax, 0.5));
  const double y1 = std::ceil(eMax * 1.08 / yStep) * yStep + (eMax == 0.0 ? yStep : 0.0);
  for (double e = 0.0; e <= y1 + 1e-12; e += yStep) L.yTicks.push_back({e, num(e)});
  const double pw = L.W - L.left - L.right, ph = L.H - L.top - L.bottom;
  const auto px = [&](double t) {
    const double v = logX ? std::log10(std::max(t, 1e-4)) : t;
    return L.left + (v - x0) / (x1 - x0) * pw;
  };
  const auto py = [&](double e) { return L.top + ph - e / y1 * ph; };
  for (Tick& t : L.xTicks) t.pos = L.left + (t.pos - x0) / (x1 - x0) * pw;
  for (Tick& t : L.yTicks) t.pos = py(t.pos);
  // The front over every setting and the single pass (itself a setting:
  // the fastest, usually the least accurate).
  std::vector<AccuracyRow> withBaseline = r.rows;
  withBaseline.push_back(r.singlePass);
  const std::vector<std::size_t> front = paretoFront(withBaseline);
  for (std::size_t i = 0; i < withBaseline.size(); ++i) {
    const AccuracyRow& w = withBaseline[i];
    const bool f = std::find(front.begin(), front.end(), i) != front.end(), baseline = i == r.rows.size();
    const std::string label = baseline ? "single pass" : "#" + std::to_string(i);
    L.points.push_back({px(w.seconds), py(w.error.rmsPercent), label,
                        baseline ? "" : escaped(label + " " + w.label + ": " + num(w.seconds) + " s, " +
                                                num(w.error.rmsPercent) + " %"),
                        f, baseline});
  }
  std::vector<std::size_t> sorted = front;
  std::sort(sorted.begin(), sorted.end(),
            [&](std::size_t a, std::size_t b) { return withBaseline[a].seconds < withBaseline[b].seconds; });
  for (std::size_t i : sorted) L.frontLine.emplace_back(L.points[i].x, L.points[i].y);
  L.xTitle = logX ? "pipeline seconds (median, log scale)" : "pipeline seconds (median)";
  L.yTitle = "RMS luminance error, % of range";
  L.title = r.scene + ": time against error (Pareto front in red)";
  return L;
}

}  // namespace

std::string accuracyPlotSvg(const AccuracyReport& r) {
  const PlotLayout L = layout(r);
  std::ostringstream o;
  o.precision(6);
  const int x1 = L.W - L.right, y1 = L.H - L.bottom;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << L.W << "\" height=\"" << L.H << "\" viewBox=\"0 0 "
    << L.W << " " << L.H << "\" font-family=\"DejaVu Sans, sans-serif\" font-size=\"12\">\n"
    << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  for (const Tick& t : L.xTicks)
    o << "<line x1=\"" << t.pos << "\" y1=\"" << L.top << "\" x2=\"" << t.pos << "\" y2=\"" << y1
      << "\" stroke=\"#e4e4e4\"/><text x=\"" << t.pos << "\" y=\"" << y1 + 16 << "\" text-anchor=\"middle\">" << t.text
      << "</text>\n";
  for (const Tick& t : L.yTicks)
    o << "<line x1=\"" << L.left << "\" y1=\"" << t.pos << "\" x2=\"" << x1 << "\" y2=\"" << t.pos
      << "\" stroke=\"#e4e4e4\"/><text x=\"" << L.left - 6 << "\" y=\"" << t.pos + 4 << "\" text-anchor=\"end\">"
      << t.text << "</text>\n";
  o << "<rect x=\"" << L.left << "\" y=\"" << L.top << "\" width=\"" << x1 - L.left << "\" height=\"" << y1 - L.top
    << "\" fill=\"none\" stroke=\"#444\"/>\n";
  if (!L.frontLine.empty()) {
    o << "<polyline fill=\"none\" stroke=\"#d22\" stroke-width=\"1.5\" points=\"";
    for (const auto& [x, y] : L.frontLine) o << x << "," << y << " ";
    o << "\"/>\n";
  }
  for (const PlotPoint& p : L.points) {
    if (p.baseline)
      o << "<rect x=\"" << p.x - 4 << "\" y=\"" << p.y - 4 << "\" width=\"8\" height=\"8\" fill=\"#888\"/>";
    else
      o << "<circle cx=\"" << p.x << "\" cy=\"" << p.y << "\" r=\"4\" fill=\"" << (p.front ? "#d22" : "#27c") << "\"><title>" << p.title << "</title></circle>";
    // Labels on the front and the baseline only: clustered points would hide each other's.
    if (p.front || p.baseline)
      o << "<text x=\"" << p.x + 6 << "\" y=\"" << p.y - 6 << "\" font-size=\"11\">" << p.label << "</text>";
    o << "\n";
  }
  o << "<text x=\"" << (L.left + x1) / 2 << "\" y=\"" << L.H - 18 << "\" text-anchor=\"middle\">" << L.xTitle
    << "</text>\n<text transform=\"translate(18," << (L.top + y1) / 2 << ") rotate(-90)\" text-anchor=\"middle\">"
    << L.yTitle << "</text>\n<text x=\"" << L.left << "\" y=\"22\" font-size=\"14\">";
  o << escaped(L.title) << "</text>\n</svg>\n";
  return o.str();
}

std::string accuracyPlotPng(const AccuracyReport& r) {
  const PlotLayout L = layout(r);
  std::vector<CanvasOp> ops;
  using K = CanvasOp::Kind;
  const auto op = [&](K kind, int x0, int y0, int x1, int y1, const float (&c)[3]) {
    CanvasOp o;
    o.kind = kind, o.x0 = x0, o.y0 = y0, o.x1 = x1, o.y1 = y1;
    for (int i = 0; i < 3; ++i) o.rgb[i] = c[i];
    ops.push_back(o);
  };
  const float grid[3] = {0.9f, 0.9f, 0.9f}, ink[3] = {0.13f, 0.13f, 0.13f}, red[3] = {0.82f, 0.13f, 0.13f},
              blue[3] = {0.15f, 0.45f, 0.8f}, grey[3] = {0.53f, 0.53f, 0.53f};
  const auto text = [&](int x, int y, const std::string& s, int size, int align = -1) {
    op(K::Text, x, y, 0, 0, ink);
    ops.back().text = s, ops.back().size = size, ops.back().align = align;
  };
  const int x1 = L.W - L.right, y1 = L.H - L.bottom;
  for (const Tick& t : L.xTicks) {
    op(K::Line, int(t.pos), L.top, int(t.pos), y1, grid);
    text(int(t.pos), y1 + 18, t.text, 12, 0);
  }
  for (const Tick& t : L.yTicks) {
    op(K::Line, L.left, int(t.pos), x1, int(t.pos), grid);
    text(L.left - 6, int(t.pos) + 4, t.text, 12, 1);
  }
  op(K::Box, L.left, L.top, x1, y1, ink);
  for (std::size_t i = 1; i < L.frontLine.size(); ++i)
    op(K::Line, int(L.frontLine[i - 1].first), int(L.frontLine[i - 1].second), int(L.frontLine[i].first),
       int(L.frontLine[i].second), red);
  for (const PlotPoint& p : L.points) {
    op(K::FilledBox, int(p.x) - 3, int(p.y) - 3, int(p.x) + 3, int(p.y) + 3, p.baseline ? grey : p.front ? red : blue);
    if (p.front || p.baseline) text(int(p.x) + 6, int(p.y) - 6, p.label, 11);
  }
  text((L.left + x1) / 2, L.H - 16, L.xTitle, 13, 0);
  text(L.left, 22, L.title, 14);
  // The y title, sideways.
  op(K::TextUp, 4, (L.top + y1) / 2 - 150, 0, 0, ink);
  ops.back().text = L.yTitle, ops.back().size = 13;
  return drawCanvasPng(L.W, L.H, ops);
}

}  // namespace mpr
