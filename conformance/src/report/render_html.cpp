// Placeholder until the renderer lands (helper R owns this file).
#include <rotorcert/report/render.hpp>
namespace rotorcert::report {
std::string render_html(const nlohmann::json& report) { return "<!doctype html><pre>" + report.dump(2) + "</pre>"; }
}  // namespace rotorcert::report
