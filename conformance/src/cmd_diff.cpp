// `rotorcert diff OLD/report.json NEW/report.json [--json]`: what got better and worse between two
// reports of the same library (report_diff.hpp): per table, the levels and, per clause, the
// result and the worst error. Exit 0 when nothing got worse, 1 on a regression (a level lost, a
// clause's result worse, a worst error more than doubled, a table gone), 2 on usage (a file that
// cannot be read or is not a report). The release gate of a library's CI (README).
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include <rotorcert/certify/report_diff.hpp>
#include <rotorcert/certify/report_document.hpp>

#include "commands.hpp"

namespace rotorcert::cli {
namespace {

using nlohmann::json;

struct Args {
  std::string old_file, new_file;
  bool as_json = false;
};

json read_report(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file + ": cannot be read");
  json j;
  try {
    j = json::parse(in);
  } catch (const json::exception& e) {
    throw std::runtime_error(file + ": not JSON: " + e.what());
  }
  if (!j.is_object() || j.value("format", "") != "rotorcert-report")
    throw std::runtime_error(file + ": not a rotorcert report.json (format \"rotorcert-report\")");
  return j;
}

std::string outcome_text(const std::optional<engine::Outcome>& o) { return o ? engine::to_string(*o) : "absent"; }

std::string error_text(double e) {
  if (!std::isfinite(e)) return "-";
  std::ostringstream s;
  s << std::setprecision(3) << e << " eps";
  return s.str();
}

json optional_json(const std::optional<certify::LevelStatus>& s) { return s ? json(certify::to_string(*s)) : json(nullptr); }
std::string status_text(const std::optional<certify::LevelStatus>& s) { return s ? certify::to_string(*s) : "not certified"; }
json error_json(double e) { return std::isfinite(e) ? json(e) : json(nullptr); }

json diff_json(const certify::ReportDiff& d) {
  json tables = json::array();
  for (const certify::TableDiff& t : d.tables) {
    json levels = json::array(), clauses = json::array();
    for (const certify::LevelChange& l : t.levels)
      levels.push_back({{"level", l.level}, {"old", optional_json(l.old_status)}, {"new", optional_json(l.new_status)},
                        {"change", certify::to_string(l.change)}});
    for (const certify::ClauseChange& c : t.clauses)
      clauses.push_back({{"clause", c.clause},
                         {"old", c.old_outcome ? json(engine::to_string(*c.old_outcome)) : json(nullptr)},
                         {"new", c.new_outcome ? json(engine::to_string(*c.new_outcome)) : json(nullptr)},
                         {"old_error_eps", error_json(c.old_error)},
                         {"new_error_eps", error_json(c.new_error)},
                         {"outcome_change", certify::to_string(c.outcome_change)},
                         {"error_change", certify::to_string(c.error_change)},
                         {"regression", c.regression()}});
    tables.push_back({{"name", t.name}, {"scalar", t.scalar}, {"only_old", t.only_old}, {"only_new", t.only_new},
                      {"regression", t.regression()}, {"levels", levels}, {"clauses", clauses}});
  }
  return {{"format", "rotorcert-diff"},
          {"format_version", 1},
          {"error_floor_eps", certify::kDiffErrorFloorEps},
          {"error_factor", certify::kDiffErrorFactor},
          {"notes", d.notes},
          {"tables", tables},
          {"regression", d.regression()}};
}

void print_diff(std::ostream& out, const certify::ReportDiff& d) {
  int worse = 0, better = 0, same = 0;
  for (const std::string& n : d.notes) out << "note: " << n << '\n';
  for (const certify::TableDiff& t : d.tables) {
    const bool improved = std::any_of(t.levels.begin(), t.levels.end(), [](auto& l) { return l.change == certify::Change::better; }) ||
                          std::any_of(t.clauses.begin(), t.clauses.end(), [](auto& c) {
                            return c.outcome_change == certify::Change::better || c.error_change == certify::Change::better;
                          });
    out << t.name << " (" << t.scalar << "): ";
    if (t.only_old) out << "REGRESSION: not in the new report\n";
    else if (t.only_new) out << "new in the new report\n";
    else out << (t.regression() ? "REGRESSION" : improved ? "better" : t.clauses.empty() ? "no change" : "changed") << '\n';
    (t.regression() ? worse : improved ? better : same) += 1;
    for (const certify::LevelChange& l : t.levels)
      if (l.old_status != l.new_status)
        out << "  level " << l.level << ": " << status_text(l.old_status) << " -> " << status_text(l.new_status)
            << "  (" << certify::to_string(l.change) << ")\n";
    for (const certify::ClauseChange& c : t.clauses) {
      out << "  " << std::left << std::setw(11) << c.clause << outcome_text(c.old_outcome) << " -> "
          << outcome_text(c.new_outcome);
      if (c.outcome_change != certify::Change::same) out << "  (" << certify::to_string(c.outcome_change) << ")";
      if (c.error_change != certify::Change::same)
        out << "; worst error " << error_text(c.old_error) << " -> " << error_text(c.new_error) << "  ("
            << certify::to_string(c.error_change) << ")";
      out << '\n';
    }
  }
  out << "summary: " << worse << " table(s) worse, " << better << " better, " << same << " unchanged or changed without regression\n";
}

int run(const Args& a) {
  json old_report, new_report;
  std::vector<certify::Certificate> old_certs, new_certs;
  try {
    old_report = read_report(a.old_file);
    new_report = read_report(a.new_file);
    old_certs = certify::certificates_of_report(old_report);
    new_certs = certify::certificates_of_report(new_report);
  } catch (const std::exception& e) {
    std::cerr << "rotorcert diff: " << e.what() << '\n';
    return kExitUsage;
  }
  certify::ReportDiff d = certify::diff_certificates(old_certs, new_certs);
  // Worst errors are like for like only with the same inputs: the same seed, cases and search.
  for (const char* option : {"seed", "cases_per_family", "search_budget"}) {
    const json o = old_report.value("options", json::object()).value(option, json());
    const json n = new_report.value("options", json::object()).value(option, json());
    if (o != n)
      d.notes.push_back(std::string("the reports differ in ") + option + " (" + o.dump() + " vs " + n.dump() +
                        "): they judged different inputs");
  }
  for (const char* version : {"spec_version", "rotorcert_version"})
    if (old_report.value(version, "") != new_report.value(version, ""))
      d.notes.push_back(std::string(version) + " " + old_report.value(version, "") + " vs " + new_report.value(version, ""));
  if (a.as_json) std::cout << diff_json(d).dump(2) << '\n';
  else print_diff(std::cout, d);
  return d.regression() ? kExitFailed : kExitOk;
}

}  // namespace

Command add_diff(CLI::App& parent) {
  auto args = std::make_shared<Args>();
  CLI::App* app = parent.add_subcommand(
      "diff", "Compare two reports: what got better and worse per table and clause; exit 1 on a regression");
  app->add_option("old", args->old_file, "The earlier report.json")->required();
  app->add_option("new", args->new_file, "The later report.json")->required();
  app->add_flag("--json", args->as_json, "Print the differences as JSON (format rotorcert-diff)");
  return {app, [args] { return run(*args); }};
}

}  // namespace rotorcert::cli
