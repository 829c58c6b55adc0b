// sections.mutants in HTML and Markdown: each mutant is a built-in implementation with one
// deliberate bug; it is killed when every clause it must break FAILs. A mutant that survives is a
// hole in the suite, so its row is highlighted (HTML) or marked in bold with a warning sign
// (Markdown).
#include "common.hpp"
#include "markup.hpp"
#include "sections.hpp"

namespace rotorcert::report::detail {

namespace {
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
}  // namespace

void render_mutants_html(std::ostream& out, const json& section) { render_mutants(out, section); }

namespace markdown {
namespace {
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
}  // namespace
}  // namespace markdown

void render_mutants_markdown(std::ostream& out, const json& section) { markdown::render_mutants(out, section); }

}  // namespace rotorcert::report::detail
