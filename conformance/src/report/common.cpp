#include "common.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>

namespace rotorcert::report::detail {

namespace {
const json kEmptyArray = json::array();
const json kEmptyObject = json::object();
}  // namespace

std::string str(const json& obj, const char* key) {
  if (!obj.is_object()) return {};
  const auto it = obj.find(key);
  if (it == obj.end() || it->is_null()) return {};
  if (it->is_string()) return it->get<std::string>();
  if (it->is_number_float()) return fmt3(it->get<double>());
  return dump(*it);
}

const json& arr(const json& obj, const char* key) {
  if (!obj.is_object()) return kEmptyArray;
  const auto it = obj.find(key);
  return it != obj.end() && it->is_array() ? *it : kEmptyArray;
}

const json& obj_at(const json& obj, const char* key) {
  if (!obj.is_object()) return kEmptyObject;
  const auto it = obj.find(key);
  return it != obj.end() && it->is_object() ? *it : kEmptyObject;
}

std::string join(const std::vector<std::string>& items, const std::string& sep) {
  std::string s;
  for (std::size_t i = 0; i < items.size(); ++i) s += (i ? sep : "") + items[i];
  return s;
}

std::string join(const json& items, const std::string& sep) {
  std::vector<std::string> v;
  if (items.is_array())
    for (const json& i : items) v.push_back(i.is_string() ? i.get<std::string>() : dump(i));
  return join(v, sep);
}

std::string fmt3(double x) {
  if (std::isnan(x)) return "NaN";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buf[40];
  // 1234 as "1230", not "1.23e+03": the same 3 significant digits, easier to compare by eye.
  if (std::abs(x) >= 1e3 && std::abs(x) < 1e6) {
    std::snprintf(buf, sizeof buf, "%.2e", x);
    std::snprintf(buf, sizeof buf, "%.0f", std::strtod(buf, nullptr));
  } else {
    std::snprintf(buf, sizeof buf, "%.3g", x);
  }
  return buf;
}

std::string error_eps_text(const json& error_eps) {
  if (error_eps.is_number()) return fmt3(error_eps.get<double>());
  return "NaN / wrong status";
}

std::string stat_text(const json& value) { return value.is_number() ? fmt3(value.get<double>()) : "\u2014"; }

std::string accuracy_max_text(const json& accuracy) {
  const json& max_eps = accuracy.is_object() && accuracy.contains("max_eps") ? accuracy["max_eps"] : json();
  if (!max_eps.is_number()) return "\u2014";
  std::string s = fmt3(max_eps.get<double>()) + " " + kEps;
  if (accuracy.contains("max") && accuracy["max"].is_number()) {
    s += " = " + fmt3(accuracy["max"].get<double>());
    const std::string unit = str(accuracy, "unit");
    if (!unit.empty()) s += " " + unit;
  }
  return s;
}

std::string outcome_abbrev(const std::string& outcome) {
  if (outcome == "PASS") return "P";
  if (outcome == "QUALITY_WARNING") return "QW";
  if (outcome == "FAIL") return "F";
  if (outcome == "NOT_SUPPORTED") return "NS";
  if (outcome == "CRASH") return "C";
  if (outcome == "TIMEOUT") return "T";
  return outcome;
}

std::string table_label(const json& certificate) {
  return str(certificate, "name") + " (" + str(certificate, "scalar") + ")";
}

std::string anchor(const json& certificate) {
  std::string id = str(certificate, "name") + "-" + str(certificate, "scalar");
  for (char& c : id) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
                    c == '-' || c == '.';
    if (!ok) c = '_';
  }
  return id;
}

std::string counts_text(const json& counts) {
  std::vector<std::string> parts;
  if (!counts.is_object()) return {};
  std::set<std::string> known;
  for (const char* code : kOutcomes) {
    known.insert(code);
    if (counts.contains(code)) parts.push_back(str(counts, code) + " " + code);
  }
  for (const auto& [code, n] : counts.items())
    if (!known.count(code)) parts.push_back(dump(n) + " " + code);
  return join(parts, ", ");
}

std::vector<ClauseColumn> clause_columns(const json& report) {
  std::set<std::string> present;
  std::vector<ClauseColumn> appearance;
  for (const json& cert : arr(report, "implementations"))
    for (const json& c : arr(cert, "clauses")) {
      const std::string id = str(c, "id");
      if (present.insert(id).second) appearance.push_back({id, str(c, "level")});
    }
  std::vector<ClauseColumn> columns;
  std::set<std::string> listed;
  for (const json& c : arr(obj_at(report, "spec"), "clauses")) {
    const std::string id = str(c, "id");
    if (present.count(id) && listed.insert(id).second) columns.push_back({id, str(c, "level")});
  }
  for (const ClauseColumn& c : appearance)
    if (listed.insert(c.id).second) columns.push_back(c);
  // Grouped by level (spec level order, unknown levels last), spec order within a level: the
  // overview draws one header cell per level over its clauses.
  std::vector<std::string> levels;
  for (const json& l : arr(obj_at(report, "spec"), "levels")) levels.push_back(l.is_string() ? l.get<std::string>() : "");
  const auto rank = [&](const std::string& level) {
    return std::find(levels.begin(), levels.end(), level) - levels.begin();
  };
  std::stable_sort(columns.begin(), columns.end(),
                   [&](const ClauseColumn& a, const ClauseColumn& b) { return rank(a.level) < rank(b.level); });
  return columns;
}

