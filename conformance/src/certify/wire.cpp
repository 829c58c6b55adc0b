#include <rotorcert/certify/wire.hpp>

#include <cmath>
#include <stdexcept>

namespace rotorcert::certify {
namespace {

double double_or_nan(const json& j) { return j.is_number() ? j.get<double>() : NAN; }

}  // namespace

json to_json(const TableInfo& t) {
  return {{"name", t.name},
          {"scalar", t.scalar},
          {"version", t.version},
          {"description", t.description},
          {"source", t.source},
          {"plugin_path", t.plugin_path},
          {"claimed_levels", t.claimed_levels},
          {"claimed_clauses", t.claimed_clauses},
          {"supported_ops", t.supported_ops},
          {"declared_preconditions", t.declared_preconditions},
          {"declared_conventions", t.declared_conventions}};
}

TableInfo table_info_from_json(const json& j) {
  TableInfo t;
  t.name = j.at("name");
  t.scalar = j.at("scalar");
  t.version = j.value("version", "");
  t.description = j.value("description", "");
  t.source = j.value("source", "plugin");
  t.plugin_path = j.value("plugin_path", "");
  t.claimed_levels = j.value("claimed_levels", std::vector<std::string>{});
  t.claimed_clauses = j.value("claimed_clauses", std::vector<std::string>{});
  t.supported_ops = j.value("supported_ops", std::vector<std::string>{});
  t.declared_preconditions = j.value("declared_preconditions", std::vector<std::string>{});
  t.declared_conventions = j.value("declared_conventions", std::vector<std::string>{});
  return t;
}

json worst_json(const engine::ClauseResult& r) {
  if (!r.has_worst()) return nullptr;
  return {{"error_eps", number_or_null(r.worst_error)},
          {"op", r.worst_op},
          {"label", r.worst_label},
          {"input", r.worst_input},
          {"detail", r.worst_detail}};
}

json to_json(const engine::ClauseResult& r, bool with_errors) {
  json j = {{"id", r.clause},
            {"level", r.level},
            {"tolerance", r.tolerance},
            {"outcome", engine::to_string(r.outcome)},
            {"note", r.note},
            {"cases", r.cases},
            {"failures", r.failures},
            {"conventions", r.conventions}};
  json diagnoses = json::array();
  for (const auto& d : r.diagnoses)
    diagnoses.push_back({{"convention", d.convention}, {"explained", d.explained}, {"failing", d.failing},
                         {"unexplained", d.unexplained}});
  j["diagnoses"] = diagnoses;
  if (r.status_failures > 0)
    j["status"] = {{"failures", r.status_failures}, {"op", r.status_op}, {"label", r.status_label},
                   {"input", r.status_input}, {"detail", r.status_detail}};
  else
    j["status"] = nullptr;
  json acceptable = json::array();
  for (const auto& a : r.acceptable)
    acceptable.push_back({{"convention", a.convention}, {"declared", a.declared}, {"count", a.count}, {"op", a.op},
                          {"label", a.label}, {"input", a.input}, {"detail", a.detail}});
  j["acceptable"] = acceptable;
  j["excluded"] = r.excluded;
  j["searched"] = r.searched;
  j["worst"] = worst_json(r);
  if (with_errors) {
    j["errors"] = r.errors;
    json w = json::object();
    for (const auto& [op, wc] : r.worst_by_op)
      w[op] = {{"error", wc.error}, {"label", wc.label}, {"input", wc.input}, {"detail", wc.detail}};
    j["worst_by_op"] = w;
  }
  return j;
}

engine::ClauseResult clause_result_from_json(const json& j) {
  engine::ClauseResult r;
  r.clause = j.at("id");
  r.level = j.value("level", "");
  r.tolerance = j.value("tolerance", "");
  if (!engine::parse_outcome(j.at("outcome").get<std::string>(), r.outcome))
    throw std::runtime_error("unknown outcome code " + j.at("outcome").dump());
  r.note = j.value("note", "");
  r.cases = j.value("cases", std::size_t{0});
  r.failures = j.value("failures", std::size_t{0});
  r.conventions = j.value("conventions", std::vector<std::string>{});
  if (const auto d = j.find("diagnoses"); d != j.end())
    for (const json& x : *d)
      r.diagnoses.push_back({x.at("convention"), x.at("explained"), x.at("failing"),
                             x.at("unexplained").get<std::vector<std::string>>()});
  if (const auto st = j.find("status"); st != j.end() && st->is_object()) {
    r.status_failures = st->at("failures");
    r.status_op = st->value("op", "");
    r.status_label = st->value("label", "");
    r.status_input = st->value("input", "");
    r.status_detail = st->value("detail", "");
  }
  if (const auto a = j.find("acceptable"); a != j.end())
    for (const json& x : *a)
      r.acceptable.push_back({x.at("convention"), x.value("declared", false), x.at("count"), x.value("op", ""),
                              x.value("label", ""), x.value("input", ""), x.value("detail", "")});
  if (const auto e = j.find("excluded"); e != j.end()) r.excluded = e->get<std::map<std::string, std::size_t>>();
  r.searched = j.value("searched", std::size_t{0});
  if (const auto w = j.find("worst"); w != j.end() && w->is_object()) {
    r.worst_error = double_or_nan(w->at("error_eps"));
    r.worst_op = w->value("op", "");
    r.worst_label = w->value("label", "");
    r.worst_input = w->value("input", "");
    r.worst_detail = w->value("detail", "");
  }
  if (const auto e = j.find("errors"); e != j.end()) r.errors = e->get<std::map<std::string, std::vector<double>>>();
  if (const auto w = j.find("worst_by_op"); w != j.end())
    for (const auto& [op, v] : w->items())
      r.worst_by_op[op] = {v.at("error").get<double>(), v.at("label"), v.at("input"), v.at("detail")};
  return r;
}
}  // namespace rotorcert::certify
