// The Markdown and HTML renderings of report.json (rotorcert/report/render.hpp), on small reports
// made here: every result code, a CRASH and a TIMEOUT with notes, a known defect, a detected
// convention, a NaN worst error, a table that could not be certified, the platform and each
// table's floating-point environment (SPEC NUM-1), the mutants section (a killed mutant, one with
// two clauses, one that survives) and a section the renderers do not know. The tests assert what
// a reader relies on: every table, clause and mutant row is there, the codes and hexfloat inputs
// appear verbatim, a surviving mutant and a changed FP environment stand out, text from
// implementations cannot inject markup, and the HTML page loads nothing from elsewhere. (That the page's script runs without error in a
// browser is checked by report_browser_check.py.)
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <rotorcert/report/render.hpp>
#include <rotorcert/testing/clause.hpp>

namespace {

using nlohmann::json;
using rotorcert::report::render_html;
using rotorcert::report::render_markdown;

const std::string kInput = "a=[0x1.6a09e6p-1, -0x0p+0, 0x1p-149, 0x1.fffffep+127] t=[0x1.8p-2]";
const std::string kHostileDetail = "out_q expected <b>[1 | 0]</b> & got \"x\" > y";
const std::string kMutantInput = "a=[0x1p+0, 0x0p+0, 0x0p+0, 0x0p+0] b=[0x1.6a09e6p-1, 0x1.6a09e6p-1, 0x0p+0, 0x0p+0]";
const std::string kHostileBug = "slerp <script>alert(1)</script> | returns b & a";
const std::vector<std::string> kCodes = {"PASS", "QUALITY_WARNING", "FAIL", "NOT_SUPPORTED", "CRASH", "TIMEOUT"};

json worst(json error_eps, const std::string& op, const std::string& label, const std::string& detail) {
  return {{"error_eps", error_eps}, {"op", op}, {"label", label}, {"input", kInput}, {"detail", detail}};
}

json clause(const std::string& id, const std::string& level, const std::string& tolerance, const std::string& outcome,
            json worst_case, const std::string& note = "", json expected_failure = nullptr,
            json conventions = json::array()) {
  const bool ran = outcome == "PASS" || outcome == "QUALITY_WARNING" || outcome == "FAIL";
  return {{"id", id},
          {"level", level},
          {"tolerance", tolerance},
          {"claimed", true},
          {"outcome", outcome},
          {"note", note},
          {"expected_failure", expected_failure},
          {"cases", ran ? 160 : 0},
          {"failures", outcome == "FAIL" ? 3 : 0},
          {"worst", worst_case},
          {"conventions", conventions},
          {"reproduce", "rotorcert certify --impl alpha_quat --scalar float --clause " + id +
                            " --seed 7 --cases 16 --out rotorcert-" + id}};
}

json fp_env(bool ftz, bool daz = false, const std::string& rounding = "to nearest") {
  return {{"mxcsr", ftz || daz ? "0x9fc0" : "0x1f80"},
          {"flush_to_zero", ftz},
          {"denormals_are_zero", daz},
          {"rounding", rounding}};
}

json mutant_clause(const std::string& id, const std::string& outcome, json conventions = json::array()) {
  return {{"id", id},           {"outcome", outcome}, {"label", "obtuse pair"}, {"input", kMutantInput},
          {"detail", "out_q expected [1 0 0 0] got [0 1 0 0]"}, {"conventions", conventions}};
}

/// Three mutants: killed on one clause, killed on two (one explained by a convention), and one
/// that survives (its clause passes) with markup and a pipe in its bug text.
json mutants_section() {
  json m = json::array();
  m.push_back({{"mutant", "compose_swapped"}, {"scalar", "double"}, {"bug", "compose(a, b) returns b a"},
               {"breaks", {"COMPOSE-1"}}, {"error", nullptr}, {"killed", true},
               {"clauses", {mutant_clause("COMPOSE-1", "FAIL", {"reverse_map"})}}});
  m.push_back({{"mutant", "slerp_sin_div"}, {"scalar", "float"}, {"bug", "slerp divides by sin(theta)"},
               {"breaks", {"EDGE-1", "EDGE-2"}}, {"error", nullptr}, {"killed", true},
               {"clauses", {mutant_clause("EDGE-1", "FAIL"), mutant_clause("EDGE-2", "FAIL")}}});
  m.push_back({{"mutant", "slerp_survivor"}, {"scalar", "float"}, {"bug", kHostileBug},
               {"breaks", {"SLERP-1"}}, {"error", nullptr}, {"killed", false},
               {"clauses", {mutant_clause("SLERP-1", "QUALITY_WARNING")}}});
  return {{"directory", "/build/mutants"}, {"killed", 2}, {"total", 3}, {"mutants", m}};
}

json accuracy(const std::string& op, const std::string& unit, double max_eps, double eps, json counts) {
  return {{"op", op},
          {"unit", unit},
          {"eps", eps},
          {"cases", 167},
          {"max_eps", max_eps},
          {"max", max_eps * eps},
          {"p50_eps", 0.25},
          {"p99_eps", 6.0},
          {"worst_clause", "SLERP-1"},
          {"worst_label", "near-antipodal"},
          {"worst_input", kInput},
          {"worst_detail", "distance 12.5 eps"},
          {"histogram", {{"edges_eps", {0.5, 1, 2, 4, 8, 16, 32, 64, 128, 256, 512, 1024}}, {"counts", counts}}}};
}

/// Two certified tables and one that could not be loaded; every result code occurs.
json sample_report() {
  const double eps32 = 1.1920928955078125e-07, eps64 = 2.220446049250313e-16;
  json alpha = {
      {"name", "alpha_quat"},
      {"scalar", "float"},
      {"format", "binary32"},
      {"version", "Alpha 2.4.1"},
      {"description", "a quaternion library with known defects"},
      {"source", "built-in"},
      {"plugin_path", nullptr},
      {"claimed_levels", {"Core", "Interp", "Robust"}},
      {"claim", "rotorcert 0.1.0: Interp (binary32)"},
      {"levels",
       {{{"level", "Core"}, {"status", "not met"}, {"counts", {{"PASS", 1}, {"FAIL", 2}}},
         {"clauses", {"QUAT-2", "COMPOSE-1"}}},
        {{"level", "Interp"}, {"status", "met with warnings"}, {"counts", {{"QUALITY_WARNING", 1}}},
         {"clauses", {"SLERP-1"}}},
        {{"level", "Robust"}, {"status", "not met"}, {"counts", {{"FAIL", 1}, {"CRASH", 1}, {"TIMEOUT", 1}}},
         {"clauses", {"EDGE-7", "EDGE-6", "EDGE-9"}}}}},
      {"expected_failures", {{{"clause", "QUAT-2"}, {"why", "rotates by the conjugate (issue #123)"}}}},
      {"as_expected", false},
      {"conventions",
       {{{"id", "reverse_map"}, {"description", "uses the reverse rotor map of the paper"}, {"clauses", {"COMPOSE-1"}}}}},
      {"error", nullptr},
      {"fp_environment", fp_env(false)},
      {"clauses",
       {clause("QUAT-2", "Core", "eps8", "FAIL", worst(3250.0, "apply", "random", "sign flipped"), "",
               "rotates by the conjugate (issue #123)"),
        clause("NORM-1", "Core", "eps4", "PASS", worst(3.14159, "normalize", "huge", "fine")),
        clause("COMPOSE-1", "Core", "eps8", "FAIL", worst(1234.5, "compose", "random", kHostileDetail), "", nullptr,
               {"reverse_map"}),
        clause("SLERP-1", "Interp", "eps16", "QUALITY_WARNING", worst(40.26, "slerp", "near-antipodal", "slow")),
        clause("EDGE-6", "Robust", "outcome", "CRASH", nullptr, "signal 11 (SIGSEGV) in child process"),
        clause("EDGE-7", "Robust", "outcome", "FAIL", worst(nullptr, "normalize", "NaN input", "status OK")),
        clause("EDGE-9", "Robust", "outcome", "TIMEOUT", nullptr, "no result within 60 s")}},
      {"accuracy",
       {accuracy("normalize", "rad", 12.5, eps32, {120, 30, 9, 4, 2, 1, 0, 0, 0, 0, 0, 0, 1}),
        accuracy("slerp", "rad", 40.25, eps32, {60, 50, 30, 20, 5, 1, 1, 0, 0, 0, 0, 0, 0})}}};
  json beta = {
      {"name", "beta_rotor"},
      {"scalar", "double"},
      {"format", "binary64"},
      {"version", "Beta 0.3"},
      {"description", "a rotor library without interpolation"},
      {"source", "plugin"},
      {"plugin_path", "/opt/beta/librotorcert_beta.so"},
      {"claimed_levels", {"Core"}},
      {"claim", "rotorcert 0.1.0: Core (binary64)"},
      {"levels",
       {{{"level", "Core"}, {"status", "met"}, {"counts", {{"PASS", 2}}}, {"clauses", json::array()}},
        {{"level", "Interp"}, {"status", "not met"}, {"counts", {{"NOT_SUPPORTED", 1}}}, {"clauses", {"SLERP-1"}}}}},
      {"expected_failures", json::array()},
      {"as_expected", true},
      {"conventions", json::array()},
      {"error", nullptr},
      {"fp_environment", fp_env(false)},
      {"clauses",
       {clause("NORM-1", "Core", "eps4", "PASS", worst(0.5, "normalize", "tiny", "fine")),
        clause("QUAT-2", "Core", "eps8", "PASS", worst(2.0, "apply", "random", "fine")),
        clause("SLERP-1", "Interp", "eps16", "NOT_SUPPORTED", nullptr, "op slerp not provided")}},
      {"accuracy", {accuracy("normalize", "rad", 0.5, eps64, {167, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0})}}};
  json gamma = {{"name", "gamma_plugin"},
                {"scalar", "float"},
                {"format", "binary32"},
                {"version", ""},
                {"description", ""},
                {"source", "plugin"},
                {"plugin_path", "/tmp/gamma.so"},
                {"claimed_levels", json::array()},
                {"claim", "rotorcert 0.1.0: no level met (binary32)"},
                {"levels", json::array()},
                {"expected_failures", json::array()},
                {"as_expected", false},
                {"conventions", json::array()},
                {"error", "plugin could not be loaded: undefined symbol rc_impl_tables"},
                {"fp_environment", nullptr},
                {"clauses", json::array()},
                {"accuracy", json::array()}};
  json spec_clauses = json::array();
  for (const auto& [id, level, tol] : std::vector<std::tuple<std::string, std::string, std::string>>{
           {"QUAT-2", "Core", "eps8"},
           {"NORM-1", "Core", "eps4"},
           {"COMPOSE-1", "Core", "eps8"},
           {"SLERP-1", "Interp", "eps16"},
           {"EDGE-6", "Robust", "outcome"},
           {"EDGE-7", "Robust", "outcome"},
           {"EDGE-9", "Robust", "outcome"}})
    spec_clauses.push_back({{"id", id}, {"title", "title of " + id}, {"level", level}, {"tolerance", tol}});
  return {{"format", "rotorcert-report"},
          {"format_version", 1},
          {"rotorcert_version", "0.1.0"},
          {"spec_version", "1.0.0"},
          {"kind", "report"},
          {"options",
           {{"seed", 7}, {"cases_per_family", 16}, {"levels", {"Core", "Interp", "Robust"}}, {"clauses", json::array()},
            {"timeout_s", 60.0}, {"memory_mb", 4096}, {"isolation", "one child process per clause"}}},
          {"run",
           {{"started_utc", "2026-11-22T03:00:00Z"}, {"duration_s", 12.5}, {"host", "builder"},
            {"command", "rotorcert report --out r"}, {"jobs", 2}}},
          {"platform",
           {{"os", "Linux 6.1.0-13-amd64"}, {"machine", "x86_64"}, {"cpu", "Test CPU Model 9000"}, {"cores", 2},
            {"compiler", "GCC 12.2.0"}, {"mpfr", "4.2.0"}, {"reference_precision_bits", 256},
            {"fp_environment", fp_env(false)}}},
          {"spec",
           {{"levels", {"Meta", "Core", "Interp", "Blend", "Rigid", "Skinning", "Robust"}},
            {"clauses", spec_clauses},
            {"tolerance_classes", {{"eps4", {{"kind", "eps"}, {"strict", "4"}, {"loose", "64"}}}}}}},
          {"implementations", {alpha, beta, gamma}},
          {"summary",
           {{"tables", 3},
            {"counts",
             {{"PASS", 3}, {"QUALITY_WARNING", 1}, {"FAIL", 3}, {"NOT_SUPPORTED", 1}, {"CRASH", 1}, {"TIMEOUT", 1}}},
            {"as_expected", false},
            {"exit_code", 1}}},
          {"sections", {{"future_part", {{"ns_per_op", 12}, {"remark", "<not yet rendered>"}}}, {"mutants", mutants_section()}}}};
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

/// The HTML of one implementation's section (from its opening tag to the next </section>).
std::string html_section(const std::string& html, const std::string& id) {
  const std::size_t begin = html.find("<section class=\"impl\" id=\"" + id + "\">");
  if (begin == std::string::npos) return {};
  return html.substr(begin, html.find("</section>", begin) - begin);
}

/// The HTML of the mutants section.
std::string html_mutants(const std::string& html) {
  const std::size_t begin = html.find("<section class=\"mutants\" id=\"section-mutants\">");
  if (begin == std::string::npos) return {};
  return html.substr(begin, html.find("</section>", begin) - begin);
}

/// The Markdown of one implementation's section (from its heading to the next "## ").
std::string md_section(const std::string& md, const std::string& heading) {
  const std::size_t begin = md.find("## " + heading);
  if (begin == std::string::npos) return {};
  return md.substr(begin, md.find("\n## ", begin + 1) - begin);
}

class ReportRender : public ::testing::Test {
 protected:
  json report = sample_report();
  std::string html = render_html(report);
  std::string md = render_markdown(report);
};

TEST_F(ReportRender, HtmlHasASectionPerTableWithEveryClauseRow) {
  for (const json& cert : report["implementations"]) {
    const std::string id = cert["name"].get<std::string>() + "-" + cert["scalar"].get<std::string>();
    const std::string section = html_section(html, id);
    ASSERT_FALSE(section.empty()) << "no section with id " << id;
    EXPECT_NE(section.find(cert["version"].get<std::string>()), std::string::npos) << id;
    EXPECT_NE(html.find("href=\"#" + id + "\""), std::string::npos) << "no link to " << id;
    EXPECT_EQ(count(section, "<tr data-outcome="), cert["clauses"].size()) << id;
    for (const json& c : cert["clauses"]) {
      const std::string row = "<tr data-outcome=\"" + c["outcome"].get<std::string>() + "\"><td class=\"clause\">" +
                              c["id"].get<std::string>() + "</td>";
      EXPECT_NE(section.find(row), std::string::npos) << id << " lacks the row of " << c["id"];
      EXPECT_NE(section.find(c["reproduce"].get<std::string>()), std::string::npos) << c["id"];
    }
  }
  // The table that could not be certified says why, in the overview and in its section.
  EXPECT_EQ(count(html, "plugin could not be loaded: undefined symbol rc_impl_tables"), 2u);
}

TEST_F(ReportRender, MarkdownHasASectionPerTableWithEveryClauseRow) {
  for (const json& cert : report["implementations"]) {
    const std::string label = cert["name"].get<std::string>() + " (" + cert["scalar"].get<std::string>() + ")";
    const std::string section = md_section(md, label);
    ASSERT_FALSE(section.empty()) << "no section " << label;
    for (const json& c : cert["clauses"])
      EXPECT_NE(section.find("| " + c["id"].get<std::string>() + " | " + c["level"].get<std::string>() + " |"),
                std::string::npos)
          << label << " lacks the row of " << c["id"];
  }
  EXPECT_NE(md.find("plugin could not be loaded: undefined symbol rc_impl_tables"), std::string::npos);
}

TEST_F(ReportRender, EveryOutcomeCodeAppearsInFullAndAbbreviated) {
  const std::string alpha = html_section(html, "alpha_quat-float") + html_section(html, "beta_rotor-double");
  for (const std::string& code : kCodes) {
    EXPECT_NE(alpha.find(">" + code), std::string::npos) << code << " missing from the certificate tables";
    EXPECT_NE(md.find("| " + code), std::string::npos) << code << " missing from the Markdown";
  }
  // The clause matrix: P, QW, F, NS, C, T, and F* for the known defect, with its legend.
  for (const char* abbrev : {">P<", ">QW<", ">F<", ">NS<", ">C<", ">T<", ">F*<"})
    EXPECT_NE(html.find(abbrev), std::string::npos) << abbrev;
  for (const char* abbrev : {"| P |", "| QW |", "| F |", "| NS |", "| C |", "| T |", "| F\\* |"})
    EXPECT_NE(md.find(abbrev), std::string::npos) << abbrev;
  // Each matrix cell's tooltip names the worst error.
  EXPECT_NE(html.find("title=\"COMPOSE-1: FAIL; worst error 1230 \u03b5, compose, random\">F<"), std::string::npos);
  EXPECT_NE(html.find("title=\"EDGE-7: FAIL; worst error NaN / wrong status, normalize"), std::string::npos);
  EXPECT_NE(html.find("known defect, expected"), std::string::npos);
  EXPECT_NE(md.find("known defect, expected"), std::string::npos);
}

TEST_F(ReportRender, NotesOfCrashTimeoutAndNotSupportedAreShown) {
  for (const char* note : {"signal 11 (SIGSEGV) in child process", "no result within 60 s", "op slerp not provided"}) {
    EXPECT_NE(html.find(note), std::string::npos) << note;
    EXPECT_NE(md.find(note), std::string::npos) << note;
  }
}

TEST_F(ReportRender, WorstInputsAppearVerbatimAsCode) {
  EXPECT_NE(html.find("<code>" + kInput + "</code>"), std::string::npos);
  EXPECT_NE(md.find("`" + kInput + "`"), std::string::npos);
  // Every clause with a worst case and every accuracy row shows it.
  EXPECT_EQ(count(html, "<code>" + kInput + "</code>"), 5u + 2u + 3u);
}

TEST_F(ReportRender, ErrorsHaveThreeSignificantDigitsAndNaNIsNamed) {
  // 3.14159 eps -> 3.14; 1234.5 eps -> 1230 (three digits, no exponent below 10^6); the accuracy
  // maximum in eps and in radians: 12.5 * 2^-23 = 1.4901e-06.
  for (const char* s : {">3.14<", ">1230<", ">40.3<"}) EXPECT_NE(html.find(s), std::string::npos) << s;
  EXPECT_EQ(html.find("3.14159"), std::string::npos);
  EXPECT_EQ(html.find("1234.5"), std::string::npos);
  EXPECT_NE(html.find("12.5 \u03b5 = 1.49e-06 rad"), std::string::npos);
  EXPECT_NE(md.find("12.5 \u03b5 = 1.49e-06 rad"), std::string::npos);
  EXPECT_NE(html.find(">NaN / wrong status<"), std::string::npos);
  EXPECT_NE(md.find("| NaN / wrong status |"), std::string::npos);
}

TEST_F(ReportRender, HtmlEscapesTextFromTheReport) {
  EXPECT_NE(html.find("out_q expected &lt;b&gt;[1 | 0]&lt;/b&gt; &amp; got &quot;x&quot; &gt; y"), std::string::npos);
  EXPECT_EQ(html.find("<b>"), std::string::npos);
  EXPECT_NE(html.find("&lt;not yet rendered&gt;"), std::string::npos);
  EXPECT_EQ(html.find("<not yet rendered>"), std::string::npos);
}

TEST_F(ReportRender, MarkdownTableCellsCannotSplitRows) {
  EXPECT_NE(md.find("[1 \\| 0]"), std::string::npos) << "a pipe in a detail must be escaped";
  // Every row of a table has as many unescaped pipes as the table's header.
  std::size_t header_pipes = 0;
  bool in_table = false;
  std::size_t start = 0;
  while (start < md.size()) {
    const std::size_t end = std::min(md.find('\n', start), md.size());
    const std::string line = md.substr(start, end - start);
    start = end + 1;
    if (line.empty() || line[0] != '|') {
      in_table = false;
      continue;
    }
    std::size_t pipes = 0;
    for (std::size_t i = 0; i < line.size(); ++i)
      if (line[i] == '|' && (i == 0 || line[i - 1] != '\\')) ++pipes;
    if (!in_table) {
      header_pipes = pipes;
      in_table = true;
    }
    EXPECT_EQ(pipes, header_pipes) << line;
  }
}

TEST_F(ReportRender, HtmlDrawsHistogramsAndComparisonsAsInlineSvg) {
  const std::string alpha = html_section(html, "alpha_quat-float");
  EXPECT_EQ(count(alpha, "<svg"), 2u) << "one histogram per op";
  EXPECT_EQ(count(alpha, "<rect"), 2u * 13u) << "one bar per bin";
  EXPECT_NE(alpha.find(">\u22640.5<"), std::string::npos);
  EXPECT_NE(alpha.find(">&gt;1024<"), std::string::npos);
  EXPECT_NE(alpha.find(">120<"), std::string::npos) << "bar counts are labelled";
  EXPECT_NE(alpha.find("error (&epsilon;), log-2 bins"), std::string::npos) << "axis title";
  // Across implementations: one chart per op (normalize, slerp), a bar per table that ran it.
  const std::size_t across = html.find("<section id=\"accuracy-across\">");
  ASSERT_NE(across, std::string::npos);
  const std::string charts = html.substr(across, html.find("</section>", across) - across);
  EXPECT_EQ(count(charts, "<svg"), 2u);
  EXPECT_EQ(count(charts, "<rect"), 3u);
  // Markdown: the same bins as text.
  EXPECT_NE(md.find("\u22640.5:120 \u22641:30 \u22642:9 \u22644:4 \u22648:2 \u226416:1 >1024:1"), std::string::npos);
}

TEST_F(ReportRender, HtmlIsSelfContained) {
  for (const char* s : {"http://", "https://", "src=", "url(", "@import", "<link", "<img", "<iframe"})
    EXPECT_EQ(html.find(s), std::string::npos) << s;
  EXPECT_EQ(count(html, "<style>"), 1u);
  EXPECT_EQ(count(html, "<script>"), 1u);
  EXPECT_NE(html.find("id=\"only-nonpass\""), std::string::npos) << "the filter checkbox";
  EXPECT_NE(html.find("document.body.dataset.ready = '1'"), std::string::npos);
}

TEST_F(ReportRender, HeaderAndOverviewSummariseTheRun) {
  for (const char* s : {"rotorcert 0.1.0", "specification 1.0.0", "seed 7", "16 cases per family"}) {
    EXPECT_NE(html.find(s), std::string::npos) << s;
    EXPECT_NE(md.find(s), std::string::npos) << s;
  }
  EXPECT_NE(html.find("3 tables certified"), std::string::npos);
  EXPECT_NE(md.find("3 tables certified; 3 PASS, 1 QUALITY_WARNING, 3 FAIL, 1 NOT_SUPPORTED, 1 CRASH, 1 TIMEOUT"),
            std::string::npos);
  EXPECT_NE(html.find("results match expectations: <span class=\"no\">no</span>"), std::string::npos);
  EXPECT_NE(md.find("results match expectations: **no**"), std::string::npos);
  // Levels matrix: statuses, colour classes, claim lines.
  for (const char* s : {"class=\"lv-met\"", "class=\"lv-warn\"", "class=\"lv-notmet\"",
                               "rotorcert 0.1.0: Interp (binary32)", "rotorcert 0.1.0: Core (binary64)"})
    EXPECT_NE(html.find(s), std::string::npos) << s;
  EXPECT_NE(md.find("| met with warnings |"), std::string::npos);
}

TEST_F(ReportRender, ConventionsExpectedFailuresAndPluginsAreExplained) {
  for (const char* s : {"reverse_map", "uses the reverse rotor map of the paper",
                               "rotates by the conjugate (issue #123)", "/opt/beta/librotorcert_beta.so"}) {
    EXPECT_NE(html.find(s), std::string::npos) << s;
    EXPECT_NE(md.find(s), std::string::npos) << s;
  }
  EXPECT_NE(html.find("passes under: reverse_map"), std::string::npos);
}

TEST_F(ReportRender, UnknownSectionsAreShownAsJson) {
  const std::size_t at = html.find("<section class=\"extra\" id=\"section-future_part\">\n<h2>future_part</h2>\n<pre");
  ASSERT_NE(at, std::string::npos);
  EXPECT_NE(html.find("&quot;ns_per_op&quot;: 12", at), std::string::npos);
  EXPECT_NE(md.find("## future_part\n\n```json\n"), std::string::npos);
  EXPECT_NE(md.find("\"ns_per_op\": 12"), std::string::npos);
}

// sections.render (`rotorcert report --render DIR`): the figure strips are embedded in the HTML as
// PNG data: URIs only (anything else is dropped, so the page still loads nothing from elsewhere),
// linked by file in the Markdown, and the error table has a row per scene and method.
TEST_F(ReportRender, RenderSectionShowsFiguresAndTheErrorTable) {
  RC_CLAUSE("REPORT-1");
  const std::string png = "data:image/png;base64,iVBORw0KGgo=";
  report["sections"]["render"] = {
      {"source", "/tmp/r/render.json"},
      {"renderer", "llvmpipe; 4.5"},
      {"as_expected", true},
      {"counts", {{"PASS", 3}, {"FAIL", 1}}},
      {"figures",
       {{{"scene", "medium"}, {"kind", "figure1"}, {"clip", "twist"}, {"panels", {"glm_quat float LBS", "dq float DQS"}},
         {"file", "/tmp/r/medium/twist/figure1.png"}, {"data_uri", png}},
        {{"scene", "medium"}, {"kind", "candy_wrapper"}, {"clip", "twist"}, {"panels", {"reference LBS"}},
         {"file", "/tmp/r/medium/twist/candy_wrapper.png"}, {"data_uri", "javascript:alert(1)"},
         {"volume_pct", {{"reference LBS", -0.399}}}}}},
      {"rows",
       {{{"scene", "medium"}, {"method", "rotor_m2 float LBS"}, {"expected", "PASS"}, {"as_expected", true},
         {"failure", ""}, {"vis1", "PASS"}, {"max_mm", 5.46e-4}, {"mean_mm", 1e-5}, {"virtual_max_mm", 1.7e-4},
         {"normal_max_rad", 2.9e-7}, {"vis2", "PASS"}, {"max_channel_diff", 1}, {"share_over", 0.0}, {"psnr_db", nullptr}},
        {{"scene", "medium"}, {"method", "paper_literal float LBS"}, {"expected", "FAIL"}, {"as_expected", true},
         {"failure", ""}, {"vis1", "FAIL"}, {"max_mm", 4066.0}, {"vis2", "FAIL"}, {"share_over", 0.374}, {"psnr_db", 21.1}}}}};
  const std::string h = render_html(report), m = render_markdown(report);
  const std::size_t at = h.find("<section class=\"render\" id=\"section-render\">");
  ASSERT_NE(at, std::string::npos);
  EXPECT_EQ(count(h, "<img"), 1u);  // the candy strip's bad URI is not used
  EXPECT_NE(h.find("src=\"" + png + "\""), std::string::npos);
  EXPECT_EQ(h.find("javascript:"), std::string::npos);
  for (const char* s : {"rotor_m2 float LBS", "paper_literal float LBS", "0.000546", "4070", "reference LBS -0.399 %"})
    EXPECT_NE(h.find(s, at), std::string::npos) << s;
  EXPECT_NE(m.find("![Figure 1 strip](/tmp/r/medium/twist/figure1.png)"), std::string::npos) << m;
  EXPECT_NE(m.find("| medium | `rotor_m2 float LBS` | PASS | PASS | 0.000546 |"), std::string::npos) << m;
  EXPECT_EQ(m.find("data:image"), std::string::npos);
}

TEST_F(ReportRender, HtmlMutantsSectionIsATableWithKillRate) {
  const std::string section = html_mutants(html);
  ASSERT_FALSE(section.empty()) << "no mutants section";
  EXPECT_NE(section.find("<h2>Mutants: proof that the suite catches real bugs</h2>"), std::string::npos);
  EXPECT_NE(section.find("2 of 3 killed (66%)"), std::string::npos) << "kill rate, rounded down";
  EXPECT_EQ(html.find("&quot;mutants&quot;"), std::string::npos) << "mutants must not fall back to JSON";
  EXPECT_NE(section.find("<table class=\"mutants\">"), std::string::npos);
  EXPECT_EQ(count(section, "<tr class=\"killed\""), 2u);
  EXPECT_EQ(count(section, "<tr class=\"not-killed\""), 1u);
  // The survivor's row is the highlighted one, and says NO.
  const std::size_t survivor = section.find("<tr class=\"not-killed\"");
  ASSERT_NE(survivor, std::string::npos);
  const std::string row = section.substr(survivor, section.find("</tr>", survivor) - survivor);
  EXPECT_NE(row.find("slerp_survivor"), std::string::npos);
  EXPECT_NE(row.find(">NO<"), std::string::npos);
  EXPECT_NE(row.find("<span class=\"badge oc-QUALITY_WARNING\""), std::string::npos) << "outcome colour-coded";
  EXPECT_NE(html.find("table.mutants tr.not-killed td {"), std::string::npos) << "the highlight has a style";
  // Every clause a mutant must break, with the outcome it got, as a coloured badge.
  for (const char* badge : {">COMPOSE-1: FAIL<", ">EDGE-1: FAIL<", ">EDGE-2: FAIL<", ">SLERP-1: QUALITY_WARNING<"})
    EXPECT_NE(section.find(badge), std::string::npos) << badge;
  EXPECT_EQ(count(section, "<span class=\"badge oc-FAIL\""), 3u);
  // The worst input of each clause verbatim as code; with two clauses, each named.
  EXPECT_EQ(count(section, "<code>" + kMutantInput + "</code>"), 4u);
  EXPECT_NE(section.find("EDGE-2: <code>"), std::string::npos);
  EXPECT_NE(section.find("obtuse pair: out_q expected [1 0 0 0] got [0 1 0 0]"), std::string::npos);
  EXPECT_NE(section.find("reverse_map"), std::string::npos) << "conventions column";
  // Text from the mutant list cannot inject markup.
  EXPECT_NE(section.find("slerp &lt;script&gt;alert(1)&lt;/script&gt; | returns b &amp; a"), std::string::npos);
  EXPECT_EQ(html.find("<script>alert"), std::string::npos);
  EXPECT_NE(html.find("href=\"#section-mutants\">Mutants<"), std::string::npos) << "nav link";
}

TEST_F(ReportRender, MarkdownMutantsSectionIsATableWithKillRate) {
  const std::string section = md_section(md, "Mutants: proof that the suite catches real bugs");
  ASSERT_FALSE(section.empty());
  EXPECT_NE(section.find("**2 of 3 killed (66%)**"), std::string::npos);
  EXPECT_EQ(md.find("\"mutants\": ["), std::string::npos) << "mutants must not fall back to JSON";
  EXPECT_EQ(count(section, "\n| "), 1u + 3u) << "header and one row per mutant";
  EXPECT_EQ(count(section, "| yes |"), 2u);
  EXPECT_NE(section.find("| **\u26a0 `slerp_survivor`** | float |"), std::string::npos) << "survivor highlighted";
  EXPECT_NE(section.find("| **NO** |"), std::string::npos);
  EXPECT_NE(section.find("EDGE-1: FAIL<br>EDGE-2: FAIL"), std::string::npos);
  EXPECT_NE(section.find("`" + kMutantInput + "`"), std::string::npos);
  EXPECT_NE(section.find("slerp \\<script>alert(1)\\</script> \\| returns b & a"), std::string::npos)
      << "pipe and tag in the bug escaped";
}

TEST_F(ReportRender, MutantsNoteIsShownWhenThereAreNoMutants) {
  report["sections"]["mutants"] = {{"note", "mutant plugins not found in /x (build the whole tree)"}};
  const std::string h = render_html(report), m = render_markdown(report);
  const std::string section = html_mutants(h);
  EXPECT_NE(section.find("mutant plugins not found in /x (build the whole tree)"), std::string::npos);
  EXPECT_EQ(section.find("<table"), std::string::npos);
  EXPECT_NE(m.find("## Mutants: proof that the suite catches real bugs"), std::string::npos);
  EXPECT_NE(m.find("mutant plugins not found in /x (build the whole tree)"), std::string::npos);
}

TEST_F(ReportRender, PlatformIsShownInTheHeader) {
  for (const char* s : {"Linux 6.1.0-13-amd64", "x86_64", "Test CPU Model 9000", "2 cores", "GCC 12.2.0", "MPFR 4.2.0",
                        "256 bits", "MXCSR 0x1f80, rounding to nearest, flush-to-zero off, denormals-are-zero off"}) {
    EXPECT_NE(html.substr(0, html.find("</header>")).find(s), std::string::npos) << s;
    EXPECT_NE(md.substr(0, md.find("\n## ")).find(s), std::string::npos) << s;
  }
  // Each table records the environment it ran in; the one that could not be loaded has none.
  EXPECT_NE(html_section(html, "beta_rotor-double").find("MXCSR 0x1f80"), std::string::npos);
  EXPECT_NE(html_section(html, "gamma_plugin-float").find("not observed"), std::string::npos);
  EXPECT_NE(md_section(md, "beta_rotor (double)").find("- FP environment: MXCSR 0x1f80"), std::string::npos);
}

TEST_F(ReportRender, NoFpWarningWhenEveryTableRanInThePlatformsEnvironment) {
  RC_CLAUSE("NUM-1");  // the report records, and shows, the environment each table ran in
  EXPECT_EQ(html.find("class=\"fp-warning\""), std::string::npos);
  EXPECT_EQ(html.find("class=\"badge fp-flag\""), std::string::npos);
  EXPECT_EQ(md.find("Warning: floating-point environment"), std::string::npos);
  EXPECT_EQ(md.find("\u26a0 FTZ"), std::string::npos);
}

TEST_F(ReportRender, FlushToZeroInATableIsFlaggedProminently) {
  RC_CLAUSE("NUM-1");  // the report records, and shows, the environment each table ran in
  report["implementations"][1]["fp_environment"] = fp_env(true);  // beta, e.g. built with -ffast-math
  const std::string h = render_html(report), m = render_markdown(report);
  const std::string beta = html_section(h, "beta_rotor-double");
  EXPECT_NE(beta.find("<div class=\"fp-warning\" role=\"alert\">"), std::string::npos);
  EXPECT_NE(beta.find("flush-to-zero is ON"), std::string::npos);
  EXPECT_NE(beta.find("MXCSR 0x9fc0, rounding to nearest, flush-to-zero ON, denormals-are-zero off"), std::string::npos);
  EXPECT_EQ(html_section(h, "alpha_quat-float").find("fp-warning"), std::string::npos) << "only the table that has it";
  EXPECT_EQ(count(h, "class=\"fp-warning\""), 1u);
  // In the overview too, next to the table's name.
  EXPECT_NE(h.find("beta_rotor (double)</a><span class=\"badge fp-flag\""), std::string::npos);
  const std::string beta_md = md_section(m, "beta_rotor (double)");
  EXPECT_NE(beta_md.find("> **\u26a0 Warning: floating-point environment changed by the implementation**"),
            std::string::npos);
  EXPECT_NE(beta_md.find("flush-to-zero is ON"), std::string::npos);
  EXPECT_EQ(md_section(m, "alpha_quat (float)").find("Warning: floating-point"), std::string::npos);
  EXPECT_NE(m.find("[beta_rotor (double)](#beta_rotor-double) **\u26a0 FTZ**"), std::string::npos);
}

TEST_F(ReportRender, DenormalsAreZeroAndOtherRoundingAreFlagged) {
  RC_CLAUSE("NUM-1");  // the report records, and shows, the environment each table ran in
  report["implementations"][0]["fp_environment"] = fp_env(false, true);
  report["implementations"][1]["fp_environment"] = fp_env(false, false, "toward zero");
  const std::string h = render_html(report), m = render_markdown(report);
  EXPECT_NE(html_section(h, "alpha_quat-float").find("denormals-are-zero is ON"), std::string::npos);
  EXPECT_NE(html_section(h, "beta_rotor-double").find("rounding toward zero differs from the platform&#39;s (to nearest)"),
            std::string::npos);
  EXPECT_EQ(count(h, "class=\"fp-warning\""), 2u);
  EXPECT_NE(m.find("**\u26a0 DAZ**"), std::string::npos);
  EXPECT_NE(m.find("**\u26a0 rounding**"), std::string::npos);
}

TEST_F(ReportRender, LimitsOfAnInProcessRunAreNotShownAsNumbers) {
  report["kind"] = "vectors-check";
  report["options"]["timeout_s"] = nullptr;
  report["options"]["memory_mb"] = nullptr;
  report["options"]["isolation"] = "in process (vectors check)";
  report["options"]["clauses"] = {"SLERP-1"};
  for (const std::string& out : {render_html(report), render_markdown(report)}) {
    EXPECT_EQ(out.find("timeout"), std::string::npos);
    EXPECT_EQ(out.find("null"), std::string::npos);
    EXPECT_NE(out.find("clauses SLERP-1, isolation: in process (vectors check)"), std::string::npos);
  }
}

TEST(ReportRenderRobustness, IncompleteReportsRenderWithoutThrowing) {
  // A renderer runs at the end of a long certification: a missing field must not lose the report.
  for (const json& r : {json::object(), json::array(), json{{"implementations", {json::object()}}},
                        json::parse(R"({"implementations": [{"clauses": [{"worst": {"error_eps": "x"}}, 3]}, 4]})"),
                        json::parse(R"({"implementations": [{"accuracy": [{"histogram": {"counts": [1, "a"]}}]}]})"),
                        json::parse(R"({"platform": 3, "implementations": [{"fp_environment": "x"}, {"fp_environment": {}}]})"),
                        json::parse(R"({"platform": {"fp_environment": [1]}, "sections": {"mutants": []}})"),
                        json::parse(R"({"sections": {"mutants": {"mutants": [1, {"breaks": 5, "clauses": [2]},
                                        {"breaks": ["A-1", 7], "clauses": [{"id": "A-1", "input": 3}]}]}}})"),
                        json::parse(R"({"sections": {"mutants": {"killed": "x", "total": 0, "mutants": []}}})")}) {
    EXPECT_NO_THROW(render_html(r)) << r.dump();
    EXPECT_NO_THROW(render_markdown(r)) << r.dump();
  }
  json r = sample_report();
  r["implementations"][0]["accuracy"][0]["max_eps"] = nullptr;
  r["implementations"][0]["clauses"][0]["worst"]["detail"] = std::string("bad utf-8 \xff\xfe");
  r["sections"]["future_part"] = std::string("bad utf-8 \xff");
  EXPECT_NO_THROW(render_html(r));
  EXPECT_NO_THROW(render_markdown(r));
}

TEST(ReportRenderRobustness, ReportsWithoutPlatformOrFpEnvironmentRenderWithoutThem) {
  // Reports written before the platform was recorded: nothing about it, and no warning.
  json r = sample_report();
  r.erase("platform");
  for (json& cert : r["implementations"]) cert.erase("fp_environment");
  std::string h, m;
  ASSERT_NO_THROW(h = render_html(r));
  ASSERT_NO_THROW(m = render_markdown(r));
  for (const std::string& out : {h, m}) {
    EXPECT_EQ(out.find("FP environment"), std::string::npos);
    EXPECT_EQ(out.find("Platform"), std::string::npos);
  }
  EXPECT_EQ(h.find("class=\"fp-warning\""), std::string::npos);
  // Without a platform environment, FTZ is still flagged (the C default is no flushing).
  r["implementations"][0]["fp_environment"] = {{"flush_to_zero", true}};
  EXPECT_NE(render_html(r).find("flush-to-zero is ON"), std::string::npos);
}

}  // namespace
