#include "reference/accuracy/accuracy_report.hpp"
#include "util/number_text.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace mpr {
namespace {

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string o = "\"";
  for (char c : s) o += c == '"' ? std::string("\"\"") : std::string(1, c);
  return o + "\"";
}

std::string jsonString(const std::string& s) {
  std::string o = "\"";
  for (unsigned char c : s) {
    if (c == '"' || c == '\\') o += '\\', o += static_cast<char>(c);
    else if (c < 0x20) { char b[8]; std::snprintf(b, sizeof b, "\\u%04x", c); o += b; }
    else o += static_cast<char>(c);
  }
  return o + "\"";
}

std::string html(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '<') o += "&lt;";
    else if (c == '>') o += "&gt;";
    else if (c == '&') o += "&amp;";
    else if (c == '"') o += "&quot;";
    else o += c;
  }
  return o;
}

double speedup(const AccuracyReport& r, const AccuracyRow& row) {
  return r.referenceSeconds > 0.0 && row.seconds > 0.0 ? r.referenceSeconds / row.seconds : 0.0;
}

// The numeric columns after the keys, in the order of results.csv.
struct Column {
  const char* name;
  std::string (*value)(const AccuracyReport&, const AccuracyRow&);
};
const Column kColumns[] = {
    {"seconds", [](const AccuracyReport&, const AccuracyRow& w) { return fixedText(w.seconds, 4); }},
    {"estimated_seconds", [](const AccuracyReport&, const AccuracyRow& w) { return fixedText(w.estimatedSeconds, 3); }},
    {"views", [](const AccuracyReport&, const AccuracyRow& w) { return std::to_string(w.views); }},
    {"light_passes", [](const AccuracyReport&, const AccuracyRow& w) { return std::to_string(w.lightPasses); }},
    {"shadow_passes", [](const AccuracyReport&, const AccuracyRow& w) { return std::to_string(w.shadowPasses); }},
    {"gl_calls", [](const AccuracyReport&, const AccuracyRow& w) { return std::to_string(w.glCalls); }},
    {"fragments", [](const AccuracyReport&, const AccuracyRow& w) { return std::to_string(w.fragments); }},
    {"rms_percent", [](const AccuracyReport&, const AccuracyRow& w) { return fixedText(w.error.rmsPercent, 3); }},
    {"max_error_percent", [](const AccuracyReport&, const AccuracyRow& w) { return fixedText(w.error.maxErrorPercent, 3); }},
    {"share_over_5_percent",
     [](const AccuracyReport&, const AccuracyRow& w) { return fixedText(w.error.shareOver5Percent, 3); }},
    {"single_pass_rms_percent",
     [](const AccuracyReport& r, const AccuracyRow&) { return fixedText(r.singlePass.error.rmsPercent, 3); }},
    // Empty (JSON null) when the reference came from a file: its time is unknown.
    {"speedup_over_reference",
     [](const AccuracyReport& r, const AccuracyRow& w) { return r.referenceSeconds > 0 ? fixedText(speedup(r, w), 2) : ""; }},
};

}  // namespace

std::vector<std::size_t> paretoFront(const std::vector<AccuracyRow>& rows) {
  std::vector<std::size_t> front;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    bool dominated = false;
    for (std::size_t j = 0; j < rows.size() && !dominated; ++j) {
      const AccuracyRow &a = rows[j], &b = rows[i];
      dominated = j != i && a.seconds <= b.seconds && a.error.rmsPercent <= b.error.rmsPercent &&
                  (a.seconds < b.seconds || a.error.rmsPercent < b.error.rmsPercent);
    }
    if (!dominated) front.push_back(i);
  }
  return front;
}

std::string resultsCsv(const AccuracyReport& r) {
  std::ostringstream o;
  o << "setting";
  for (const std::string& k : r.keys) o << "," << csvField(k);
  for (const Column& c : kColumns) o << "," << c.name;
  o << "\n";
  for (const AccuracyRow& w : r.rows) {
    o << csvField(w.label);
    for (const std::string& v : w.values) o << "," << csvField(v);
    for (const Column& c : kColumns) o << "," << c.value(r, w);
    o << "\n";
  }
  return o.str();
}

std::string resultsJson(const AccuracyReport& r) {
  std::ostringstream o;
  const auto row = [&](const AccuracyRow& w, const std::string& indent) {
    o << "{\n" << indent << "  \"setting\": " << jsonString(w.label);
    for (std::size_t k = 0; k < r.keys.size() && k < w.values.size(); ++k)
      o << ",\n" << indent << "  " << jsonString(r.keys[k]) << ": " << jsonString(w.values[k]);
    for (const Column& c : kColumns) {
      const std::string v = c.value(r, w);
      o << ",\n" << indent << "  \"" << c.name << "\": " << (v.empty() ? "null" : v);
    }
    o << ",\n" << indent << "  \"image\": " << jsonString(w.image) << ",\n"
      << indent << "  \"difference\": " << jsonString(w.difference) << "\n" << indent << "}";
  };
  o << "{\n  \"scene\": " << jsonString(r.scene) << ",\n  \"width\": " << r.width << ",\n  \"height\": " << r.height
    << ",\n  \"repeat\": " << r.repeat << ",\n  \"reference\": " << jsonString(r.reference)
    << ",\n  \"reference_seconds\": " << fixedText(r.referenceSeconds, 3)
    << ",\n  \"reference_luminance_range\": [" << fixedText(r.singlePass.error.referenceMin, 6) << ", "
    << fixedText(r.singlePass.error.referenceMax, 6) << "]"
    << ",\n  \"error_measure\": \"RMS of Rec. 709 luminance (0.2126 R + 0.7152 G + 0.0722 B of the 8-bit values / 255, "
       "the reference quantised as the pipeline quantises) over the reference's luminance range, in percent\""
    << ",\n  \"keys\": [";
  for (std::size_t k = 0; k < r.keys.size(); ++k) o << (k ? ", " : "") << jsonString(r.keys[k]);
  o << "],\n  \"single_pass\": ";
  row(r.singlePass, "  ");
  o << ",\n  \"rows\": [";
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    o << (i ? ", " : "");
    row(r.rows[i], "    ");
  }
  o << "]\n}\n";
  return o.str();
}