const json* find_clause(const json& certificate, const std::string& id) {
  for (const json& c : arr(certificate, "clauses"))
    if (str(c, "id") == id) return &c;
  return nullptr;
}

namespace {
std::string edge_text(const json& e) {
  if (!e.is_number()) return "?";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", e.get<double>());
  return buf;
}
}  // namespace

std::string histogram_bin_label(const json& histogram, std::size_t i) {
  const json& edges = arr(histogram, "edges_eps");
  if (i < edges.size()) return "\u2264" + edge_text(edges[i]);
  if (!edges.empty()) return ">" + edge_text(edges.back());
  return "bin " + std::to_string(i);
}

std::string histogram_text(const json& histogram) {
  std::vector<std::string> parts;
  const json& counts = arr(histogram, "counts");
  for (std::size_t i = 0; i < counts.size(); ++i)
    if (counts[i].is_number() && counts[i].get<double>() > 0)
      parts.push_back(histogram_bin_label(histogram, i) + ":" + dump(counts[i]));
  return parts.empty() ? "no finite errors" : join(parts, " ");
}

std::vector<std::string> report_levels(const json& report) {
  std::vector<std::string> levels;
  for (const json& l : arr(obj_at(report, "options"), "levels"))
    if (l.is_string()) levels.push_back(l);
  if (levels.empty())
    for (const json& l : arr(obj_at(report, "spec"), "levels"))
      if (l.is_string() && l != "Meta") levels.push_back(l);
  return levels;
}

std::string fp_env_text(const json& env) {
  if (!env.is_object()) return "not observed";
  const auto on_off = [&](const char* key) { return str(env, key) == "true" ? "ON" : "off"; };
  std::string s;
  if (!str(env, "mxcsr").empty()) s += "MXCSR " + str(env, "mxcsr") + ", ";
  s += "rounding " + (str(env, "rounding").empty() ? std::string("unknown") : str(env, "rounding"));
  s += std::string(", flush-to-zero ") + on_off("flush_to_zero") + ", denormals-are-zero " + on_off("denormals_are_zero");
  return s;
}

namespace {
std::string platform_rounding(const json& platform_env) {
  const std::string r = str(platform_env, "rounding");
  // A platform that recorded none (older reports): C starts every program rounding to nearest.
  return r.empty() || r == "unknown" ? "to nearest" : r;
}
bool rounding_differs(const json& cert_env, const json& platform_env) {
  const std::string r = str(cert_env, "rounding");
  return !r.empty() && r != "unknown" && r != platform_rounding(platform_env);
}
}  // namespace

std::vector<std::string> fp_env_warnings(const json& cert_env, const json& platform_env) {
  std::vector<std::string> w;
  if (!cert_env.is_object()) return w;
  if (str(cert_env, "flush_to_zero") == "true")
    w.push_back("flush-to-zero is ON: subnormal results are replaced by zero");
  if (str(cert_env, "denormals_are_zero") == "true")
    w.push_back("denormals-are-zero is ON: subnormal inputs are read as zero");
  if (rounding_differs(cert_env, platform_env))
    w.push_back("rounding " + str(cert_env, "rounding") + " differs from the platform's (" +
                platform_rounding(platform_env) + ")");
  const std::string mine = str(cert_env, "mxcsr"), theirs = str(platform_env, "mxcsr");
  if (w.empty() && !mine.empty() && !theirs.empty() && mine != theirs)
    w.push_back("MXCSR " + mine + " differs from the platform's " + theirs + " (exception masks changed)");
  return w;
}

std::vector<std::string> fp_env_flags(const json& cert_env, const json& platform_env) {
  std::vector<std::string> f;
  if (!cert_env.is_object()) return f;
  if (str(cert_env, "flush_to_zero") == "true") f.push_back("FTZ");
  if (str(cert_env, "denormals_are_zero") == "true") f.push_back("DAZ");
  if (rounding_differs(cert_env, platform_env)) f.push_back("rounding");
  return f;
}

