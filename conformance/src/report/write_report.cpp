#include <rotorcert/report/write.hpp>

#include <rotorcert/certify/atomic_file.hpp>
#include <rotorcert/report/render.hpp>

namespace rotorcert::report {

void write_report(const std::filesystem::path& dir, const nlohmann::json& report) {
  std::filesystem::create_directories(dir);
  certify::write_atomically(dir / "report.json", report.dump(2) + "\n");
  certify::write_atomically(dir / "report.md", render_markdown(report));
  certify::write_atomically(dir / "report.html", render_html(report));
}

}  // namespace rotorcert::report
