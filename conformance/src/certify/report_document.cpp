#include <rotorcert/certify/report_document.hpp>

#include <algorithm>
#include <map>
#include <stdexcept>

#include <rotorcert/certify/platform.hpp>
#include <rotorcert/certify/verdict.hpp>
#include <rotorcert/certify/wire.hpp>

#ifndef ROTORCERT_VERSION
#error "ROTORCERT_VERSION must be defined by the build"
#endif

namespace rotorcert::certify {
namespace {

constexpr engine::Outcome kOutcomes[] = {engine::Outcome::pass,          engine::Outcome::quality_warning,
                                         engine::Outcome::fail,          engine::Outcome::not_supported,
                                         engine::Outcome::crash,         engine::Outcome::timeout};

json levels_json(const Certificate& c) {
  json all = json::array();
  for (const LevelResult& l : level_results(c)) {
    json counts = json::object();
    for (const auto& [outcome, n] : l.counts) counts[engine::to_string(outcome)] = n;
    all.push_back({{"level", l.level}, {"status", to_string(l.status)}, {"counts", counts}, {"clauses", l.not_pass}});
  }
  return all;
}

json accuracy_json(const Certificate& c) {
  json all = json::array();
  for (const OpAccuracy& a : accuracy(c))
    all.push_back({{"op", a.op},
                   {"unit", a.unit},
                   {"eps", a.eps},
                   {"cases", a.cases},
                   {"max_eps", a.max_eps},
                   {"max", a.max_eps * a.eps},
                   {"p50_eps", a.p50_eps},
                   {"p99_eps", a.p99_eps},
                   {"worst_clause", a.worst_clause},
                   {"worst_label", a.worst.label},
                   {"worst_input", a.worst.input},
                   {"worst_detail", a.worst.detail},
                   {"histogram", {{"edges_eps", a.histogram_edges_eps}, {"counts", a.histogram_counts}}}});
  return all;
}

}  // namespace

json certificate_json(const Certificate& c) {
  json j = {{"name", c.table.name},
            {"scalar", c.table.scalar},
            {"format", c.table.format() == ref::Format::binary32 ? "binary32" : "binary64"},
            {"version", c.table.version},
            {"description", c.table.description},
            {"source", c.table.source},
            {"plugin_path", c.table.plugin_path.empty() ? json(nullptr) : json(c.table.plugin_path)},
            {"claimed_levels", c.table.claimed_levels},
            {"declared_preconditions", c.table.declared_preconditions},
            {"declared_conventions", c.table.declared_conventions},
            {"error", c.error.empty() ? json(nullptr) : json(c.error)},
            {"fp_environment", c.fp_environment},
            {"claim", claim(c)},
            {"levels", levels_json(c)},
            {"accuracy", accuracy_json(c)},
            {"as_expected", as_expected(c)}};
  json ef = json::array();
  for (const auto& [clause, why] : c.expected_failures) ef.push_back({{"clause", clause}, {"why", why}});
  j["expected_failures"] = ef;
  json clauses = json::array();
  for (const engine::ClauseResult& r : c.clauses) {
    json cj = to_json(r, false);
    cj["claimed"] = claimed(c, r.clause);
    const std::string* why = expected_failure(c, r.clause);
    cj["expected_failure"] = why == nullptr ? json(nullptr) : json(*why);
    const auto rp = c.reproduce.find(r.clause);
    cj["reproduce"] = rp == c.reproduce.end() ? "" : rp->second;
    clauses.push_back(std::move(cj));
  }
  j["clauses"] = clauses;
  json conventions = json::array();
  for (const ConventionFinding& f : convention_findings(c))
    conventions.push_back({{"id", f.id}, {"description", f.description}, {"clauses", f.clauses}});
  j["conventions"] = conventions;
  return j;
}

Certificate certificate_from_json(const json& j) {
  try {
    Certificate c;
    c.table.name = j.at("name");
    c.table.scalar = j.at("scalar");
    c.table.version = j.value("version", "");
    c.table.description = j.value("description", "");
    c.table.source = j.value("source", "");
    if (const auto p = j.find("plugin_path"); p != j.end() && p->is_string()) c.table.plugin_path = *p;
    c.table.claimed_levels = j.value("claimed_levels", std::vector<std::string>{});
    c.table.declared_preconditions = j.value("declared_preconditions", std::vector<std::string>{});
    c.table.declared_conventions = j.value("declared_conventions", std::vector<std::string>{});
    if (const auto e = j.find("error"); e != j.end() && e->is_string()) c.error = *e;
    c.fp_environment = j.value("fp_environment", json());
    for (const json& l : j.at("levels")) c.levels.push_back(l.at("level"));
    for (const json& f : j.value("expected_failures", json::array())) c.expected_failures[f.at("clause")] = f.at("why");
    for (const json& r : j.at("clauses")) {
      c.clauses.push_back(clause_result_from_json(r));
      if (r.value("claimed", false)) c.table.claimed_clauses.push_back(c.clauses.back().clause);
      if (const auto rp = r.find("reproduce"); rp != r.end() && rp->is_string() && !rp->get<std::string>().empty())
        c.reproduce[c.clauses.back().clause] = *rp;
    }
    return c;
  } catch (const json::exception& e) {
    throw std::runtime_error("a certificate" + (j.contains("name") ? " (" + j["name"].dump() + ")" : std::string()) +
                             " does not have the report.json form: " + e.what());
  }
}

std::vector<Certificate> certificates_of_report(const json& report) {
  std::vector<Certificate> all;
  for (const json& c : report.at("implementations")) all.push_back(certificate_from_json(c));
  if (const auto s = report.find("sections"); s != report.end() && s->is_object())
    if (const auto tp = s->find("third_party"); tp != s->end() && tp->contains("libraries"))
      for (const json& lib : tp->at("libraries"))
        for (const json& c : lib.value("certificates", json::array())) all.push_back(certificate_from_json(c));
  return all;
}

bool report_ok(const std::string& kind, const std::vector<Certificate>& certificates) {
  const auto test = kind == "report" || kind == "third-party" ? as_expected : all_claimed_good;
  return std::all_of(certificates.begin(), certificates.end(), test);
}

json report_json(const spec::Spec& spec, const std::string& kind, const json& options, const json& run,
                 const std::vector<Certificate>& certificates) {
  json clauses = json::array();
  for (const spec::Clause& c : spec.clauses)
    if (c.level != "Meta")
      clauses.push_back({{"id", c.id}, {"title", c.title}, {"level", c.level}, {"tolerance", c.tolerance}});
  json classes = json::object();
  for (const auto& [name, tc] : spec.tolerance_classes)
    classes[name] = {{"kind", tc.kind},
                     {"strict", tc.strict ? json(*tc.strict) : json(nullptr)},
                     {"loose", tc.loose ? json(*tc.loose) : json(nullptr)},
                     {"doc", tc.doc}};
  std::map<std::string, int> counts;
  for (engine::Outcome o : kOutcomes) counts[engine::to_string(o)] = 0;
  json implementations = json::array();
  for (const Certificate& c : certificates) {
    for (const engine::ClauseResult& r : c.clauses) ++counts[engine::to_string(r.outcome)];
    implementations.push_back(certificate_json(c));
  }
  const bool all_expected = std::all_of(certificates.begin(), certificates.end(), as_expected);
  return {{"format", "rotorcert-report"},
          {"format_version", 1},
          {"rotorcert_version", ROTORCERT_VERSION},
          {"spec_version", spec.version},
          {"kind", kind},
          {"options", options},
          {"platform", platform_json()},
          {"run", run},
          {"spec", {{"levels", spec.levels}, {"clauses", clauses}, {"tolerance_classes", classes}}},
          {"implementations", implementations},
          {"summary",
           {{"tables", certificates.size()},
            {"counts", counts},
            {"as_expected", all_expected},
            {"exit_code", report_ok(kind, certificates) ? 0 : 1}}},
          {"sections", json::object()}};
}
}  // namespace rotorcert::certify