std::string platform_text(const json& platform) {
  if (!platform.is_object()) return {};
  std::vector<std::string> parts;
  std::string os = str(platform, "os");
  if (!str(platform, "machine").empty()) os += (os.empty() ? "" : " ") + str(platform, "machine");
  if (!os.empty()) parts.push_back(os);
  std::string cpu = str(platform, "cpu");
  if (!str(platform, "cores").empty()) cpu += (cpu.empty() ? "" : " ") + ("(" + str(platform, "cores") + " cores)");
  if (!cpu.empty()) parts.push_back(cpu);
  if (!str(platform, "compiler").empty()) parts.push_back(str(platform, "compiler"));
  std::string mpfr;
  if (!str(platform, "mpfr").empty()) mpfr = "MPFR " + str(platform, "mpfr");
  if (!str(platform, "reference_precision_bits").empty())
    mpfr += (mpfr.empty() ? "" : " ") + ("(reference " + str(platform, "reference_precision_bits") + " bits)");
  if (!mpfr.empty()) parts.push_back(mpfr);
  return join(parts, ", ");
}

bool is_mutant_list(const json& section) {
  return section.is_object() && section.contains("mutants") && section["mutants"].is_array();
}

std::string kill_rate_text(const json& section) {
  const json& k = section.is_object() && section.contains("killed") ? section["killed"] : json();
  const json& t = section.is_object() && section.contains("total") ? section["total"] : json();
  const long long killed = k.is_number_integer() ? k.get<long long>() : 0;
  const long long total = t.is_number_integer() ? t.get<long long>() : static_cast<long long>(arr(section, "mutants").size());
  std::string s = std::to_string(killed) + " of " + std::to_string(total) + " killed";
  if (total > 0) s += " (" + std::to_string(100 * killed / total) + "%)";
  return s;
}

std::vector<MutantClause> mutant_clauses(const json& mutant) {
  std::vector<MutantClause> out;
  std::set<std::string> seen;
  const auto result_of = [&](const std::string& id) -> const json* {
    for (const json& c : arr(mutant, "clauses"))
      if (str(c, "id") == id) return &c;
    return nullptr;
  };
  for (const json& b : arr(mutant, "breaks")) {
    const std::string id = b.is_string() ? b.get<std::string>() : dump(b);
    if (!seen.insert(id).second) continue;
    const json* r = result_of(id);
    out.push_back({id, r ? str(*r, "outcome") : "", r});
  }
  for (const json& c : arr(mutant, "clauses"))
    if (seen.insert(str(c, "id")).second) out.push_back({str(c, "id"), str(c, "outcome"), &c});
  return out;
}

std::string dump(const json& value, int indent) { return value.dump(indent, ' ', false, json::error_handler_t::replace); }

std::vector<std::string> verdict_notes(const json& c) {
  std::vector<std::string> notes;
  if (c.contains("status") && c["status"].is_object()) {
    const json& st = c["status"];
    notes.push_back("status (RESULT-2): " + str(st, "failures") + " input(s) with a wrong status, first " + str(st, "op") +
                    " [" + str(st, "label") + "] " + str(st, "input") + ": " + str(st, "detail"));
  }
  for (const json& a : arr(c, "acceptable"))
    notes.push_back(std::string(a.value("declared", false) ? "declared convention " : "ACCEPTABLE (ACC-1) ") +
                    str(a, "convention") + " x" + str(a, "count") + ", e.g. " + str(a, "op") + " [" + str(a, "label") +
                    "] " + str(a, "input"));
  if (c.contains("excluded") && c["excluded"].is_object() && !c["excluded"].empty()) {
    std::vector<std::string> parts;
    for (const auto& [id, n] : c["excluded"].items()) parts.push_back(id + " x" + dump(n));
    notes.push_back("not judged, outside declared preconditions (DECL-1): " + join(parts, ", "));
  }
  for (const json& d : arr(c, "diagnoses")) {
    std::string line = "CONV-1: " + str(d, "convention") + " explains " + str(d, "explained") + " of " +
                       str(d, "failing") + " failing inputs";
    if (!arr(d, "unexplained").empty()) line += "; not explained: " + join(arr(d, "unexplained"), " | ");
    notes.push_back(line);
  }
  if (c.contains("searched") && c["searched"].is_number() && c["searched"].get<double>() > 0)
    notes.push_back("worst-case search: " + str(c, "searched") + " calls around the worst inputs");
  return notes;
}

std::string declarations_text(const json& cert) {
  std::vector<std::string> parts;
  if (!arr(cert, "declared_preconditions").empty())
    parts.push_back("preconditions " + join(arr(cert, "declared_preconditions"), ", "));
  if (!arr(cert, "declared_conventions").empty())
    parts.push_back("conventions " + join(arr(cert, "declared_conventions"), ", "));
  return parts.empty() ? "" : "Declared (DECL-1): " + join(parts, "; ");
}

}  // namespace rotorcert::report::detail
