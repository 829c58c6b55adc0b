// Writing a report: report.json with its Markdown and HTML renderings (render.hpp), each file
// atomically (REPORT-1), so a reader, or an interrupted run (RESULT-4), never sees a torn one.
#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>

namespace rotorcert::report {

/// Writes DIR/report.json, DIR/report.md and DIR/report.html (creating DIR).
void write_report(const std::filesystem::path& dir, const nlohmann::json& report);

}  // namespace rotorcert::report
