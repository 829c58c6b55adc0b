// report.json as one self-contained HTML page: inline CSS, inline SVG charts, a small inline
// script (the "show only non-PASS clauses" filter; it marks <body data-ready="1"> when it has run,
// which the browser check looks for). Nothing is loaded from elsewhere: no URLs, no src
// attributes, no web fonts; inline SVG needs no namespace URL in HTML5. Every text from the report
// goes through esc().
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include <rotorcert/report/render.hpp>

#include "common.hpp"
#include "markup.hpp"
#include "render_speed.hpp"
#include "render_third_party.hpp"

namespace rotorcert::report {

namespace {

using namespace detail;

bool is_expected_failure(const json& clause) {
  return clause.contains("expected_failure") && clause["expected_failure"].is_string();
}

std::string level_class(const std::string& status) {
  if (status == "met") return "lv-met";
  if (status == "met with warnings") return "lv-warn";
  if (status == "not met") return "lv-notmet";
  return "lv-none";
}

constexpr const char* kStyle = R"css(
:root { --fg:#1d232b; --muted:#5b6573; --line:#d8dde3; --bg:#ffffff; --panel:#f6f8fa; --accent:#2457a6;
  --pass:#1e7b3a; --pass-bg:#e3f3e7; --qw:#8a5b00; --qw-bg:#fff1cc; --fail:#a61b1b; --fail-bg:#fde0de;
  --ns:#545d69; --ns-bg:#eceff2; --crash:#6a1fa3; --crash-bg:#efe2fa; --to:#9a3d00; --to-bg:#ffe6d2; }
* { box-sizing: border-box; }
body { margin: 0 auto; max-width: 1600px; padding: 24px 32px 64px; color: var(--fg); background: var(--bg);
  font: 15px/1.5 system-ui, -apple-system, "Segoe UI", Roboto, "Helvetica Neue", Arial, "Noto Sans", sans-serif; }
h1 { font-size: 1.9em; margin: 0 0 .2em; letter-spacing: -.01em; }
h2 { font-size: 1.45em; margin: 2em 0 .5em; padding-bottom: .2em; border-bottom: 2px solid var(--line); }
h3 { font-size: 1.1em; margin: 1.6em 0 .5em; }
a { color: var(--accent); text-decoration: none; } a:hover { text-decoration: underline; }
code, pre { font: 12.5px/1.45 ui-monospace, "SFMono-Regular", Menlo, Consolas, "DejaVu Sans Mono", "Liberation Mono", monospace; }
code { background: var(--panel); padding: 1px 4px; border-radius: 3px; overflow-wrap: anywhere; }
pre { background: var(--panel); border: 1px solid var(--line); border-radius: 6px; padding: 12px; overflow: auto; }
.meta, .muted { color: var(--muted); }
.summary { font-size: 1.05em; background: var(--panel); border: 1px solid var(--line); border-radius: 6px; padding: 10px 14px; }
dl.facts { display: grid; grid-template-columns: max-content 1fr; gap: 2px 16px; margin: .5em 0 1em; }
dl.facts dt { color: var(--muted); } dl.facts dd { margin: 0; }
table { border-collapse: collapse; margin: .4em 0 1em; font-size: 13.5px; }
th, td { border: 1px solid var(--line); padding: 4px 8px; text-align: left; vertical-align: top; }
th { background: var(--panel); font-weight: 600; }
td.num, th.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
.scroll { overflow-x: auto; max-width: 100%; }
table.certificate td.input, table.accuracy td.input { min-width: 18em; max-width: 34em; }
table.certificate td.detail { min-width: 14em; max-width: 30em; }
table.certificate td.repro { min-width: 24em; }
table.certificate td.clause { white-space: nowrap; font-weight: 600; }
table.clause-matrix th.clause { writing-mode: vertical-rl; transform: rotate(180deg); white-space: nowrap;
  font-weight: 500; padding: 6px 2px; }
table.clause-matrix { font-size: 12.5px; }
table.clause-matrix td.oc { text-align: center; font-weight: 600; min-width: 1.9em; padding: 3px 1px; }
table.clause-matrix tbody th, table.levels-matrix tbody th { white-space: nowrap; }
.badge { display: inline-block; padding: 0 6px; border-radius: 10px; font-weight: 600; font-size: 12px; white-space: nowrap; }
.oc-PASS { color: var(--pass); background: var(--pass-bg); }
.oc-QUALITY_WARNING { color: var(--qw); background: var(--qw-bg); }
.oc-FAIL { color: var(--fail); background: var(--fail-bg); }
.oc-NOT_SUPPORTED { color: var(--ns); background: var(--ns-bg); }
.oc-CRASH { color: var(--crash); background: var(--crash-bg); }
.oc-TIMEOUT { color: var(--to); background: var(--to-bg); }
.oc-none { color: #a0a8b2; background: #fff; }
.expected { background-image: repeating-linear-gradient(135deg, transparent 0 5px, rgba(255,255,255,.65) 5px 8px); }
.lv-met { color: var(--pass); background: var(--pass-bg); font-weight: 600; }
.lv-warn { color: var(--qw); background: var(--qw-bg); font-weight: 600; }
.lv-notmet { color: var(--fail); background: var(--fail-bg); font-weight: 600; }
.lv-none { color: #a0a8b2; }
.claimed { box-shadow: inset 0 0 0 2px currentColor; }
.yes { color: var(--pass); font-weight: 600; } .no { color: var(--fail); font-weight: 600; }
.note { font-size: 12px; color: var(--muted); margin-top: 2px; }
.error { color: var(--fail); background: var(--fail-bg); padding: 8px 12px; border-radius: 6px; }
.legend span { display: inline-block; margin: 2px 10px 2px 0; }
.legend .badge { min-width: 2.4em; text-align: center; }
.controls { position: sticky; top: 0; z-index: 2; background: rgba(255,255,255,.95); border-bottom: 1px solid var(--line);
  padding: 8px 0; margin: 1em 0; }
.charts { display: flex; flex-wrap: wrap; gap: 12px 28px; }
figure { margin: 0; }
figcaption { font-weight: 600; font-size: 13.5px; margin-bottom: 2px; }
svg text { font-family: system-ui, -apple-system, "Segoe UI", Roboto, Arial, sans-serif; fill: #38414d; }
svg .bar { fill: #4a78c2; } svg .bar.double { fill: #2f9b8f; } svg .bar.base { fill: #9aa3ad; } svg .grid { stroke: #e3e7ec; } svg .axis { stroke: #7d8794; }
nav ul { columns: 3 18em; margin: .3em 0; padding-left: 1.2em; }
section.impl { margin-top: 2.5em; }
tr[hidden] { display: none; }
.fp-warning { color: var(--fail); background: var(--fail-bg); border: 2px solid var(--fail); border-radius: 6px;
  padding: 8px 12px; margin: .6em 0 1em; }
.fp-warning ul { margin: .3em 0; }
.badge.fp-flag { color: #fff; background: var(--fail); margin-left: 6px; }
.kill-rate { font-size: 1.15em; }
table.mutants td.input { min-width: 18em; max-width: 34em; }
table.mutants td.detail { min-width: 14em; max-width: 30em; }
table.mutants td.breaks .badge { margin: 1px 4px 1px 0; }
table.mutants td.mutant code { white-space: nowrap; overflow-wrap: normal; }
table.mutants tr.not-killed td { background: var(--fail-bg); }
table.mutants tr.not-killed td:first-child { box-shadow: inset 4px 0 0 var(--fail); }
footer { margin-top: 3em; color: var(--muted); font-size: 13px; }
)css";

/// The filter and the ready mark. Written for any browser of the last decade, no external code.
constexpr const char* kScript = R"js(
(function () {
  'use strict';
  var box = document.getElementById('only-nonpass');
  var status = document.getElementById('filter-status');
  var rows = document.querySelectorAll('table.certificate tr[data-outcome]');
  function apply() {
    var hidden = 0;
    for (var i = 0; i < rows.length; ++i) {
      var hide = box.checked && rows[i].getAttribute('data-outcome') === 'PASS';
      rows[i].hidden = hide;
      if (hide) ++hidden;
    }
    status.textContent = box.checked ? hidden + ' PASS rows hidden' : '';
  }
  box.addEventListener('change', apply);
  apply();
  document.body.dataset.ready = '1';
})();
)js";

void render_header(std::ostream& out, const json& r) {
  const json& opt = obj_at(r, "options");
  const json& run = obj_at(r, "run");
  const json& sum = obj_at(r, "summary");
  out << "<header>\n<h1>rotorcert conformance report</h1>\n";
  out << "<p class=\"meta\">rotorcert " << esc(str(r, "rotorcert_version")) << " &middot; specification "
      << esc(str(r, "spec_version")) << " &middot; kind " << esc(str(r, "kind")) << " &middot; "
      << esc(str(r, "format")) << " v" << esc(str(r, "format_version")) << "</p>\n";
  out << "<dl class=\"facts\">\n";
  out << "<dt>Options</dt><dd>seed " << esc(str(opt, "seed")) << ", " << esc(str(opt, "cases_per_family"))
      << " cases per family, levels " << esc(join(arr(opt, "levels"), ", "));
  if (!arr(opt, "clauses").empty()) out << ", clauses " << esc(join(arr(opt, "clauses"), ", "));
  // vectors check runs in process: no time or memory limit (null).
  if (!str(opt, "timeout_s").empty()) out << ", timeout " << esc(str(opt, "timeout_s")) << " s";
  if (!str(opt, "memory_mb").empty()) out << ", memory " << esc(str(opt, "memory_mb")) << " MB";
  out << ", isolation: " << esc(str(opt, "isolation")) << "</dd>\n";
  const json& platform = obj_at(r, "platform");
  if (!platform.empty()) {
    out << "<dt>Platform</dt><dd id=\"platform\">" << esc(platform_text(platform)) << "</dd>\n";
    out << "<dt>FP environment</dt><dd>" << esc(fp_env_text(platform.contains("fp_environment") ? platform["fp_environment"] : json()))
        << " <span class=\"muted\">(the tool at start-up; each table below records its own)</span></dd>\n";
  }
  out << "<dt>Run</dt><dd>started " << esc(str(run, "started_utc")) << ", " << esc(str(run, "duration_s"))
      << " s, host " << esc(str(run, "host")) << ", " << esc(str(run, "jobs")) << " jobs</dd>\n";
  out << "<dt>Command</dt><dd><code>" << esc(str(run, "command")) << "</code></dd>\n</dl>\n";
  const json& as_expected = sum.contains("as_expected") ? sum["as_expected"] : json();
  const std::string yes_no = as_expected.is_boolean() ? (as_expected.get<bool>() ? "yes" : "no") : "unknown";
  out << "<p class=\"summary\" id=\"summary\"><strong>" << esc(str(sum, "tables")) << " tables certified</strong>";
  const json& counts = obj_at(sum, "counts");
  for (const char* code : kOutcomes)
    if (counts.contains(code))
      out << " &middot; <span class=\"badge oc-" << code << "\">" << esc(str(counts, code)) << " " << code
          << "</span>";
  if (sum.contains("mutants_total"))
    out << " &middot; mutants caught: " << esc(str(sum, "mutants_killed")) << " of " << esc(str(sum, "mutants_total"));
  out << " &middot; results match expectations: <span class=\"" << (yes_no == "yes" ? "yes" : "no") << "\">"
      << yes_no << "</span> (exit code " << esc(str(sum, "exit_code")) << ")</p>\n</header>\n";
}

void render_nav(std::ostream& out, const json& r) {
  out << "<nav><ul>\n";
  if (!arr(r, "implementations").empty())
    out << "<li><a href=\"#overview\">Overview</a></li>\n<li><a href=\"#accuracy-across\">Accuracy across "
           "implementations</a></li>\n";
  for (const json& cert : arr(r, "implementations"))
    out << "<li><a href=\"#" << esc(anchor(cert)) << "\">" << esc(table_label(cert)) << "</a></li>\n";
  for (const auto& [name, value] : obj_at(r, "sections").items())
    out << "<li><a href=\"#section-" << esc(name) << "\">" << (name == "mutants" ? "Mutants" : name == "render" ? "Render check" : name == "speed" ? "Speed" : name == "third_party" ? "Third-party libraries" : esc(name))
        << "</a></li>\n";
  out << "</ul></nav>\n";
}

void render_legend(std::ostream& out) {
  out << "<p class=\"legend\">";
  for (const char* code : kOutcomes)
    out << "<span><span class=\"badge oc-" << code << "\">" << outcome_abbrev(code) << "</span> " << code << "</span>";
  out << "<span><span class=\"badge oc-FAIL expected\">F*</span> known defect, expected</span>"
         "<span><span class=\"badge oc-none\">&middot;</span> not certified</span></p>\n";
}

std::string clause_tooltip(const json& c) {
  std::string t = str(c, "id") + ": " + str(c, "outcome");
  if (is_expected_failure(c)) t += " (known defect, expected: " + str(c, "expected_failure") + ")";
  if (c.contains("worst") && c["worst"].is_object()) {
    const json& w = c["worst"];
    const json e = w.contains("error_eps") ? w["error_eps"] : json();
    t += "; worst error " + error_eps_text(e) + (e.is_number() ? std::string(" ") + kEps : "");
    if (!str(w, "op").empty()) t += ", " + str(w, "op");
    if (!str(w, "label").empty()) t += ", " + str(w, "label");
  }
  if (!str(c, "note").empty()) t += "; " + str(c, "note");
  return t;
}

void render_overview(std::ostream& out, const json& r) {
  const auto levels = report_levels(r);
  out << "<section id=\"overview\">\n<h2>Overview</h2>\n<h3>Levels</h3>\n<div class=\"scroll\">\n"
         "<table class=\"levels-matrix\">\n<thead><tr><th>Table</th>";
  for (const std::string& l : levels) out << "<th>" << esc(l) << "</th>";
  out << "<th>Claim</th><th>As expected</th></tr></thead>\n<tbody>\n";
  const json& platform_env = obj_at(obj_at(r, "platform"), "fp_environment");
  for (const json& cert : arr(r, "implementations")) {
    out << "<tr><th><a href=\"#" << esc(anchor(cert)) << "\">" << esc(table_label(cert)) << "</a>";
    const json& env = cert.contains("fp_environment") ? cert["fp_environment"] : json();
    for (const std::string& flag : fp_env_flags(env, platform_env))
      out << "<span class=\"badge fp-flag\" title=\"" << esc(join(fp_env_warnings(env, platform_env), "; ")) << "\">"
          << esc(flag) << "</span>";
    out << "</th>";
    for (const std::string& level : levels) {
      const json* found = nullptr;
      for (const json& l : arr(cert, "levels"))
        if (str(l, "level") == level) found = &l;
      if (!found) {
        out << "<td class=\"lv-none\">&middot;</td>";
        continue;
      }
      const std::string status = str(*found, "status");
      std::string tip = counts_text(obj_at(*found, "counts"));
      if (!arr(*found, "clauses").empty()) tip += ": " + join(arr(*found, "clauses"), ", ");
      bool claimed = false;
      for (const json& l : arr(cert, "claimed_levels")) claimed = claimed || l == level;
      if (claimed) tip = "claimed; " + tip;
      out << "<td class=\"" << level_class(status) << (claimed ? " claimed" : "") << "\" title=\"" << esc(tip)
          << "\">" << esc(status) << "</td>";
    }
    if (!str(cert, "error").empty())
      out << "<td class=\"error\">error: " << esc(str(cert, "error")) << "</td>";
    else
      out << "<td>" << esc(str(cert, "claim")) << "</td>";
    const bool ok = str(cert, "as_expected") == "true";
    out << "<td class=\"" << (ok ? "yes" : "no") << "\">" << (ok ? "yes" : "no") << "</td></tr>\n";
  }
  out << "</tbody>\n</table>\n</div>\n<p class=\"legend muted\"><span class=\"badge lv-met claimed\">met</span> "
         "outlined: a level the implementation claims</p>\n";

  const auto columns = clause_columns(r);
  out << "<h3>Clauses</h3>\n";
  render_legend(out);
  out << "<div class=\"scroll\">\n<table class=\"clause-matrix\">\n<thead><tr><th rowspan=\"2\">Table</th>";
  for (std::size_t i = 0; i < columns.size();) {
    std::size_t j = i;
    while (j < columns.size() && columns[j].level == columns[i].level) ++j;
    out << "<th colspan=\"" << (j - i) << "\">" << esc(columns[i].level) << "</th>";
    i = j;
  }
  out << "</tr>\n<tr>";
  std::map<std::string, std::string> titles;
  for (const json& c : arr(obj_at(r, "spec"), "clauses"))
    titles[str(c, "id")] = str(c, "title") + " (" + str(c, "tolerance") + ")";
  for (const ClauseColumn& c : columns)
    out << "<th class=\"clause\" title=\"" << esc(titles[c.id]) << "\">" << esc(c.id) << "</th>";
  out << "</tr></thead>\n<tbody>\n";
  for (const json& cert : arr(r, "implementations")) {
    out << "<tr><th><a href=\"#" << esc(anchor(cert)) << "\">" << esc(table_label(cert)) << "</a></th>";
    for (const ClauseColumn& c : columns) {
      const json* result = find_clause(cert, c.id);
      if (!result) {
        out << "<td class=\"oc oc-none\">&middot;</td>";
        continue;
      }
      const std::string outcome = str(*result, "outcome");
      const bool expected = is_expected_failure(*result);
      out << "<td class=\"oc oc-" << esc(outcome) << (expected ? " expected" : "") << "\" title=\""
          << esc(clause_tooltip(*result)) << "\">" << esc(outcome_abbrev(outcome)) << (expected ? "*" : "")
          << "</td>";
    }
    out << "</tr>\n";
  }
  out << "</tbody>\n</table>\n</div>\n</section>\n";
}

/// Max error per op across tables: one horizontal bar chart per op, log-2 scale in eps.
void render_accuracy_across(std::ostream& out, const json& r) {
  std::vector<std::string> ops;
  for (const json& cert : arr(r, "implementations"))
    for (const json& a : arr(cert, "accuracy"))
      if (std::find(ops.begin(), ops.end(), str(a, "op")) == ops.end()) ops.push_back(str(a, "op"));
  out << "<section id=\"accuracy-across\">\n<h2>Accuracy across implementations</h2>\n";
  if (ops.empty()) {
    out << "<p class=\"muted\">No accuracy measured.</p>\n</section>\n";
    return;
  }
  out << "<p class=\"muted\">Maximum error per op over every case of every clause the op ran in, in &epsilon; "
         "of each table's format (log scale). Bars: blue binary32, teal binary64.</p>\n<div class=\"charts\">\n";
  for (const std::string& op : ops) {
    struct Bar {
      std::string label, scalar, tip;
      json value;
    };
    std::vector<Bar> bars;
    double lo = 0.5, hi = 1;
    for (const json& cert : arr(r, "implementations"))
      for (const json& a : arr(cert, "accuracy"))
        if (str(a, "op") == op) {
          const json v = a.contains("max_eps") ? a["max_eps"] : json();
          bars.push_back({table_label(cert), str(cert, "scalar"),
                          table_label(cert) + ": " + accuracy_max_text(a) + " (" + str(a, "worst_clause") + ")", v});
          if (v.is_number() && v.get<double>() > 0) {
            lo = std::min(lo, v.get<double>());
            hi = std::max(hi, v.get<double>());
          }
        }
    // One power of two below the smallest value, so that the smallest bar is still visible.
    const int e_lo = static_cast<int>(std::floor(std::log2(lo))) - 1;
    const int e_hi = std::max(e_lo + 1, static_cast<int>(std::ceil(std::log2(hi))));
    const int step = std::max(1, (e_hi - e_lo + 5) / 6);  // at most 7 ticks
    const double left = 170, plot = 300, right = 110, top = 8, row_h = 20;
    const double height = top + row_h * static_cast<double>(bars.size()) + 34;
    const double width = left + plot + right;
    const auto x_of = [&](double v) { return left + plot * (std::log2(v) - e_lo) / (e_hi - e_lo); };
    out << "<figure class=\"across\"><figcaption>" << esc(op) << "</figcaption>\n<svg role=\"img\" width=\""
        << px(width) << "\" height=\"" << px(height) << "\" viewBox=\"0 0 " << px(width) << " " << px(height)
        << "\" aria-label=\"maximum error of " << esc(op) << " per table\">\n";
    const double axis_y = top + row_h * static_cast<double>(bars.size());
    for (int e = e_lo; e <= e_hi; e += step) {
      const double x = x_of(std::ldexp(1.0, e));
      // Powers of two as numbers while they are short, beyond that as 2 with an exponent.
      char label[64];
      if (e >= -3 && e <= 13)
        std::snprintf(label, sizeof label, "%g", std::ldexp(1.0, e));
      else
        std::snprintf(label, sizeof label, "2<tspan dy=\"-4\" font-size=\"8\">%d</tspan>", e);
      out << "<line class=\"grid\" x1=\"" << px(x) << "\" y1=\"" << px(top) << "\" x2=\"" << px(x) << "\" y2=\""
          << px(axis_y) << "\"/><text x=\"" << px(x) << "\" y=\"" << px(axis_y + 13)
          << "\" font-size=\"10\" text-anchor=\"middle\">" << label << "</text>\n";
    }
    out << "<line class=\"axis\" x1=\"" << px(left) << "\" y1=\"" << px(axis_y) << "\" x2=\"" << px(left + plot)
        << "\" y2=\"" << px(axis_y) << "\"/>\n<text x=\"" << px(left + plot / 2) << "\" y=\"" << px(axis_y + 28)
        << "\" font-size=\"11\" text-anchor=\"middle\">max error (&epsilon;, log scale)</text>\n";
    for (std::size_t i = 0; i < bars.size(); ++i) {
      const Bar& b = bars[i];
      const double y = top + row_h * static_cast<double>(i);
      double w = 0;
      std::string value = "n/a";
      if (b.value.is_number()) {
        const double v = b.value.get<double>();
        value = fmt3(v);
        if (v > 0) w = std::max(1.0, x_of(v) - left);
      }
      out << "<g><title>" << esc(b.tip) << "</title><text x=\"" << px(left - 6) << "\" y=\"" << px(y + 14)
          << "\" font-size=\"11\" text-anchor=\"end\">" << esc(b.label) << "</text><rect class=\"bar"
          << (b.scalar == "double" ? " double" : "") << "\" x=\"" << px(left) << "\" y=\"" << px(y + 3)
          << "\" width=\"" << px(w) << "\" height=\"" << px(row_h - 6) << "\"/><text x=\"" << px(left + w + 4)
          << "\" y=\"" << px(y + 14) << "\" font-size=\"11\">" << esc(value) << "</text></g>\n";
    }
    out << "</svg></figure>\n";
  }
  out << "</div>\n</section>\n";
}

/// One histogram: a bar per log-2 bin of the Accuracy histogram, counts on the bars.
void render_histogram(std::ostream& out, const json& accuracy) {
  const json& h = obj_at(accuracy, "histogram");
  const json& counts = arr(h, "counts");
  double max_count = 0;
  for (const json& c : counts)
    if (c.is_number()) max_count = std::max(max_count, c.get<double>());
  const double left = 46, top = 18, plot_h = 110, step = 36, bar_w = 28, bottom = 46;
  const double n = static_cast<double>(counts.size());
  const double width = left + step * n + 10, height = top + plot_h + bottom, base = top + plot_h;
  out << "<figure class=\"histogram\"><figcaption>" << esc(str(accuracy, "op")) << " <span class=\"muted\">("
      << esc(str(accuracy, "cases")) << " cases, max " << esc(accuracy_max_text(accuracy))
      << ")</span></figcaption>\n<svg role=\"img\" width=\"" << px(width) << "\" height=\"" << px(height)
      << "\" viewBox=\"0 0 " << px(width) << " " << px(height) << "\" aria-label=\"error histogram of "
      << esc(str(accuracy, "op")) << "\">\n";
  out << "<line class=\"axis\" x1=\"" << px(left) << "\" y1=\"" << px(base) << "\" x2=\"" << px(width - 6)
      << "\" y2=\"" << px(base) << "\"/><line class=\"axis\" x1=\"" << px(left) << "\" y1=\"" << px(top)
      << "\" x2=\"" << px(left) << "\" y2=\"" << px(base) << "\"/>\n";
  out << "<text x=\"" << px(left - 4) << "\" y=\"" << px(base) << "\" font-size=\"10\" text-anchor=\"end\">0</text>"
      << "<text x=\"" << px(left - 4) << "\" y=\"" << px(top + 4) << "\" font-size=\"10\" text-anchor=\"end\">"
      << fmt3(max_count) << "</text>\n";
  out << "<text transform=\"translate(12 " << px(top + plot_h / 2)
      << ") rotate(-90)\" font-size=\"11\" text-anchor=\"middle\">cases</text>\n";
  for (std::size_t i = 0; i < counts.size(); ++i) {
    const double c = counts[i].is_number() ? counts[i].get<double>() : 0;
    const double bh = max_count > 0 && c > 0 ? std::max(1.0, plot_h * c / max_count) : 0;
    const double x = left + step * static_cast<double>(i) + (step - bar_w) / 2;
    const std::string bin = histogram_bin_label(h, i);
    out << "<g><title>" << esc(bin) << " " << kEps << ": " << dump(counts[i]) << " cases</title><rect class=\"bar\" x=\""
        << px(x) << "\" y=\"" << px(base - bh) << "\" width=\"" << px(bar_w) << "\" height=\"" << px(bh) << "\"/>";
    if (c > 0)
      out << "<text x=\"" << px(x + bar_w / 2) << "\" y=\"" << px(base - bh - 3)
          << "\" font-size=\"10\" text-anchor=\"middle\">" << dump(counts[i]) << "</text>";
    out << "<text x=\"" << px(x + bar_w / 2) << "\" y=\"" << px(base + 13)
        << "\" font-size=\"9.5\" text-anchor=\"middle\">" << esc(bin) << "</text></g>\n";
  }
  out << "<text x=\"" << px(left + step * n / 2) << "\" y=\"" << px(base + 34)
      << "\" font-size=\"11\" text-anchor=\"middle\">error (&epsilon;), log-2 bins</text>\n</svg></figure>\n";
}

/// The environment a table ran in; a warning box when the implementation changed it (NUM-1: the
/// suite tests an implementation as it is, e.g. built with -ffast-math, and says so).
void render_fp_warning(std::ostream& out, const json& env, const json& platform_env) {
  const auto warnings = fp_env_warnings(env, platform_env);
  if (warnings.empty()) return;
  out << "<div class=\"fp-warning\" role=\"alert\"><strong>&#9888; Floating-point environment changed by the "
         "implementation</strong> (observed in the child process after loading it):\n<ul>\n";
  for (const std::string& w : warnings) out << "<li>" << esc(w) << "</li>\n";
  out << "</ul>Every result of this table was measured in this environment (SPEC NUM-1), e.g. a library built with "
         "-ffast-math.</div>\n";
}

void render_certificate(std::ostream& out, const json& cert, const json& platform_env) {
  out << "<section class=\"impl\" id=\"" << esc(anchor(cert)) << "\">\n<h2>" << esc(str(cert, "name"))
      << " <span class=\"muted\">" << esc(str(cert, "scalar")) << " &middot; " << esc(str(cert, "format"))
      << "</span></h2>\n";
  out << "<p>" << esc(str(cert, "description")) << "</p>\n<dl class=\"facts\">\n";
  out << "<dt>Version</dt><dd>" << esc(str(cert, "version")) << "</dd>\n";
  out << "<dt>Source</dt><dd>" << esc(str(cert, "source"));
  if (!str(cert, "plugin_path").empty()) out << " <code>" << esc(str(cert, "plugin_path")) << "</code>";
  out << "</dd>\n<dt>Claimed levels</dt><dd>" << esc(join(arr(cert, "claimed_levels"), ", ")) << "</dd>\n";
  out << "<dt>Claim</dt><dd><strong>" << esc(str(cert, "claim")) << "</strong></dd>\n";
  const bool ok = str(cert, "as_expected") == "true";
  out << "<dt>As expected</dt><dd class=\"" << (ok ? "yes" : "no") << "\">" << (ok ? "yes" : "no") << "</dd>\n";
  // Absent in reports from before the environment was recorded; null when it could not be observed.
  const bool has_env = cert.is_object() && cert.contains("fp_environment");
  const json& env = has_env ? cert["fp_environment"] : json();
  if (has_env) out << "<dt>FP environment</dt><dd class=\"fp-env\">" << esc(fp_env_text(env)) << "</dd>\n";
  out << "</dl>\n";
  render_fp_warning(out, env, platform_env);
  if (!str(cert, "error").empty()) out << "<p class=\"error\">Error: " << esc(str(cert, "error")) << "</p>\n";

  if (!arr(cert, "levels").empty()) {
    out << "<h3>Levels</h3>\n<table class=\"levels\">\n<thead><tr><th>Level</th><th>Status</th><th>Counts</th>"
           "<th>Clauses not PASS</th></tr></thead>\n<tbody>\n";
    for (const json& l : arr(cert, "levels"))
      out << "<tr><td>" << esc(str(l, "level")) << "</td><td class=\"" << level_class(str(l, "status")) << "\">"
          << esc(str(l, "status")) << "</td><td>" << esc(counts_text(obj_at(l, "counts"))) << "</td><td>"
          << esc(join(arr(l, "clauses"), ", ")) << "</td></tr>\n";
    out << "</tbody>\n</table>\n";
  }
  if (!arr(cert, "conventions").empty()) {
    out << "<h3>Detected conventions</h3>\n<table class=\"conventions\">\n<thead><tr><th>Convention</th>"
           "<th>Description</th><th>Explains clauses</th></tr></thead>\n<tbody>\n";
    for (const json& c : arr(cert, "conventions"))
      out << "<tr><td><code>" << esc(str(c, "id")) << "</code></td><td>" << esc(str(c, "description")) << "</td><td>"
          << esc(join(arr(c, "clauses"), ", ")) << "</td></tr>\n";
    out << "</tbody>\n</table>\n";
  }
  if (!arr(cert, "expected_failures").empty()) {
    out << "<h3>Expected failures (known defects)</h3>\n<ul>\n";
    for (const json& e : arr(cert, "expected_failures"))
      out << "<li><strong>" << esc(str(e, "clause")) << "</strong>: " << esc(str(e, "why")) << "</li>\n";
    out << "</ul>\n";
  }
  if (const std::string d = declarations_text(cert); !d.empty()) out << "<p class=\"note\">" << esc(d) << "</p>\n";
  if (!arr(cert, "clauses").empty()) {
    out << "<h3>Certificate</h3>\n<div class=\"scroll\">\n<table class=\"certificate\">\n<thead><tr>"
           "<th>Clause</th><th>Level</th><th>Tolerance</th><th>Outcome</th><th class=\"num\">Cases</th>"
           "<th class=\"num\">Failures</th><th class=\"num\">Worst (&epsilon;)</th><th>Op</th><th>Label</th>"
           "<th>Worst input</th><th>Detail</th><th>Expected failure</th><th>Reproduce</th></tr></thead>\n<tbody>\n";
    for (const json& c : arr(cert, "clauses")) {
      const std::string outcome = str(c, "outcome");
      const bool has_worst = c.contains("worst") && c["worst"].is_object();
      const json& w = obj_at(c, "worst");
      out << "<tr data-outcome=\"" << esc(outcome) << "\"><td class=\"clause\">" << esc(str(c, "id")) << "</td><td>"
          << esc(str(c, "level")) << "</td><td>" << esc(str(c, "tolerance")) << "</td><td><span class=\"badge oc-"
          << esc(outcome) << (is_expected_failure(c) ? " expected" : "") << "\">" << esc(outcome)
          << (is_expected_failure(c) ? "*" : "") << "</span>";
      if (str(c, "claimed") == "false") out << "<div class=\"note\">not claimed</div>";
      if (!str(c, "note").empty()) out << "<div class=\"note\">" << esc(str(c, "note")) << "</div>";
      out << "</td><td class=\"num\">" << esc(str(c, "cases")) << "</td><td class=\"num\">" << esc(str(c, "failures"))
          << "</td><td class=\"num\">"
          << (has_worst ? esc(error_eps_text(w.contains("error_eps") ? w["error_eps"] : json())) : "") << "</td><td>"
          << esc(str(w, "op")) << "</td><td>" << esc(str(w, "label")) << "</td><td class=\"input\">";
      if (!str(w, "input").empty()) out << "<code>" << esc(str(w, "input")) << "</code>";
      out << "</td><td class=\"detail\">" << esc(str(w, "detail"));
      if (!arr(c, "conventions").empty())
        out << "<div class=\"note\">passes under: " << esc(join(arr(c, "conventions"), ", ")) << "</div>";
      for (const std::string& n : verdict_notes(c)) out << "<div class=\"note\">" << esc(n) << "</div>";
      out << "</td><td>" << esc(str(c, "expected_failure")) << "</td><td class=\"repro\">";
      if (!str(c, "reproduce").empty()) out << "<code>" << esc(str(c, "reproduce")) << "</code>";
      out << "</td></tr>\n";
    }
    out << "</tbody>\n</table>\n</div>\n";
  }
  if (!arr(cert, "accuracy").empty()) {
    out << "<h3>Accuracy</h3>\n<div class=\"scroll\">\n<table class=\"accuracy\">\n<thead><tr><th>Op</th>"
           "<th>Unit</th><th class=\"num\">Cases</th><th class=\"num\">Max</th><th class=\"num\">p50 (&epsilon;)</th>"
           "<th class=\"num\">p99 (&epsilon;)</th><th>Worst clause</th><th>Label</th><th>Worst input</th>"
           "</tr></thead>\n<tbody>\n";
    for (const json& a : arr(cert, "accuracy")) {
      out << "<tr><td>" << esc(str(a, "op")) << "</td><td>" << esc(str(a, "unit")) << "</td><td class=\"num\">"
          << esc(str(a, "cases")) << "</td><td class=\"num\">" << esc(accuracy_max_text(a)) << "</td><td class=\"num\">"
          << esc(stat_text(a.contains("p50_eps") ? a["p50_eps"] : json())) << "</td><td class=\"num\">"
          << esc(stat_text(a.contains("p99_eps") ? a["p99_eps"] : json())) << "</td><td>"
          << esc(str(a, "worst_clause")) << "</td><td>" << esc(str(a, "worst_label")) << "</td><td class=\"input\">";
      if (!str(a, "worst_input").empty()) out << "<code>" << esc(str(a, "worst_input")) << "</code>";
      if (!str(a, "worst_detail").empty()) out << "<div class=\"note\">" << esc(str(a, "worst_detail")) << "</div>";
      out << "</td></tr>\n";
    }
    out << "</tbody>\n</table>\n</div>\n<h3>Error histograms</h3>\n<div class=\"charts\">\n";
    for (const json& a : arr(cert, "accuracy")) render_histogram(out, a);
    out << "</div>\n";
  }
  out << "</section>\n";
}

constexpr const char* kMutantsTitle = "Mutants: proof that the suite catches real bugs";

/// sections.mutants: each mutant is a built-in implementation with one deliberate bug; it is
/// killed when every clause it must break FAILs. A mutant that survives is a hole in the suite,
/// so its row is highlighted.
void render_mutants(std::ostream& out, const json& section) {
  out << "<section class=\"mutants\" id=\"section-mutants\">\n<h2>" << kMutantsTitle << "</h2>\n";
  if (!is_mutant_list(section)) {
    out << "<p class=\"muted\">" << esc(str(section, "note")) << "</p>\n</section>\n";
    return;
  }
  const json& k = section.contains("killed") ? section["killed"] : json();
  const json& t = section.contains("total") ? section["total"] : json();
  const bool all = k.is_number() && t.is_number() && k == t;
  out << "<p class=\"muted\">Each mutant is a built-in implementation with one deliberate bug. It is killed when "
         "every clause it must break FAILs.</p>\n<p class=\"kill-rate\"><strong class=\""
      << (all ? "yes" : "no") << "\">" << esc(kill_rate_text(section)) << "</strong>";
  if (!str(section, "directory").empty())
    out << " <span class=\"muted\">(plugins in <code>" << esc(str(section, "directory")) << "</code>)</span>";
  out << "</p>\n<div class=\"scroll\">\n<table class=\"mutants\">\n<thead><tr><th>Mutant</th><th>Scalar</th>"
         "<th>Bug</th><th>Must break (outcome)</th><th>Killed</th><th>Worst input</th><th>Detail</th>"
         "<th>Conventions</th></tr></thead>\n<tbody>\n";
  for (const json& m : arr(section, "mutants")) {
    const bool killed = str(m, "killed") == "true";
    const auto clauses = mutant_clauses(m);
    out << "<tr class=\"" << (killed ? "killed" : "not-killed") << "\" data-killed=\"" << (killed ? "true" : "false")
        << "\"><td class=\"mutant\"><code>" << esc(str(m, "mutant")) << "</code></td><td>" << esc(str(m, "scalar")) << "</td><td>"
        << esc(str(m, "bug"));
    if (!str(m, "error").empty()) out << "<div class=\"error\">error: " << esc(str(m, "error")) << "</div>";
    out << "</td><td class=\"breaks\">";
    for (const MutantClause& c : clauses) {
      const std::string oc = c.outcome.empty() ? "none" : c.outcome;
      out << "<span class=\"badge oc-" << esc(oc) << "\" title=\"" << esc(str(c.result ? *c.result : json(), "label"))
          << "\">" << esc(c.id) << ": " << esc(c.outcome.empty() ? "not run" : c.outcome) << "</span> ";
    }
    out << "</td><td class=\"" << (killed ? "yes" : "no") << "\">" << (killed ? "yes" : "NO") << "</td>";
    // The worst case of each clause; named by clause when there are several.
    std::string inputs, details, conventions;
    for (const MutantClause& c : clauses) {
      if (!c.result) continue;
      const std::string prefix = clauses.size() > 1 ? esc(c.id) + ": " : "";
      if (!str(*c.result, "input").empty())
        inputs += "<div>" + prefix + "<code>" + esc(str(*c.result, "input")) + "</code></div>";
      std::string d = str(*c.result, "detail");
      if (!str(*c.result, "label").empty()) d = str(*c.result, "label") + (d.empty() ? "" : ": " + d);
      if (!d.empty()) details += "<div>" + prefix + esc(d) + "</div>";
      if (!arr(*c.result, "conventions").empty())
        conventions += "<div>" + prefix + esc(join(arr(*c.result, "conventions"), ", ")) + "</div>";
    }
    out << "<td class=\"input\">" << inputs << "</td><td class=\"detail\">" << details << "</td><td>" << conventions
        << "</td></tr>\n";
  }
  out << "</tbody>\n</table>\n</div>\n</section>\n";
}

constexpr const char* kRenderTitle = "Render check: visual equivalence (VIS-1, VIS-2, VIS-3)";

/// obj[key], or null when obj is not an object or has no such key (renderers never throw).
json field(const json& obj, const char* key) { return obj.is_object() && obj.contains(key) ? obj[key] : json(); }
/// PSNR: null in render.json means identical frames (infinite PSNR).
std::string psnr_text(const json& row) {
  return row.is_object() && row.contains("psnr_db") && row["psnr_db"].is_null() ? "\u221e" : stat_text(field(row, "psnr_db"));
}

/// sections.render (`rotorcert report --render DIR`): the Figure 1 and candy-wrapper strips, embedded
/// (only data:image/png;base64 URIs are used, so the page still loads nothing from elsewhere), and
/// the error table, one row per scene and method.
void render_render(std::ostream& out, const json& section) {
  if (!str(section, "note").empty()) {
    out << "<section class=\"render\" id=\"section-render\">\n<h2>" << kRenderTitle << "</h2>\n<p class=\"muted\">"
        << esc(str(section, "note")) << "</p>\n</section>\n";
    return;
  }
  out << "<section class=\"render\" id=\"section-render\">\n<h2>" << kRenderTitle << "</h2>\n<p class=\"muted\">From <code>"
      << esc(str(section, "source")) << "</code>; renderer " << esc(str(section, "renderer")) << ". Results "
      << (str(section, "as_expected") == "true" ? "match" : "<strong class=\"no\">DO NOT match</strong>")
      << " expectations (" << esc(counts_text(obj_at(section, "counts")))
      << " over VIS-1 and VIS-2). Vertex errors in mm against the MPFR reference of the same technique; images against "
         "the reference frame of the same renderer.</p>\n";
  for (const json& f : arr(section, "figures")) {
    const std::string uri = str(f, "data_uri");
    const bool figure1 = str(f, "kind") == "figure1";
    std::string caption = std::string(figure1 ? "Figure 1 strip (QLB, DQB, GA rotor)" : "Candy-wrapper strip") + ", " +
                          str(f, "scene") + ", clip " + str(f, "clip") + ", last frame; left to right: " +
                          join(arr(f, "panels"), ", ");
    if (!figure1) {
      std::vector<std::string> v;
      for (const auto& [name, pct] : obj_at(f, "volume_pct").items()) v.push_back(name + " " + stat_text(pct) + " %");
      if (!v.empty()) caption += ". Volume change (VIS-3): " + join(v, ", ");
    }
    out << "<figure>";
    if (uri.rfind("data:image/png;base64,", 0) == 0)
      out << "<img style=\"max-width:100%\" alt=\"" << esc(caption) << "\" src=\"" << esc(uri) << "\">";
    out << "<figcaption>" << esc(caption) << "</figcaption></figure>\n";
  }
  out << "<div class=\"scroll\">\n<table class=\"render\">\n<thead><tr><th>Scene</th><th>Method</th><th>Expected</th>"
         "<th>VIS-1</th><th>max mm</th><th>mean mm</th><th>virtual mm</th><th>normal rad</th><th>VIS-2</th>"
         "<th>max diff</th><th>share &gt; 1 level</th><th>PSNR dB</th></tr></thead>\n<tbody>\n";
  for (const json& r : arr(section, "rows")) {
    const bool ok = str(r, "as_expected") == "true";
    out << "<tr class=\"" << (ok ? "as-expected" : "not-as-expected") << "\"><td>" << esc(str(r, "scene")) << "</td><td><code>"
        << esc(str(r, "method")) << "</code>";
    if (!str(r, "failure").empty()) out << "<div class=\"error\">" << esc(str(r, "failure")) << "</div>";
    out << "</td><td>" << esc(str(r, "expected").empty() ? "\u2014" : str(r, "expected"))
        << (ok ? "" : " <strong class=\"no\">(not met)</strong>") << "</td><td><span class=\"badge oc-" << esc(str(r, "vis1"))
        << "\">" << esc(str(r, "vis1")) << "</span></td><td>" << stat_text(field(r, "max_mm")) << "</td><td>"
        << stat_text(field(r, "mean_mm")) << "</td><td>" << stat_text(field(r, "virtual_max_mm")) << "</td><td>"
        << stat_text(field(r, "normal_max_rad")) << "</td><td><span class=\"badge oc-" << esc(str(r, "vis2")) << "\">"
        << esc(str(r, "vis2")) << "</span></td><td>" << esc(str(r, "max_channel_diff")) << "</td><td>"
        << stat_text(field(r, "share_over")) << "</td><td>" << psnr_text(r) << "</td></tr>\n";
  }
  out << "</tbody>\n</table>\n</div>\n</section>\n";
}

/// The sections; one this renderer does not know is shown as JSON.
void render_sections(std::ostream& out, const json& r) {
  for (const auto& [name, value] : obj_at(r, "sections").items()) {
    if (name == "mutants" && value.is_object()) {
      render_mutants(out, value);
      continue;
    }
    if (name == "render" && value.is_object()) {
      render_render(out, value);
      continue;
    }
    if (name == "speed" && value.is_object()) {
      render_speed_html(out, value);
      continue;
    }
    if (name == "third_party" && value.is_object()) {
      render_third_party_html(out, value);
      continue;
    }
    out << "<section class=\"extra\" id=\"section-" << esc(name) << "\">\n<h2>" << esc(name)
        << "</h2>\n<pre class=\"json\">" << esc(dump(value, 2)) << "</pre>\n</section>\n";
  }
}

}  // namespace

std::string render_html(const nlohmann::json& report) {
  std::ostringstream out;
  out << "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>rotorcert report: "
      << esc(str(obj_at(report, "summary"), "tables")) << " tables, specification " << esc(str(report, "spec_version"))
      << "</title>\n<style>" << kStyle << "</style>\n</head>\n<body>\n";
  render_header(out, report);
  render_nav(out, report);
  out << "<div class=\"controls\"><label><input type=\"checkbox\" id=\"only-nonpass\"> show only non-PASS "
         "clauses</label> <span id=\"filter-status\" class=\"muted\"></span></div>\n";
  // A report without certificates (`rotorcert bench`) has no overview.
  if (!arr(report, "implementations").empty()) {
    render_overview(out, report);
    render_accuracy_across(out, report);
  }
  const json& platform_env = obj_at(obj_at(report, "platform"), "fp_environment");
  for (const json& cert : arr(report, "implementations")) render_certificate(out, cert, platform_env);
  render_sections(out, report);
  out << "<footer>Generated by rotorcert " << esc(str(report, "rotorcert_version")) << " from report.json ("
      << esc(str(report, "format")) << " version " << esc(str(report, "format_version"))
      << "). Errors in &epsilon; of each table's format, 3 significant digits.</footer>\n<script>" << kScript
      << "</script>\n</body>\n</html>\n";
  return out.str();
}

}  // namespace rotorcert::report
