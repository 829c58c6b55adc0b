// Human-readable renderings of report.json (format "rotorcert-report" v1, spec/report.schema.json):
// Markdown for terminals and code review, and a self-contained HTML page (inline CSS, inline SVG
// charts, a little inline script, no external resources) for browsers.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace rotorcert::report {

std::string render_markdown(const nlohmann::json& report);
std::string render_html(const nlohmann::json& report);

}  // namespace rotorcert::report
