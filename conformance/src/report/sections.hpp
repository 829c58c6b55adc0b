// The parts of the report, each rendered in HTML and in Markdown by the one file that owns it:
//   render_certificates.cpp  report.json "implementations": the overview, accuracy across
//                            implementations and one certificate per table (REPORT-1);
//   render_mutants.cpp       sections.mutants;
//   render_render_check.cpp  sections.render (VIS-1..3);
//   render_speed.cpp         sections.speed (REPORT-2);
//   render_third_party.cpp   sections.third_party (REPORT-3).
// render_html.cpp and render_markdown.cpp are only the two pages around them: a section key that
// sections() does not list is shown there as JSON. A new section is one entry in sections.cpp and
// one file with its two renderers. Private to rotorcert_report.
#pragma once

#include <ostream>
#include <span>
#include <string_view>

#include <nlohmann/json.hpp>

namespace rotorcert::report::detail {

/// Renders one part of report.json (a section's value, or the whole report for the certificates).
using RenderFn = void (*)(std::ostream& out, const nlohmann::json& value);

/// A section of report.json "sections": its key, its entry in the HTML page's table of contents,
/// and its two renderings.
struct Section {
  std::string_view key;
  std::string_view nav_title;
  RenderFn html;
  RenderFn markdown;
};

/// Every section the renderers know.
std::span<const Section> sections();
/// The section of `key`, or nullptr.
const Section* find_section(std::string_view key);

void render_certificates_html(std::ostream& out, const nlohmann::json& report);
void render_certificates_markdown(std::ostream& out, const nlohmann::json& report);
void render_mutants_html(std::ostream& out, const nlohmann::json& section);
void render_mutants_markdown(std::ostream& out, const nlohmann::json& section);
void render_render_check_html(std::ostream& out, const nlohmann::json& section);
void render_render_check_markdown(std::ostream& out, const nlohmann::json& section);
/// Tables, a bar chart per operation and per character and accuracy-versus-speed scatter plots
/// (inline SVG); Markdown: the same tables, no charts.
void render_speed_html(std::ostream& out, const nlohmann::json& section);
void render_speed_markdown(std::ostream& out, const nlohmann::json& section);
/// The libraries with their routes, claims and reproduce commands, a clause-by-library matrix,
/// every defect with its worst input in hexfloat and its error, the libraries not run and why,
/// and each adapter's convention mapping.
void render_third_party_html(std::ostream& out, const nlohmann::json& section);
void render_third_party_markdown(std::ostream& out, const nlohmann::json& section);

}  // namespace rotorcert::report::detail
