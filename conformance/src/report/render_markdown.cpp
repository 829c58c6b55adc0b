// Placeholder until the renderer lands (helper R owns this file).
#include <rotorcert/report/render.hpp>
namespace rotorcert::report {
std::string render_markdown(const nlohmann::json& report) { return "```json\n" + report.dump(2) + "\n```\n"; }
}  // namespace rotorcert::report
