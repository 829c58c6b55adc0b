// Markup of the report renderings: escaping for HTML and for Markdown table cells, SVG numbers,
// Markdown table rows. Private to rotorcert_report; shared by the whole report and its sections.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace rotorcert::report::detail {

/// Text for HTML (element content and attribute values): & < > " ' escaped.
std::string esc(const std::string& text);
/// A number for SVG coordinates (one decimal).
std::string px(double v);

/// Plain text in a Markdown table cell: pipes escaped, newlines as <br>, '<' escaped so that no
/// text is taken for an HTML tag.
std::string cell(const std::string& text);
/// Verbatim text as a Markdown code span (hexfloats, commands): a fence longer than any run of
/// backticks inside; pipes still escaped, which GFM requires even inside code spans in tables.
std::string code(const std::string& text);
/// One Markdown table row; header() adds the separator line.
void row(std::ostream& out, const std::vector<std::string>& cells);
void header(std::ostream& out, const std::vector<std::string>& cells);

}  // namespace rotorcert::report::detail
