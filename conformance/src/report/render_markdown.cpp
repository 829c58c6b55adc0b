// report.json as GitHub-flavoured Markdown: the content of the HTML page without its charts
// (histograms as one line of text). Every table cell goes through cell() or code(): a '|' inside a
// cell would otherwise end it, a newline would end the row.
//
// The page: a header, then the certificates and each section, rendered by the files that own them
// (sections.hpp).
#include <algorithm>
#include <sstream>

#include <rotorcert/report/render.hpp>

#include "common.hpp"
#include "markup.hpp"
#include "sections.hpp"

namespace rotorcert::report {

namespace {

using namespace detail;

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

/// The sections; one this renderer does not know is shown as JSON.
void render_sections(std::ostream& out, const json& r) {
  const json& sections = obj_at(r, "sections");
  for (const auto& [name, value] : sections.items()) {
    if (const Section* s = find_section(name); s != nullptr && value.is_object()) {
      s->markdown(out, value);
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
  render_certificates_markdown(out, report);
  render_sections(out, report);
  return out.str();
}

}  // namespace rotorcert::report