std::string reportHtml(const AccuracyReport& r, const std::string& plotSvg) {
  const std::vector<std::size_t> front = paretoFront(r.rows);
  std::ostringstream o;
  o << "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><meta name=\"generator\" content=\"mpr accuracy\"><title>mpr accuracy: " << html(r.scene)
    << "</title>\n<style>\nbody{font:14px/1.4 system-ui,sans-serif;margin:1.5em;color:#222}\n"
       "table{border-collapse:collapse;font-size:12px}th,td{border:1px solid #ccc;padding:3px 7px;text-align:right}\n"
       "th{background:#eee;cursor:pointer;user-select:none}td:nth-child(2),th:nth-child(2){text-align:left}\n"
       "tr.pareto td{background:#eef8ee}.imgs{display:flex;flex-wrap:wrap;gap:12px}\n"
       "figure{margin:0}figcaption{font-size:12px;max-width:320px}img{width:320px;image-rendering:pixelated}\n"
       "</style></head><body>\n";
  o << "<h1>What accuracy costs: " << html(r.scene) << "</h1>\n<p>" << r.width << "&times;" << r.height
    << ", pipeline times " << (r.repeat > 1 ? "the median of " + std::to_string(r.repeat) + " runs" : std::string("of one run"))
    << ". Reference: " << html(r.reference);
  if (r.referenceSeconds > 0) o << ", " << fixedText(r.referenceSeconds, 2) << " s";
  o << ". Error: RMS of the luminance difference (Rec. 709, on the 8-bit values) over the reference's luminance "
       "range " << fixedText(r.singlePass.error.referenceMin, 3) << "&ndash;" << fixedText(r.singlePass.error.referenceMax, 3)
    << " (the 1997 paper's measure, &sect;7.4). Single pass (every multi-pass effect off): "
    << fixedText(r.singlePass.error.rmsPercent, 2) << " %. Rows on the Pareto front (no other setting both faster and more accurate) are green; click a heading to sort. Plot marks are the rows' numbers (#)."
    << "</p>\n";
  o << "<h2>Time against error</h2>\n" << plotSvg << "\n<h2>Settings</h2>\n<table id=\"t\"><thead><tr><th>#</th><th>setting</th>";
  for (const std::string& k : r.keys) o << "<th>" << html(k) << "</th>";
  for (const Column& c : kColumns) o << "<th>" << c.name << "</th>";
  o << "</tr></thead><tbody>\n";
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    const AccuracyRow& w = r.rows[i];
    const bool onFront = std::find(front.begin(), front.end(), i) != front.end();
    o << "<tr" << (onFront ? " class=\"pareto\"" : "") << "><td>" << i << "</td><td>" << html(w.label) << "</td>";
    for (const std::string& v : w.values) o << "<td>" << html(v) << "</td>";
    for (const Column& c : kColumns) o << "<td>" << c.value(r, w) << "</td>";
    o << "</tr>\n";
  }
  o << "</tbody></table>\n<h2>Images</h2>\n<p>Difference images: grey where the luminance agrees with the reference, "
       "red where the pipeline is brighter, blue where darker, saturated at 10 % of the range.</p>\n<div class=\"imgs\">\n";
  const auto figure = [&](const std::string& src, const std::string& caption) {
    o << "<figure><img src=\"" << html(src) << "\" alt=\"" << html(caption) << "\"><figcaption>" << html(caption)
      << "</figcaption></figure>\n";
  };
  figure(r.referenceImage, "reference (" + r.reference + ")");
  figure(r.singlePass.image, "single pass: " + fixedText(r.singlePass.error.rmsPercent, 2) + " % RMS");
  figure(r.singlePass.difference, "single pass, difference");
  o << "</div>\n";
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    const AccuracyRow& w = r.rows[i];
    o << "<h3>#" << i << " " << html(w.label) << "</h3>\n<div class=\"imgs\">\n";
    figure(w.image, "pipeline: " + fixedText(w.error.rmsPercent, 2) + " % RMS, " + fixedText(w.seconds, 3) + " s");
    figure(w.difference, "difference");
    figure(r.referenceImage, "reference");
    o << "</div>\n";
  }
  // A small sort on click; numbers compare as numbers.
  o << "<script>\ndocument.querySelectorAll('#t th').forEach((th,col)=>{let up=true;th.onclick=()=>{\n"
       "const body=document.querySelector('#t tbody');const rows=[...body.rows];\n"
       "rows.sort((a,b)=>{const x=a.cells[col].textContent,y=b.cells[col].textContent;\n"
       "const nx=parseFloat(x),ny=parseFloat(y);const c=isNaN(nx)||isNaN(ny)?x.localeCompare(y):nx-ny;return up?c:-c;});\n"
       "up=!up;rows.forEach(r=>body.appendChild(r));};});\n</script>\n</body></html>\n";
  return o.str();
}

}  // namespace mpr
