#include <rotorcert/certify/wire.hpp>

#include <cmath>
#include <stdexcept>

namespace rotorcert::certify {
namespace {

double double_or_nan(const json& j) { return j.is_number() ? j.get<double>() : NAN; }

// A ClauseResult comes back from a child process, in which the implementation under test ran:
// every field is checked for its type (nlohmann's at() and get() throw on a missing key or a
// wrong type; a negative or fractional number would convert silently to a count).

std::size_t count_of(const json& j) {
  if (!j.is_number_unsigned()) throw std::runtime_error("a count that is not a non-negative integer: " + j.dump().substr(0, 40));
  return j.get<std::size_t>();
}
std::size_t count_or_zero(const json& j, const char* key) {
  const auto it = j.find(key);
  return it == j.end() ? 0 : count_of(*it);
}

}  // namespace

json to_json(const WorkingOn& w) { return {{"op", w.op}, {"label", w.label}, {"input", w.input}, {"text", w.text}}; }

WorkingOn working_on_from_progress(const std::string& frame) {
  WorkingOn w;
  w.text = frame;
  const json j = json::parse(frame, nullptr, /*allow_exceptions=*/false);
  if (!j.is_object()) return w;
  const auto field = [&](const char* key) { return j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : ""; };
  if (!j.contains("text") || !j["text"].is_string()) return w;
  w.op = field("op");
  w.label = field("label");
  w.input = field("input");
  w.text = field("text");
  return w;
}

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
  r.cases = count_or_zero(j, "cases");
  r.failures = count_or_zero(j, "failures");
  r.conventions = j.value("conventions", std::vector<std::string>{});
  if (const auto d = j.find("diagnoses"); d != j.end())
    for (const json& x : *d)
      r.diagnoses.push_back({x.at("convention"), count_of(x.at("explained")), count_of(x.at("failing")),
                             x.at("unexplained").get<std::vector<std::string>>()});
  if (const auto st = j.find("status"); st != j.end() && st->is_object()) {
    r.status_failures = count_of(st->at("failures"));
    r.status_op = st->value("op", "");
    r.status_label = st->value("label", "");
    r.status_input = st->value("input", "");
    r.status_detail = st->value("detail", "");
  }
  if (const auto a = j.find("acceptable"); a != j.end())
    for (const json& x : *a)
      r.acceptable.push_back({x.at("convention"), x.value("declared", false), count_of(x.at("count")), x.value("op", ""),
                              x.value("label", ""), x.value("input", ""), x.value("detail", "")});
  if (const auto e = j.find("excluded"); e != j.end()) {
    if (!e->is_object()) throw std::runtime_error("excluded is not an object");
    for (const auto& [precondition, n] : e->items()) r.excluded[precondition] = count_of(n);
  }
  r.searched = count_or_zero(j, "searched");
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
