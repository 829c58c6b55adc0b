// The certificates of report.json ("implementations") in HTML and Markdown: the overview (levels
// and clauses of every table), accuracy across implementations, and one certificate per table
// (levels, detected conventions, known defects, every clause with its worst input, accuracy with
// error histograms). HTML charts are inline SVG; Markdown gives the histograms as one line of text.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "common.hpp"
#include "markup.hpp"
#include "sections.hpp"

namespace rotorcert::report::detail {

namespace {

// ---- HTML ----------------------------------------------------------------------------------------

bool is_expected_failure(const json& clause) {
  return clause.contains("expected_failure") && clause["expected_failure"].is_string();
}

std::string level_class(const std::string& status) {
  if (status == "met") return "lv-met";
  if (status == "met with warnings") return "lv-warn";
  if (status == "not met") return "lv-notmet";
  return "lv-none";
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

}  // namespace

void render_certificates_html(std::ostream& out, const json& report) {
  // A report without certificates (`rotorcert bench`) has no overview.
  if (!arr(report, "implementations").empty()) {
    render_overview(out, report);
    render_accuracy_across(out, report);
  }
  const json& platform_env = obj_at(obj_at(report, "platform"), "fp_environment");
  for (const json& cert : arr(report, "implementations")) render_certificate(out, cert, platform_env);
}

namespace markdown {
namespace {

// ---- Markdown ------------------------------------------------------------------------------------

std::string outcome_cell(const json& clause) {
  std::string s = str(clause, "outcome");
  if (clause.contains("expected_failure") && !clause["expected_failure"].is_null()) s += " (expected)";
  return s;
}

void render_overview(std::ostream& out, const json& r) {
  const auto levels = report_levels(r);
  out << "## Levels\n\n";
  std::vector<std::string> head = {"Table"};
  head.insert(head.end(), levels.begin(), levels.end());
  head.insert(head.end(), {"Claim", "As expected"});
  header(out, head);
  const json& platform_env = obj_at(obj_at(r, "platform"), "fp_environment");
  for (const json& cert : arr(r, "implementations")) {
    std::vector<std::string> cells = {"[" + cell(table_label(cert)) + "](#" + anchor(cert) + ")"};
    const auto flags = fp_env_flags(cert.contains("fp_environment") ? cert["fp_environment"] : json(), platform_env);
    if (!flags.empty()) cells[0] += " **\u26a0 " + cell(join(flags, ", ")) + "**";
    for (const std::string& level : levels) {
      std::string status = "—";
      for (const json& l : arr(cert, "levels"))
        if (str(l, "level") == level) status = str(l, "status");
      cells.push_back(cell(status));
    }
    cells.push_back(cell(str(cert, "error").empty() ? str(cert, "claim") : "error: " + str(cert, "error")));
    cells.push_back(str(cert, "as_expected") == "true" ? "yes" : "**no**");
    row(out, cells);
  }

  out << "\n## Clauses\n\n";
  const auto columns = clause_columns(r);
  head = {"Table"};
  for (const ClauseColumn& c : columns) head.push_back(c.id);
  header(out, head);
  for (const json& cert : arr(r, "implementations")) {
    std::vector<std::string> cells = {cell(table_label(cert))};
    for (const ClauseColumn& c : columns) {
      const json* result = find_clause(cert, c.id);
      if (!result) {
        cells.push_back("·");
        continue;
      }
      std::string a = outcome_abbrev(str(*result, "outcome"));
      if (result->contains("expected_failure") && !(*result)["expected_failure"].is_null()) a += "\\*";
      cells.push_back(a);
    }
    row(out, cells);
  }
  out << "\nP = PASS, QW = QUALITY_WARNING, F = FAIL, NS = NOT_SUPPORTED, C = CRASH, T = TIMEOUT; "
         "\\* = known defect, expected; · = not certified.\n\n";
}

void render_accuracy_overview(std::ostream& out, const json& r) {
  std::vector<std::string> ops;
  for (const json& cert : arr(r, "implementations"))
    for (const json& a : arr(cert, "accuracy"))
      if (std::find(ops.begin(), ops.end(), str(a, "op")) == ops.end()) ops.push_back(str(a, "op"));
  if (ops.empty()) return;
  out << "## Accuracy across implementations\n\nMaximum error per op, in " << kEps << " of each table's format.\n\n";
  std::vector<std::string> head = {"Op"};
  for (const json& cert : arr(r, "implementations")) head.push_back(cell(table_label(cert)));
  header(out, head);
  for (const std::string& op : ops) {
    std::vector<std::string> cells = {cell(op)};
    for (const json& cert : arr(r, "implementations")) {
      std::string v = "·";
      for (const json& a : arr(cert, "accuracy"))
        if (str(a, "op") == op) v = stat_text(a.contains("max_eps") ? a["max_eps"] : json());
      cells.push_back(v);
    }
    row(out, cells);
  }
  out << "\n";
}

void render_certificate(std::ostream& out, const json& cert, const json& platform_env) {
  out << "## " << table_label(cert) << " <a id=\"" << anchor(cert) << "\"></a>\n\n";
  out << "- Description: " << cell(str(cert, "description")) << "\n";
  out << "- Version: " << cell(str(cert, "version")) << "; format " << str(cert, "format") << "\n";
  out << "- Source: " << cell(str(cert, "source"));
  if (!str(cert, "plugin_path").empty()) out << " " << code(str(cert, "plugin_path"));
  out << "\n- Claimed levels: " << join(arr(cert, "claimed_levels"), ", ") << "\n";
  out << "- Claim: **" << cell(str(cert, "claim")) << "**\n";
  out << "- Results match expectations: " << (str(cert, "as_expected") == "true" ? "yes" : "**no**") << "\n";
  if (!str(cert, "error").empty()) out << "- **Error:** " << cell(str(cert, "error")) << "\n";
  // Absent in reports from before the environment was recorded; null when it could not be observed.
  const bool has_env = cert.is_object() && cert.contains("fp_environment");
  const json& env = has_env ? cert["fp_environment"] : json();
  if (has_env) out << "- FP environment: " << cell(fp_env_text(env)) << "\n";
  out << "\n";
  // NUM-1: the suite tests an implementation as it is (e.g. built with -ffast-math) and says so.
  const auto warnings = fp_env_warnings(env, platform_env);
  if (!warnings.empty()) {
    out << "> **\u26a0 Warning: floating-point environment changed by the implementation** (observed in the child "
           "process after loading it). Every result of this table was measured in this environment (SPEC NUM-1).\n";
    for (const std::string& w : warnings) out << ">\n> - " << cell(w) << "\n";
    out << "\n";
  }

  if (!arr(cert, "levels").empty()) {
    out << "### Levels\n\n";
    header(out, {"Level", "Status", "Counts", "Clauses not PASS"});
    for (const json& l : arr(cert, "levels"))
      row(out, {cell(str(l, "level")), cell(str(l, "status")), cell(counts_text(obj_at(l, "counts"))),
                cell(join(arr(l, "clauses"), ", "))});
    out << "\n";
  }
  if (!arr(cert, "conventions").empty()) {
    out << "### Detected conventions\n\n";
    header(out, {"Convention", "Description", "Explains clauses"});
    for (const json& c : arr(cert, "conventions"))
      row(out, {cell(str(c, "id")), cell(str(c, "description")), cell(join(arr(c, "clauses"), ", "))});
    out << "\n";
  }
  if (!arr(cert, "expected_failures").empty()) {
    out << "### Expected failures (known defects)\n\n";
    for (const json& e : arr(cert, "expected_failures"))
      out << "- " << str(e, "clause") << ": " << cell(str(e, "why")) << "\n";
    out << "\n";
  }
  if (const std::string d = declarations_text(cert); !d.empty()) out << d << "\n\n";
  if (!arr(cert, "clauses").empty()) {
    out << "### Certificate\n\n";
    header(out, {"Clause", "Level", "Tolerance", "Outcome", "Cases", "Failures", "Worst (" + std::string(kEps) + ")",
                 "Op", "Label", "Worst input", "Detail", "Expected failure", "Reproduce"});
    for (const json& c : arr(cert, "clauses")) {
      const json& worst = obj_at(c, "worst");
      const bool has_worst = c.contains("worst") && c["worst"].is_object();
      std::string outcome = outcome_cell(c);
      if (str(c, "claimed") == "false") outcome += " (not claimed)";
      std::vector<std::string> detail;
      if (!str(c, "note").empty()) detail.push_back("note: " + str(c, "note"));
      if (!str(worst, "detail").empty()) detail.push_back(str(worst, "detail"));
      if (!arr(c, "conventions").empty()) detail.push_back("passes under: " + join(arr(c, "conventions"), ", "));
      for (const std::string& n : verdict_notes(c)) detail.push_back(n);
      row(out, {cell(str(c, "id")), cell(str(c, "level")), cell(str(c, "tolerance")), cell(outcome),
                str(c, "cases"), str(c, "failures"),
                has_worst ? error_eps_text(worst.contains("error_eps") ? worst["error_eps"] : json()) : "",
                cell(str(worst, "op")), cell(str(worst, "label")), code(str(worst, "input")),
                cell(join(detail, "; ")), cell(str(c, "expected_failure")), code(str(c, "reproduce"))});
    }
    out << "\n";
  }
  if (!arr(cert, "accuracy").empty()) {
    out << "### Accuracy\n\n";
    header(out, {"Op", "Unit", "Cases", "Max", "p50 (" + std::string(kEps) + ")", "p99 (" + std::string(kEps) + ")",
                 "Worst clause", "Label", "Worst input", "Histogram (" + std::string(kEps) + ")"});
    for (const json& a : arr(cert, "accuracy"))
      row(out, {cell(str(a, "op")), cell(str(a, "unit")), str(a, "cases"), cell(accuracy_max_text(a)),
                stat_text(a.contains("p50_eps") ? a["p50_eps"] : json()),
                stat_text(a.contains("p99_eps") ? a["p99_eps"] : json()), cell(str(a, "worst_clause")),
                cell(str(a, "worst_label")), code(str(a, "worst_input")),
                cell(histogram_text(obj_at(a, "histogram")))});
    out << "\n";
  }
}

}  // namespace
}  // namespace markdown

void render_certificates_markdown(std::ostream& out, const json& report) {
  if (!arr(report, "implementations").empty()) {  // `rotorcert bench` certifies nothing
    markdown::render_overview(out, report);
    markdown::render_accuracy_overview(out, report);
  }
  const json& platform_env = obj_at(obj_at(report, "platform"), "fp_environment");
  for (const json& cert : arr(report, "implementations")) markdown::render_certificate(out, cert, platform_env);
}

}  // namespace rotorcert::report::detail
