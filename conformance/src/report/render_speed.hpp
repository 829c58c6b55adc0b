// The speed section of the report (sections.speed, rotorcert/report/speed.hpp) in HTML (tables,
// a bar chart per operation and per character, accuracy-versus-speed scatter plots, inline SVG)
// and in Markdown (the same tables, no charts). Private to rotorcert_report.
#pragma once

#include <ostream>

#include <nlohmann/json.hpp>

namespace rotorcert::report::detail {

void render_speed_html(std::ostream& out, const nlohmann::json& section);
void render_speed_markdown(std::ostream& out, const nlohmann::json& section);

}  // namespace rotorcert::report::detail
