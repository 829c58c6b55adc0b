// The third-party section of the report (sections.third_party, written by
// rotorcert/thirdparty/thirdparty.hpp; spec REPORT-3) in HTML and Markdown: the libraries with their
// routes, claims and reproduce commands, a clause-by-library matrix, every defect with its worst input
// in hexfloat and its error, the libraries not run and why, and each adapter's convention mapping.
// Private to rotorcert_report.
#pragma once

#include <ostream>

#include <nlohmann/json.hpp>

namespace rotorcert::report::detail {

void render_third_party_html(std::ostream& out, const nlohmann::json& section);
void render_third_party_markdown(std::ostream& out, const nlohmann::json& section);

}  // namespace rotorcert::report::detail
