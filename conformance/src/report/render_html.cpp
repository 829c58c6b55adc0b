// report.json as one self-contained HTML page: inline CSS, inline SVG charts, a small inline
// script (the "show only non-PASS clauses" filter; it marks <body data-ready="1"> when it has run,
// which the browser check looks for). Nothing is loaded from elsewhere: no URLs, no src
// attributes, no web fonts; inline SVG needs no namespace URL in HTML5. Every text from the report
// goes through esc().
//
// The page: header, table of contents, the certificates and each section, rendered by the files
// that own them (sections.hpp).
#include <sstream>

#include <rotorcert/report/render.hpp>

#include "common.hpp"
#include "markup.hpp"
#include "sections.hpp"

namespace rotorcert::report {

namespace {

using namespace detail;

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
    out << "<li><a href=\"#section-" << esc(name) << "\">"
        << (find_section(name) ? esc(std::string(find_section(name)->nav_title)) : esc(name)) << "</a></li>\n";
  out << "</ul></nav>\n";
}

/// The sections; one this renderer does not know is shown as JSON.
void render_sections(std::ostream& out, const json& r) {
  for (const auto& [name, value] : obj_at(r, "sections").items()) {
    if (const Section* s = find_section(name); s != nullptr && value.is_object()) {
      s->html(out, value);
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
  render_certificates_html(out, report);
  render_sections(out, report);
  out << "<footer>Generated by rotorcert " << esc(str(report, "rotorcert_version")) << " from report.json ("
      << esc(str(report, "format")) << " version " << esc(str(report, "format_version"))
      << "). Errors in &epsilon; of each table's format, 3 significant digits.</footer>\n<script>" << kScript
      << "</script>\n</body>\n</html>\n";
  return out.str();
}

}  // namespace rotorcert::report
