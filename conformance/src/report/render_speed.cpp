// sections.speed in HTML and Markdown (sections.hpp). The renderers never throw on a section with
// missing fields: every read goes through str / arr / obj_at or checks the type.
#include "sections.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "common.hpp"
#include "markup.hpp"

namespace rotorcert::report::detail {

namespace {

double num(const json& obj, const char* key, double fallback = NAN) {
  return obj.is_object() && obj.contains(key) && obj[key].is_number() ? obj[key].get<double>() : fallback;
}
std::string num_text(const json& obj, const char* key) { return stat_text(obj.is_object() && obj.contains(key) ? obj[key] : json()); }
std::string ratio_text(double r) { return std::isfinite(r) ? fmt3(r) + "\u00d7" : "\u2014"; }
std::string percent_text(double f) { return std::isfinite(f) ? fmt3(100.0 * f) + " %" : "\u2014"; }
std::string gflops_text(double f) { return std::isfinite(f) ? fmt3(f * 1e-9) : "\u2014"; }

/// A frame time with its spread: "median (low-high, R runs)", or the median alone.
std::string spread_text(const json& spread) {
  const double m = num(spread, "median"), lo = num(spread, "low"), hi = num(spread, "high");
  if (!std::isfinite(m)) return "\u2014";
  const double reps = num(spread, "repetitions", 1);
  if (!(reps > 1) || !std::isfinite(lo) || !std::isfinite(hi)) return fmt3(m);
  return fmt3(m) + " (" + fmt3(lo) + "\u2013" + fmt3(hi) + ", " + fmt3(reps) + " runs)";
}
/// A ratio with its interval and verdict: "1.20\u00d7 [1.05\u20131.31] faster".
std::string compare_text(const json& claim, const char* ratio, const char* interval, const char* verdict) {
  std::string t = ratio_text(num(claim, ratio));
  if (claim.contains(interval) && claim[interval].is_array() && claim[interval].size() == 2 &&
      claim[interval][0].is_number() && claim[interval][1].is_number())
    t += " [" + fmt3(claim[interval][0].get<double>()) + "\u2013" + fmt3(claim[interval][1].get<double>()) + "]";
  const std::string v = str(claim, verdict);
  return v.empty() ? t : t + " " + v;
}

std::string target_verdict(const json& t) {
  if (!t.contains("met") || !t["met"].is_boolean()) return "not measured";
  if (t["met"].get<bool>()) return "met";
  return "missed by " + ratio_text(num(t, "missed_by"));
}

/// A parity row's measure: its slowdown against the baseline, or its excess in ns (SIMD-SINGLE).
std::string parity_measure_text(const json& r) {
  if (r.is_object() && r.contains("excess_ns")) {
    const double e = num(r, "excess_ns");
    return std::isfinite(e) ? (e >= 0 ? "+" : "") + fmt3(e) + " ns" : "\u2014";
  }
  return ratio_text(num(r, "slowdown"));
}
std::string parity_verdict(const json& r) {
  if (!r.is_object() || !r.contains("met") || !r["met"].is_boolean()) return "not measured";
  return r["met"].get<bool>() ? "met" : "missed";
}
/// "rotor_m1 float compose: 2.1x" for a family's worst row.
std::string parity_worst_text(const json& family) {
  const json& w = obj_at(family, "worst");
  if (!w.is_object() || w.empty()) return "\u2014";
  return str(w, "impl") + " " + str(w, "scalar") + " " + str(w, "what") + ": " + parity_measure_text(w);
}
const char* kParityIntro =
    "Issue 18's bars for each implementation against the quaternion code it is isomorphic to: the "
    "implementation's time over the baseline's (ns per element at 4096 for ops, the median frame for frames; "
    "SIMD-SINGLE: the extra ns of a one-element call over rotor_m2's), both from this run. A row exists only "
    "where both were measured (the quick run has no single-element calls).";

/// Rows of the ops list grouped: op -> (impl/scalar -> n -> row).
using OpIndex = std::map<std::string, std::map<std::string, std::map<long long, const json*>>>;
OpIndex index_ops(const json& section) {
  OpIndex idx;
  for (const json& r : arr(section, "ops"))
    idx[str(r, "op")][str(r, "impl") + " " + str(r, "scalar")][static_cast<long long>(num(r, "n", 0))] = &r;
  return idx;
}

struct Bar {
  std::string label, tip;
  double value;
  const char* style;  // "", " double" or " base"
};

/// A horizontal bar chart on a log-10 axis (values span decades: 2 ns to 2 us per element).
void bar_chart(std::ostream& out, const std::string& caption, const std::string& unit, const std::vector<Bar>& bars) {
  double lo = INFINITY, hi = 0;
  for (const Bar& b : bars)
    if (std::isfinite(b.value) && b.value > 0) lo = std::min(lo, b.value), hi = std::max(hi, b.value);
  if (!(hi > 0)) return;
  const double e0 = std::floor(std::log10(lo)), e1 = std::max(e0 + 1, std::ceil(std::log10(hi)));
  const double left = 190, plot = 420, row_h = 18, top = 8;
  const double axis_y = top + row_h * static_cast<double>(bars.size()) + 4;
  const double width = left + plot + 80, height = axis_y + 34;
  const auto x_of = [&](double v) { return left + plot * (std::log10(v) - e0) / (e1 - e0); };
  out << "<figure class=\"speed\"><figcaption>" << esc(caption) << "</figcaption>\n<svg role=\"img\" width=\""
      << px(width) << "\" height=\"" << px(height) << "\" viewBox=\"0 0 " << px(width) << " " << px(height)
      << "\" aria-label=\"" << esc(caption) << "\">\n";
  for (double e = e0; e <= e1; e += 1) {
    const double x = x_of(std::pow(10.0, e));
    out << "<line class=\"grid\" x1=\"" << px(x) << "\" y1=\"" << px(top) << "\" x2=\"" << px(x) << "\" y2=\""
        << px(axis_y) << "\"/><text x=\"" << px(x) << "\" y=\"" << px(axis_y + 13)
        << "\" font-size=\"10\" text-anchor=\"middle\">" << fmt3(std::pow(10.0, e)) << "</text>\n";
  }
  out << "<line class=\"axis\" x1=\"" << px(left) << "\" y1=\"" << px(axis_y) << "\" x2=\"" << px(left + plot)
      << "\" y2=\"" << px(axis_y) << "\"/><text x=\"" << px(left + plot / 2) << "\" y=\"" << px(axis_y + 28)
      << "\" font-size=\"11\" text-anchor=\"middle\">" << esc(unit) << " (log scale, shorter is faster)</text>\n";
  for (std::size_t i = 0; i < bars.size(); ++i) {
    const Bar& b = bars[i];
    const double y = top + row_h * static_cast<double>(i);
    const bool ok = std::isfinite(b.value) && b.value > 0;
    const double w = ok ? std::max(1.0, x_of(b.value) - left) : 0.0;
    out << "<g><title>" << esc(b.tip) << "</title><text x=\"" << px(left - 6) << "\" y=\"" << px(y + 13)
        << "\" font-size=\"11\" text-anchor=\"end\">" << esc(b.label) << "</text><rect class=\"bar" << b.style
        << "\" x=\"" << px(left) << "\" y=\"" << px(y + 3) << "\" width=\"" << px(w) << "\" height=\"" << px(row_h - 5)
        << "\"/><text x=\"" << px(left + w + 4) << "\" y=\"" << px(y + 13) << "\" font-size=\"11\">"
        << (ok ? fmt3(b.value) : "n/a") << "</text></g>\n";
  }
  out << "</svg></figure>\n";
}

/// Accuracy (max error in eps, log 2) against speed (ns/element, log 10), one point per table.
void scatter(std::ostream& out, const std::string& op, const std::vector<const json*>& points) {
  double x0 = INFINITY, x1 = 0, y1 = 1;
  for (const json* p : points) {
    const double x = num(*p, "ns_per_element"), y = num(*p, "max_eps");
    if (std::isfinite(x) && x > 0) x0 = std::min(x0, x), x1 = std::max(x1, x);
    if (std::isfinite(y)) y1 = std::max(y1, y);
  }
  if (!(x1 > 0)) return;
  const double ex0 = std::floor(std::log10(x0)), ex1 = std::max(ex0 + 1, std::ceil(std::log10(x1)));
  const double ey0 = -2, ey1 = std::max(1.0, std::ceil(std::log2(y1)));  // errors below 2^-2 eps sit on the floor
  const double left = 56, top = 10, w = 360, h = 200, width = left + w + 150, height = top + h + 40;
  const auto xo = [&](double v) { return left + w * (std::log10(v) - ex0) / (ex1 - ex0); };
  const auto yo = [&](double v) {
    return top + h - h * (std::clamp(std::log2(std::max(v, 0.25)), ey0, ey1) - ey0) / (ey1 - ey0);
  };
  out << "<figure class=\"scatter\"><figcaption>" << esc(op) << ": max error vs time at 4096 elements"
      << "</figcaption>\n<svg role=\"img\" width=\"" << px(width) << "\" height=\"" << px(height) << "\" viewBox=\"0 0 "
      << px(width) << " " << px(height) << "\" aria-label=\"accuracy versus speed of " << esc(op) << "\">\n";
  for (double e = ex0; e <= ex1; e += 1)
    out << "<line class=\"grid\" x1=\"" << px(xo(std::pow(10.0, e))) << "\" y1=\"" << px(top) << "\" x2=\""
        << px(xo(std::pow(10.0, e))) << "\" y2=\"" << px(top + h) << "\"/><text x=\"" << px(xo(std::pow(10.0, e)))
        << "\" y=\"" << px(top + h + 13) << "\" font-size=\"10\" text-anchor=\"middle\">" << fmt3(std::pow(10.0, e))
        << "</text>\n";
  const double ystep = ey1 - ey0 > 12 ? 4 : 2;
  for (double e = ey0; e <= ey1; e += ystep)
    out << "<line class=\"grid\" x1=\"" << px(left) << "\" y1=\"" << px(yo(std::pow(2.0, e))) << "\" x2=\""
        << px(left + w) << "\" y2=\"" << px(yo(std::pow(2.0, e))) << "\"/><text x=\"" << px(left - 4) << "\" y=\""
        << px(yo(std::pow(2.0, e)) + 4) << "\" font-size=\"10\" text-anchor=\"end\">" << fmt3(std::pow(2.0, e))
        << "</text>\n";
  out << "<line class=\"axis\" x1=\"" << px(left) << "\" y1=\"" << px(top + h) << "\" x2=\"" << px(left + w)
      << "\" y2=\"" << px(top + h) << "\"/><line class=\"axis\" x1=\"" << px(left) << "\" y1=\"" << px(top)
      << "\" x2=\"" << px(left) << "\" y2=\"" << px(top + h) << "\"/>\n<text x=\"" << px(left + w / 2) << "\" y=\""
      << px(top + h + 28) << "\" font-size=\"11\" text-anchor=\"middle\">ns per element (log)</text><text transform=\""
      << "translate(12 " << px(top + h / 2) << ") rotate(-90)\" font-size=\"11\" text-anchor=\"middle\">max error (&epsilon;, log)</text>\n";
  for (const json* p : points) {
    const double x = num(*p, "ns_per_element"), y = num(*p, "max_eps");
    if (!(std::isfinite(x) && x > 0)) continue;
    const bool failed = !std::isfinite(y);
    const double cy = failed ? top + 2 : yo(y);
    const std::string name = str(*p, "impl") + " " + str(*p, "scalar");
    out << "<g><title>" << esc(name + ": " + fmt3(x) + " ns, " + (failed ? "no finite max error" : fmt3(y) + " eps"))
        << "</title><circle class=\"bar" << (str(*p, "scalar") == "double" ? " double" : "") << "\" cx=\"" << px(xo(x))
        << "\" cy=\"" << px(cy) << "\" r=\"4\"/><text x=\"" << px(xo(x) + 6) << "\" y=\"" << px(cy + 4)
        << "\" font-size=\"10\">" << esc(name) << "</text></g>\n";
  }
  out << "</svg></figure>\n";
}

const char* kSizes[] = {"1", "64", "4096", "65536"};

/// "24 mul + 18 add + 1 div + 1 sqrt" of a generated_ops object (the nonzero terms).
std::string arithmetic_text(const json& g) {
  std::string out;
  for (const char* k : {"mul", "add", "div", "sqrt"}) {
    const double v = num(g, k, 0);
    if (v == 0) continue;
    out += (out.empty() ? "" : " + ") + fmt3(v) + " " + k;
  }
  return out.empty() ? "0" : out;
}

const char* kCountsIntro =
    "The generated rotor's arithmetic per element (its generator's count of the fast path, guards included) beside "
    "the quaternion formula's nominal flops (an FMA counts 2, a transcendental 20; the generated counts leave "
    "slerp's atan and sincos calls out) and the two tables' times at 4096. "
    "Where the counts match and the times do not, the gap is the implementation's, not the algebra's.";

}  // namespace

void render_speed_html(std::ostream& out, const json& s) {
  out << "<section class=\"speed\" id=\"section-speed\">\n<h2>Speed: operations, frame pipeline, roofline</h2>\n";
  if (!str(s, "note").empty()) {
    out << "<p class=\"muted\">" << esc(str(s, "note")) << "</p>\n</section>\n";
    return;
  }
  const json& m = obj_at(s, "machine");
  const json& roofs = obj_at(s, "roofs");
  out << "<p class=\"muted\">From <code>" << esc(str(s, "source")) << "</code>" << (str(s, "quick") == "true" ? " (quick run)" : "")
      << ", " << esc(str(s, "date")) << ": " << esc(str(m, "cpu_model")) << ", " << esc(str(m, "num_cpus")) << " CPUs at "
      << esc(str(m, "mhz_per_cpu")) << " MHz, Highway target " << esc(str(m, "hwy_target")) << ", compiler "
      << esc(str(m, "compiler")) << ". CPU time per element of one batched call on one thread; ratios are within this "
      << "run. Roofs of one core: peak FMA " << gflops_text(num(obj_at(roofs, "peak_flops"), "float")) << " GFLOP/s float, "
      << gflops_text(num(obj_at(roofs, "peak_flops"), "double")) << " GFLOP/s double; memory bandwidth "
      << gflops_text(num(obj_at(roofs, "bandwidth"), "read")) << " GB/s read, "
      << gflops_text(num(obj_at(roofs, "bandwidth"), "triad")) << " GB/s triad.</p>\n";
  for (const json& n : arr(s, "notes")) out << "<div class=\"note\">" << esc(n.is_string() ? n.get<std::string>() : dump(n)) << "</div>\n";

  out << "<h3>Targets (4096 float elements)</h3>\n<table class=\"speed-targets\">\n<thead><tr><th>Target</th><th>Kernel</th>"
         "<th>Baseline</th><th>Ratio</th><th>Required</th><th>Verdict</th></tr></thead>\n<tbody>\n";
  for (const json& t : arr(s, "targets")) {
    const std::string v = target_verdict(t);
    out << "<tr><td>" << esc(str(t, "what")) << "</td><td><code>" << esc(str(t, "kernel")) << "</code></td><td><code>"
        << esc(str(t, "baseline")) << "</code></td><td>" << ratio_text(num(t, "ratio")) << "</td><td>\u2265 "
        << ratio_text(num(t, "target")) << "</td><td><span class=\"badge oc-" << (v == "met" ? "PASS" : "FAIL") << "\">"
        << esc(v) << "</span></td></tr>\n";
  }
  out << "</tbody>\n</table>\n";

  // Parity families (issue 18), each with its rows folded away.
  const json& parity = obj_at(s, "parity");
  if (!arr(parity, "families").empty()) {
    out << "<h3>Parity with the quaternion code</h3>\n<p class=\"muted\">" << esc(kParityIntro)
        << "</p>\n<table class=\"speed-parity\">\n<thead><tr><th>Bar</th><th>Comparison</th><th>Required</th>"
           "<th>Met</th><th>Worst</th></tr></thead>\n<tbody>\n";
    for (const json& f : arr(parity, "families"))
      out << "<tr><td>" << esc(str(f, "id")) << "</td><td>" << esc(str(f, "what")) << "</td><td>" << esc(str(f, "bar"))
          << "</td><td>" << num_text(f, "met") << " of " << num_text(f, "rows") << "</td><td>"
          << esc(parity_worst_text(f)) << "</td></tr>\n";
    out << "</tbody>\n</table>\n";
    for (const json& f : arr(parity, "families")) {
      if (!(num(f, "rows", 0) > 0)) continue;
      out << "<details><summary>" << esc(str(f, "id")) << ": every row (" << esc(str(f, "unit"))
          << ")</summary>\n<table class=\"speed-parity-rows\">\n<thead><tr><th>Table</th><th>Scalar</th><th>Op or "
             "scene</th><th>Time</th><th>Baseline</th><th>Measure</th><th>Verdict</th></tr></thead>\n<tbody>\n";
      for (const json& r : arr(parity, "rows")) {
        if (str(r, "family") != str(f, "id")) continue;
        const std::string v = parity_verdict(r);
        out << "<tr><td><code>" << esc(str(r, "impl")) << "</code></td><td>" << esc(str(r, "scalar")) << "</td><td>"
            << esc(str(r, "what")) << "</td><td>" << num_text(r, "time") << "</td><td>" << num_text(r, "baseline")
            << "</td><td>" << esc(parity_measure_text(r)) << "</td><td><span class=\"badge oc-"
            << (v == "met" ? "PASS" : "FAIL") << "\">" << esc(v) << "</span></td></tr>\n";
      }
      out << "</tbody>\n</table>\n</details>\n";
    }
  }

  // Frame pipeline and the paper's claim.
  out << "<h3>Frame pipeline (sample two clips, blend, globals, skinning transforms, CPU skin)</h3>\n";
  if (arr(s, "frames").empty()) {
    out << "<p class=\"muted\">No frame benchmarks in this run.</p>\n";
  } else {
    out << "<p class=\"muted\">Frame times are medians over repeated runs, with their range. The fastest GA rotor is "
           "<em>faster</em> than a method only where its slowest run beats that method's fastest (the interval of the "
           "time ratio lies above 1), <em>slower</em> where the reverse holds, at <em>parity</em> where the ranges "
           "overlap.</p>\n";
    out << "<table class=\"speed-claim\">\n<thead><tr><th>Character</th><th>Scalar</th><th>QLB \u00b5s</th><th>DQB \u00b5s</th>"
           "<th>Fastest GA rotor</th><th>\u00b5s</th><th>vs QLB</th><th>vs DQB</th><th>Paper's claim</th></tr></thead>\n<tbody>\n";
    for (const json& c : arr(s, "paper_claim")) {
      const bool holds = str(c, "holds") == "true";
      out << "<tr><td>" << esc(str(c, "scene")) << "</td><td>" << esc(str(c, "scalar")) << "</td><td>"
          << esc(c.contains("qlb") ? spread_text(c["qlb"]) : num_text(c, "qlb_us")) << "</td><td>"
          << esc(c.contains("dqb") ? spread_text(c["dqb"]) : num_text(c, "dqb_us")) << "</td><td><code>"
          << esc(str(c, "rotor")) << "</code></td><td>"
          << esc(c.contains("rotor_spread") ? spread_text(c["rotor_spread"]) : num_text(c, "rotor_us")) << "</td><td>"
          << esc(compare_text(c, "vs_qlb", "vs_qlb_interval", "verdict_qlb")) << "</td><td>"
          << esc(compare_text(c, "vs_dqb", "vs_dqb_interval", "verdict_dqb")) << "</td><td><span class=\"badge oc-"
          << (holds ? "PASS" : "FAIL") << "\">" << (holds ? "holds" : "does not hold") << "</span></td></tr>\n";
    }
    out << "</tbody>\n</table>\n<div class=\"charts\">\n";
    std::map<std::string, std::vector<Bar>> per_scene;
    for (const json& f : arr(s, "frames"))
      per_scene[str(f, "scene")].push_back({str(f, "impl") + " " + str(f, "scalar") + " " + str(f, "technique"),
                                            str(f, "method") + ": " + num_text(f, "us_per_frame") + " \u00b5s per frame (pose " +
                                                num_text(f, "pose_us") + " \u00b5s), " +
                                                num_text(f, "joints") + " joints, " + num_text(f, "vertices") + " vertices",
                                            num(f, "us_per_frame"), str(f, "scalar") == "double" ? " double" : ""});
    for (auto& [scene, bars] : per_scene) {
      std::sort(bars.begin(), bars.end(), [](const Bar& a, const Bar& b) { return a.value < b.value; });
      bar_chart(out, "frame time, " + scene, "\u00b5s per frame", bars);
    }
    out << "</div>\n<div class=\"scroll\">\n<table class=\"speed-frames\">\n<thead><tr><th>Character</th><th>Method</th>"
           "<th>Table</th><th>Scalar</th><th>Technique</th><th>Joints</th><th>Vertices</th><th>\u00b5s per frame</th>"
           "<th>of which pose \u00b5s</th></tr></thead>\n<tbody>\n";
    for (const json& f : arr(s, "frames"))
      out << "<tr><td>" << esc(str(f, "scene")) << "</td><td>" << esc(str(f, "method")) << "</td><td><code>"
          << esc(str(f, "impl")) << "</code></td><td>" << esc(str(f, "scalar")) << "</td><td>" << esc(str(f, "technique"))
          << "</td><td>" << num_text(f, "joints") << "</td><td>" << num_text(f, "vertices") << "</td><td>"
          << num_text(f, "us_per_frame") << "</td><td>" << num_text(f, "pose_us") << "</td></tr>\n";
    out << "</tbody>\n</table>\n</div>\n";
  }

  // Per-operation charts at 4096 and the full table.
  const OpIndex idx = index_ops(s);
  std::map<std::string, double> base4096;  // "glm_slerp float" -> ns
  for (const json& b : arr(s, "baselines"))
    if (num(b, "n", 0) == 4096) base4096[str(b, "name") + " " + str(b, "scalar")] = num(b, "ns_per_element");
  out << "<h3>Operations: ns per element at 4096 (in cache)</h3>\n<div class=\"charts\">\n";
  for (const auto& [op, tables] : idx) {
    std::vector<Bar> bars;
    for (const auto& table_sizes : tables) {
      // Named, not a structured binding: clang 14 cannot capture those in the lambda below.
      const std::string& table = table_sizes.first;
      const auto& sizes = table_sizes.second;
      const auto it = sizes.find(4096);
      if (it == sizes.end()) continue;
      bars.push_back({table, table + " " + op + ": " + num_text(*it->second, "ns_per_element") + " ns/element, roofline " +
                                 percent_text(num(*it->second, "roofline_fraction")),
                      num(*it->second, "ns_per_element"), str(*it->second, "scalar") == "double" ? " double" : ""});
    }
    if (op == "slerp" || op == "nlerp" || op == "blend_qlb")
      for (const auto& [name, ns] : base4096) bars.push_back({name + " (baseline)", name, ns, " base"});
    std::sort(bars.begin(), bars.end(), [](const Bar& a, const Bar& b) { return a.value < b.value; });
    bar_chart(out, op, "ns per element", bars);
  }
  out << "</div>\n<div class=\"scroll\">\n<table class=\"speed-ops\">\n<thead><tr><th>Op</th><th>Table</th><th>SIMD</th>";
  for (const char* n : kSizes) out << "<th>ns/el n=" << n << "</th>";
  out << "<th>vs glm::slerp (4096)</th><th>roofline 4096 (compute)</th><th>roofline 65536</th></tr></thead>\n<tbody>\n";
  for (const auto& [op, tables] : idx)
    for (const auto& table_sizes : tables) {
      // Named, not a structured binding: clang 14 cannot capture those in the lambda below.
      const std::string& table = table_sizes.first;
      const auto& sizes = table_sizes.second;
      const json* any = sizes.begin()->second;
      out << "<tr><td>" << esc(op) << "</td><td>" << esc(table) << "</td><td>" << esc(str(*any, "simd_target")) << "</td>";
      for (const char* n : kSizes) {
        const auto it = sizes.find(std::stoll(n));
        out << "<td>" << (it == sizes.end() ? "\u2014" : num_text(*it->second, "ns_per_element")) << "</td>";
      }
      const auto at = [&](long long n) { const auto it = sizes.find(n); return it == sizes.end() ? nullptr : it->second; };
      out << "<td>" << (at(4096) ? ratio_text(num(*at(4096), "vs_glm_slerp")) : "\u2014") << "</td><td>"
          << (at(4096) ? percent_text(num(*at(4096), "roofline_fraction")) : "\u2014") << "</td><td>"
          << (at(65536) ? percent_text(num(*at(65536), "roofline_fraction")) + " (" + str(*at(65536), "bound") + ")"
                        : "\u2014")
          << "</td></tr>\n";
    }
  out << "</tbody>\n</table>\n</div>\n";

  // Algebra or implementation.
  if (!arr(s, "operation_counts").empty()) {
    out << "<h3>Algebra or implementation: operation counts beside the times</h3>\n<p class=\"muted\">" << esc(kCountsIntro)
        << "</p>\n<table class=\"speed-counts\">\n<thead><tr><th>Op</th><th>Scalar</th><th>Generated rotor: operations</th>"
           "<th>Formula flops</th><th>rotor_gen ns/el</th><th>glm_quat ns/el</th><th>rotor_gen / glm_quat</th></tr></thead>\n"
           "<tbody>\n";
    for (const json& c : arr(s, "operation_counts"))
      out << "<tr><td>" << esc(str(c, "op")) << "</td><td>" << esc(str(c, "scalar")) << "</td><td>"
          << esc(arithmetic_text(obj_at(c, "generated"))) << " (" << num_text(c, "generated_total") << ")</td><td>"
          << num_text(c, "formula_flops") << "</td><td>" << num_text(c, "ns_per_element") << "</td><td>"
          << num_text(c, "glm_quat_ns_per_element") << "</td><td>" << ratio_text(num(c, "vs_glm_quat")) << "</td></tr>\n";
    out << "</tbody>\n</table>\n";
  }

  // Accuracy versus speed.
  std::map<std::string, std::vector<const json*>> per_op;
  for (const json& p : arr(s, "accuracy_vs_speed")) per_op[str(p, "op")].push_back(&p);
  if (!per_op.empty()) {
    out << "<h3>Accuracy versus speed</h3>\n<p class=\"muted\">Max error of each table's certificate (all cases of the "
           "op, in &epsilon; of its format) against its time per element at 4096; points at the top edge have no finite "
           "max error (a wrong result or status).</p>\n<div class=\"charts\">\n";
    for (const auto& [op, points] : per_op) scatter(out, op, points);
    out << "</div>\n";
  }
  out << "</section>\n";
}

void render_speed_markdown(std::ostream& out, const json& s) {
  out << "## Speed: operations, frame pipeline, roofline <a id=\"section-speed\"></a>\n\n";
  if (!str(s, "note").empty()) {
    out << cell(str(s, "note")) << "\n\n";
    return;
  }
  const json& m = obj_at(s, "machine");
  const json& roofs = obj_at(s, "roofs");
  out << "From " << code(str(s, "source")) << (str(s, "quick") == "true" ? " (quick run)" : "") << ": "
      << cell(str(m, "cpu_model")) << ", " << cell(str(m, "num_cpus")) << " CPUs, Highway target " << cell(str(m, "hwy_target"))
      << ". Peak FMA " << gflops_text(num(obj_at(roofs, "peak_flops"), "float")) << " GFLOP/s float, "
      << gflops_text(num(obj_at(roofs, "peak_flops"), "double")) << " double; bandwidth "
      << gflops_text(num(obj_at(roofs, "bandwidth"), "triad")) << " GB/s triad. Charts: report.html.\n\n";
  for (const json& n : arr(s, "notes")) out << "> " << cell(n.is_string() ? n.get<std::string>() : dump(n)) << "\n\n";
  header(out, {"Target (4096 float)", "Ratio", "Required", "Verdict"});
  for (const json& t : arr(s, "targets"))
    row(out, {cell(str(t, "what")), ratio_text(num(t, "ratio")), "\u2265 " + ratio_text(num(t, "target")), cell(target_verdict(t))});
  out << "\n";
  const json& parity = obj_at(s, "parity");
  if (!arr(parity, "families").empty()) {
    out << cell(kParityIntro) << "\n\n";
    header(out, {"Bar", "Comparison", "Required", "Met", "Worst"});
    for (const json& f : arr(parity, "families"))
      row(out, {cell(str(f, "id")), cell(str(f, "what")), cell(str(f, "bar")),
                num_text(f, "met") + " of " + num_text(f, "rows"), cell(parity_worst_text(f))});
    out << "\n";
    bool any_missed = false;
    for (const json& r : arr(parity, "rows")) {
      if (parity_verdict(r) != "missed") continue;
      if (!any_missed) header(out, {"Missed", "Table", "Scalar", "Op or scene", "Time", "Baseline", "Measure"});
      any_missed = true;
      row(out, {cell(str(r, "family")), code(str(r, "impl")), cell(str(r, "scalar")), cell(str(r, "what")),
                num_text(r, "time"), num_text(r, "baseline"), cell(parity_measure_text(r))});
    }
    if (any_missed) out << "\n";
  }
  if (!arr(s, "paper_claim").empty()) {
    header(out, {"Character", "Scalar", "QLB \u00b5s", "DQB \u00b5s", "Fastest GA rotor", "\u00b5s", "vs QLB", "vs DQB", "Paper's claim"});
    for (const json& c : arr(s, "paper_claim"))
      row(out, {cell(str(c, "scene")), cell(str(c, "scalar")),
                cell(c.contains("qlb") ? spread_text(c["qlb"]) : num_text(c, "qlb_us")),
                cell(c.contains("dqb") ? spread_text(c["dqb"]) : num_text(c, "dqb_us")), code(str(c, "rotor")),
                cell(c.contains("rotor_spread") ? spread_text(c["rotor_spread"]) : num_text(c, "rotor_us")),
                cell(compare_text(c, "vs_qlb", "vs_qlb_interval", "verdict_qlb")),
                cell(compare_text(c, "vs_dqb", "vs_dqb_interval", "verdict_dqb")),
                str(c, "holds") == "true" ? "holds" : "**does not hold**"});
    out << "\nFrame times: median (range, runs). vs QLB / DQB: their time over the rotor's, [interval from the ranges], and the "
           "verdict: faster only where the ranges do not overlap.\n";
    out << "\n";
  }
  if (!arr(s, "frames").empty()) {
    header(out, {"Character", "Method", "Table", "Scalar", "Technique", "\u00b5s per frame", "of which pose \u00b5s"});
    for (const json& f : arr(s, "frames"))
      row(out, {cell(str(f, "scene")), cell(str(f, "method")), code(str(f, "impl")), cell(str(f, "scalar")),
                cell(str(f, "technique")), num_text(f, "us_per_frame"), num_text(f, "pose_us")});
    out << "\n";
  }
  header(out, {"Op", "Table", "ns/el n=1", "n=64", "n=4096", "n=65536", "vs glm::slerp (4096)", "roofline 4096", "roofline 65536"});
  for (const auto& [op, tables] : index_ops(s))
    for (const auto& table_sizes : tables) {
      // Named, not a structured binding: clang 14 cannot capture those in the lambda below.
      const std::string& table = table_sizes.first;
      const auto& sizes = table_sizes.second;
      std::vector<std::string> cells = {cell(op), cell(table)};
      for (const char* n : kSizes) {
        const auto it = sizes.find(std::stoll(n));
        cells.push_back(it == sizes.end() ? "\u2014" : num_text(*it->second, "ns_per_element"));
      }
      const auto at = [&](long long n) { const auto it = sizes.find(n); return it == sizes.end() ? nullptr : it->second; };
      cells.push_back(at(4096) ? ratio_text(num(*at(4096), "vs_glm_slerp")) : "\u2014");
      cells.push_back(at(4096) ? percent_text(num(*at(4096), "roofline_fraction")) : "\u2014");
      cells.push_back(at(65536) ? percent_text(num(*at(65536), "roofline_fraction")) : "\u2014");
      row(out, cells);
    }
  out << "\n";
  if (!arr(s, "operation_counts").empty()) {
    out << cell(kCountsIntro) << "\n\n";
    header(out, {"Op", "Scalar", "Generated rotor: operations", "Formula flops", "rotor_gen ns/el", "glm_quat ns/el",
                 "rotor_gen / glm_quat"});
    for (const json& c : arr(s, "operation_counts"))
      row(out, {cell(str(c, "op")), cell(str(c, "scalar")),
                cell(arithmetic_text(obj_at(c, "generated")) + " (" + num_text(c, "generated_total") + ")"),
                num_text(c, "formula_flops"), num_text(c, "ns_per_element"), num_text(c, "glm_quat_ns_per_element"),
                ratio_text(num(c, "vs_glm_quat"))});
    out << "\n";
  }
}

}  // namespace rotorcert::report::detail
