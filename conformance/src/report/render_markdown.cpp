// report.json as GitHub-flavoured Markdown: the content of the HTML page without its charts
// (histograms as one line of text). Every table cell goes through cell() or code(): a '|' inside a
// cell would otherwise end it, a newline would end the row.
#include <algorithm>
#include <sstream>

#include <rotorcert/report/render.hpp>

#include "common.hpp"
#include "markup.hpp"
#include "render_speed.hpp"
#include "render_third_party.hpp"

namespace rotorcert::report {

namespace {

using namespace detail;

std::string outcome_cell(const json& clause) {
  std::string s = str(clause, "outcome");
  if (clause.contains("expected_failure") && !clause["expected_failure"].is_null()) s += " (expected)";
  return s;
}

void render_header(std::ostream& out, const json& r) {
  const json& opt = obj_at(r, "options");
  const json& run = obj_at(r, "run");
  const json& sum = obj_at(r, "summary");
  out << "# rotorcert report\n\n";
  out << "rotorcert " << str(r, "rotorcert_version") << " · specification " << str(r, "spec_version") << " · kind "
      << str(r, "kind") << " · format " << str(r, "format") << " v" << str(r, "format_version") << "\n\n";
  out << "- Options: seed " << str(opt, "seed") << ", " << str(opt, "cases_per_family") << " cases per family, levels "
      << join(arr(opt, "levels"), ", ");
  if (!arr(opt, "clauses").empty()) out << ", clauses " << join(arr(opt, "clauses"), ", ");
  // vectors check runs in process: no time or memory limit (null).
  if (!str(opt, "timeout_s").empty()) out << ", timeout " << str(opt, "timeout_s") << " s";
  if (!str(opt, "memory_mb").empty()) out << ", memory " << str(opt, "memory_mb") << " MB";
  out << ", isolation: " << str(opt, "isolation") << "\n";
  const json& platform = obj_at(r, "platform");
  if (!platform.empty()) {
    out << "- Platform: " << cell(platform_text(platform)) << "\n";
    out << "- FP environment: "
        << cell(fp_env_text(platform.contains("fp_environment") ? platform["fp_environment"] : json()))
        << " (the tool at start-up; each table below records its own)\n";
  }
  out << "- Run: started " << str(run, "started_utc") << ", " << str(run, "duration_s") << " s, host "
      << str(run, "host") << ", " << str(run, "jobs") << " jobs, command " << code(str(run, "command")) << "\n";
  const json& as_expected = sum.contains("as_expected") ? sum["as_expected"] : json();
  out << "- **Summary:** " << str(sum, "tables") << " tables certified; " << counts_text(obj_at(sum, "counts"))
      << (sum.contains("mutants_total")
              ? "; mutants caught: " + str(sum, "mutants_killed") + " of " + str(sum, "mutants_total")
              : std::string())
      << "; results match expectations: **"
      << (as_expected.is_boolean() ? (as_expected.get<bool>() ? "yes" : "no") : "unknown") << "** (exit code "
      << str(sum, "exit_code") << ")\n\n";
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

/// sections.mutants: a mutant is killed when every clause it must break FAILs; one that survives
/// is a hole in the suite, so its row is marked in bold with a warning sign.
void render_mutants(std::ostream& out, const json& section) {
  out << "## Mutants: proof that the suite catches real bugs <a id=\"section-mutants\"></a>\n\n";
  if (!is_mutant_list(section)) {
    out << cell(str(section, "note")) << "\n\n";
    return;
  }
  out << "Each mutant is a built-in implementation with one deliberate bug. It is killed when every clause it "
         "must break FAILs.\n\n**"
      << kill_rate_text(section) << "**";
  if (!str(section, "directory").empty()) out << " (plugins in " << code(str(section, "directory")) << ")";
  out << "\n\n";
  header(out, {"Mutant", "Scalar", "Bug", "Must break (outcome)", "Killed", "Worst input", "Detail", "Conventions"});
  for (const json& m : arr(section, "mutants")) {
    const bool killed = str(m, "killed") == "true";
    const auto clauses = mutant_clauses(m);
    std::vector<std::string> breaks, inputs, details, conventions;
    for (const MutantClause& c : clauses) {
      breaks.push_back(cell(c.id + ": " + (c.outcome.empty() ? "not run" : c.outcome)));
      if (!c.result) continue;
      const std::string prefix = clauses.size() > 1 ? cell(c.id) + ": " : "";
      if (!str(*c.result, "input").empty()) inputs.push_back(prefix + code(str(*c.result, "input")));
      std::string d = str(*c.result, "detail");
      if (!str(*c.result, "label").empty()) d = str(*c.result, "label") + (d.empty() ? "" : ": " + d);
      if (!d.empty()) details.push_back(prefix + cell(d));
      if (!arr(*c.result, "conventions").empty())
        conventions.push_back(prefix + cell(join(arr(*c.result, "conventions"), ", ")));
    }
    std::string bug = cell(str(m, "bug"));
    if (!str(m, "error").empty()) bug += "<br>**error:** " + cell(str(m, "error"));
    const std::string name = code(str(m, "mutant"));
    row(out, {killed ? name : "**\u26a0 " + name + "**", cell(str(m, "scalar")), bug, join(breaks, "<br>"),
              killed ? "yes" : "**NO**", join(inputs, "<br>"), join(details, "<br>"), join(conventions, "<br>")});
  }
  out << "\n";
}

/// obj[key], or null when obj is not an object or has no such key (renderers never throw).
json field(const json& obj, const char* key) { return obj.is_object() && obj.contains(key) ? obj[key] : json(); }
/// PSNR: null in render.json means identical frames (infinite PSNR).
std::string psnr_text(const json& row) {
  return row.is_object() && row.contains("psnr_db") && row["psnr_db"].is_null() ? "\u221e" : stat_text(field(row, "psnr_db"));
}

/// sections.render (`rotorcert report --render DIR`): the figure strips as image links to the PNG
/// files `rotorcert render` wrote (Markdown viewers differ on data: URIs), and the error table.
void render_render(std::ostream& out, const json& section) {
  out << "## Render check: visual equivalence (VIS-1, VIS-2, VIS-3) <a id=\"section-render\"></a>\n\n";
  if (!str(section, "note").empty()) {
    out << cell(str(section, "note")) << "\n\n";
    return;
  }
  out
      << "From " << code(str(section, "source")) << "; renderer " << cell(str(section, "renderer")) << ". Results "
      << (str(section, "as_expected") == "true" ? "match" : "**DO NOT match**") << " expectations ("
      << cell(counts_text(obj_at(section, "counts"))) << " over VIS-1 and VIS-2).\n\n";
  for (const json& f : arr(section, "figures")) {
    const bool figure1 = str(f, "kind") == "figure1";
    std::string caption = std::string(figure1 ? "Figure 1 strip (QLB, DQB, GA rotor)" : "Candy-wrapper strip") + ", " +
                          str(f, "scene") + ", clip " + str(f, "clip") + "; left to right: " + join(arr(f, "panels"), ", ");
    if (!figure1) {
      std::vector<std::string> v;
      for (const auto& [name, pct] : obj_at(f, "volume_pct").items()) v.push_back(name + " " + stat_text(pct) + " %");
      if (!v.empty()) caption += ". Volume change (VIS-3): " + join(v, ", ");
    }
    // Characters that would end the link target early are replaced.
    std::string file = str(f, "file");
    for (char& c : file)
      if (c == ' ' || c == '(' || c == ')' || c == '<' || c == '>') c = '_';
    out << "![" << (figure1 ? "Figure 1 strip" : "Candy-wrapper strip") << "](" << file << ")\n\n" << cell(caption) << "\n\n";
  }
  header(out, {"Scene", "Method", "Expected", "VIS-1", "max mm", "mean mm", "virtual mm", "normal rad", "VIS-2", "max diff",
               "share > 1 level", "PSNR dB"});
  for (const json& r : arr(section, "rows")) {
    const bool ok = str(r, "as_expected") == "true";
    std::string method = code(str(r, "method"));
    if (!str(r, "failure").empty()) method += "<br>" + cell(str(r, "failure"));
    row(out, {cell(str(r, "scene")), method,
              cell(str(r, "expected").empty() ? "\u2014" : str(r, "expected")) + (ok ? "" : " **(not met)**"),
              cell(str(r, "vis1")), stat_text(field(r, "max_mm")), stat_text(field(r, "mean_mm")),
              stat_text(field(r, "virtual_max_mm")), stat_text(field(r, "normal_max_rad")), cell(str(r, "vis2")),
              cell(str(r, "max_channel_diff")), stat_text(field(r, "share_over")), psnr_text(r)});
  }
  out << "\n";
}

/// Sections this renderer does not know (added by a later issue): visible as
/// JSON until they get their own rendering.
void render_sections(std::ostream& out, const json& r) {
  const json& sections = obj_at(r, "sections");
  for (const auto& [name, value] : sections.items()) {
    if (name == "mutants" && value.is_object()) {
      render_mutants(out, value);
      continue;
    }
    if (name == "render" && value.is_object()) {
      render_render(out, value);
      continue;
    }
    if (name == "speed" && value.is_object()) {
      render_speed_markdown(out, value);
      continue;
    }
    if (name == "third_party" && value.is_object()) {
      render_third_party_markdown(out, value);
      continue;
    }
    out << "## " << cell(name) << "\n\n";
    std::string text = dump(value, 2);
    std::size_t run = 0, longest = 0;
    for (char c : text) {
      run = c == '`' ? run + 1 : 0;
      longest = std::max(longest, run);
    }
    const std::string fence(std::max<std::size_t>(3, longest + 1), '`');
    out << fence << "json\n" << text << "\n" << fence << "\n\n";
  }
}

}  // namespace

std::string render_markdown(const nlohmann::json& report) {
  std::ostringstream out;
  render_header(out, report);
  if (!arr(report, "implementations").empty()) {  // `rotorcert bench` certifies nothing
    render_overview(out, report);
    render_accuracy_overview(out, report);
  }
  const json& platform_env = obj_at(obj_at(report, "platform"), "fp_environment");
  for (const json& cert : arr(report, "implementations")) render_certificate(out, cert, platform_env);
  render_sections(out, report);
  return out.str();
}

}  // namespace rotorcert::report
