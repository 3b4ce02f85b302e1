#pragma once
// The time-versus-error plot of a sweep (seconds across, RMS error up), the
// Pareto front joined and marked, the single-pass baseline as its own point:
// as SVG text, and as a PNG drawn with OpenImageIO.
#include <string>

#include "reference/accuracy/accuracy_report.hpp"

namespace mpr {

std::string accuracyPlotSvg(const AccuracyReport& r);
// The same plot as the bytes of a PNG file (drawn with OpenImageIO; its text
// needs the DejaVu Sans font, which scripts/setup installs: without it the
// plot is drawn without text).
std::string accuracyPlotPng(const AccuracyReport& r);

}  // namespace mpr
