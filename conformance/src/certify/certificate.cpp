#include <rotorcert/certify/certificate.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <set>
#include <sstream>
#include <stdexcept>

#include <rotorcert/certify/platform.hpp>
#include <rotorcert/reference/metrics.hpp>
#include <rotorcert/report/render.hpp>

#ifndef ROTORCERT_SOURCE_DIR
#error "ROTORCERT_SOURCE_DIR must be defined by the build"
#endif
#ifndef ROTORCERT_VERSION
#error "ROTORCERT_VERSION must be defined by the build"
#endif

namespace rotorcert::certify {
namespace {

using engine::Outcome;

const char* const kLevelNames[] = {"Core", "Interp", "Blend", "Rigid", "Skinning", "Robust"};

/// NaN and infinities have no JSON number: they become null.
json number_or_null(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }
double double_or_nan(const json& j) { return j.is_number() ? j.get<double>() : NAN; }

/// The unit an op's error is reported in once multiplied by eps (SPEC section 3).
std::string unit_of(const engine::AbiOp& op) {
  switch (op.outputs.front().measure) {
    case engine::Measure::rotation:
    case engine::Measure::quaternion:
    case engine::Measure::unit_rotation:
    case engine::Measure::canonical_rotation:
    case engine::Measure::bivector:
    case engine::Measure::angle: return "rad";
    case engine::Measure::rigid:
    case engine::Measure::unit_rigid: return "rad/relative";
    default: return "relative";
  }
}

/// Nearest-rank percentile of sorted values.
double percentile(const std::vector<double>& sorted, double p) {
  if (sorted.empty()) return 0;
  const auto rank = static_cast<std::size_t>(std::ceil(p / 100.0 * static_cast<double>(sorted.size())));
  return sorted[std::min(sorted.size() - 1, rank == 0 ? 0 : rank - 1)];
}

const std::vector<double>& histogram_edges() {
  static const std::vector<double> edges = {0.5, 1, 2, 4, 8, 16, 32, 64, 128, 256, 512, 1024};
  return edges;
}

json accuracy_json(const Certificate& c) {
  json all = json::array();
  const double eps = ref::format_epsilon<double>(c.table.format());
  for (const engine::AbiOp& op : engine::abi_ops()) {
    std::vector<double> errors;
    const engine::WorstCase* worst = nullptr;
    std::string worst_clause;
    for (const engine::ClauseResult& r : c.clauses) {
      if (const auto it = r.errors.find(op.name); it != r.errors.end())
        errors.insert(errors.end(), it->second.begin(), it->second.end());
      if (const auto it = r.worst_by_op.find(op.name); it != r.worst_by_op.end())
        if (worst == nullptr || it->second.error > worst->error) {
          worst = &it->second;
          worst_clause = r.clause;
        }
    }
    if (errors.empty()) continue;
    std::sort(errors.begin(), errors.end());
    std::vector<int> counts(histogram_edges().size() + 1, 0);
    for (double e : errors)
      ++counts[std::lower_bound(histogram_edges().begin(), histogram_edges().end(), e) - histogram_edges().begin()];
    json a = {{"op", op.name},
              {"unit", unit_of(op)},
              {"eps", eps},
              {"cases", errors.size()},
              {"max_eps", errors.back()},
              {"max", errors.back() * eps},
              {"p50_eps", percentile(errors, 50)},
              {"p99_eps", percentile(errors, 99)},
              {"worst_clause", worst_clause},
              {"worst_label", worst ? worst->label : ""},
              {"worst_input", worst ? worst->input : ""},
              {"worst_detail", worst ? worst->detail : ""},
              {"histogram", {{"edges_eps", histogram_edges()}, {"counts", counts}}}};
    all.push_back(std::move(a));
  }
  return all;
}

bool claimed(const Certificate& c, const std::string& clause) {
  return std::find(c.table.claimed_clauses.begin(), c.table.claimed_clauses.end(), clause) !=
         c.table.claimed_clauses.end();
}

bool good(const std::string& outcome) { return outcome == "PASS" || outcome == "QUALITY_WARNING"; }

}  // namespace

bool claimed_clause_good(const json& clause_result) {
  const std::string outcome = clause_result.at("outcome");
  if (good(outcome)) return true;
  // DECL-1: NOT_SUPPORTED because every input, or the Robust inputs, lie outside the table's
  // declared preconditions is what the table declared, not a surprise.
  const auto e = clause_result.find("excluded");
  return outcome == "NOT_SUPPORTED" && e != clause_result.end() && e->is_object() && !e->empty();
}

namespace {

}  // namespace

TableInfo table_info(const rc_impl& table, std::string source, std::string plugin_path) {
  TableInfo t;
  t.name = table.name ? table.name : "";
  t.scalar = table.scalar == RC_SCALAR_FLOAT32 ? "float" : "double";
  t.version = table.version ? table.version : "";
  t.description = table.description ? table.description : "";
  t.source = std::move(source);
  t.plugin_path = std::move(plugin_path);
  for (int i = 0; i < 6; ++i)
    if (table.levels & (1u << i)) t.claimed_levels.emplace_back(kLevelNames[i]);
  t.claimed_clauses = engine::claimed_clauses(table);
  for (const engine::AbiOp& op : engine::abi_ops())
    if (engine::supports(table, op.name)) t.supported_ops.push_back(op.name);
  const engine::Declarations d = engine::declarations_of(table);
  t.declared_preconditions.assign(d.preconditions.begin(), d.preconditions.end());
  t.declared_conventions.assign(d.conventions.begin(), d.conventions.end());
  return t;
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
  if (r.worst_op.empty() && r.worst_input.empty()) {
    j["worst"] = nullptr;
  } else {
    j["worst"] = {{"error_eps", number_or_null(r.worst_error)},
                  {"op", r.worst_op},
                  {"label", r.worst_label},
                  {"input", r.worst_input},
                  {"detail", r.worst_detail}};
  }
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

std::map<std::string, std::string> read_expected_failures(const std::filesystem::path& file, const std::string& table,
                                                          const std::string& scalar) {
  std::map<std::string, std::string> result;
  if (!std::filesystem::exists(file)) return result;
  const json j = spec::read_json(file);
  for (const json& f : j.at("failures"))
    if (f.at("table") == table && f.at("scalar") == scalar) result[f.at("clause")] = f.at("why");
  return result;
}

std::filesystem::path builtin_expected_failures_file(const std::string& impl_name) {
  return std::filesystem::path(ROTORCERT_SOURCE_DIR) / "impls" / impl_name / "expected_failures.json";
}

std::map<std::string, std::string> expected_failures(const std::string& impl_name, const std::string& scalar) {
  // The file sits in the directory of the implementation that provides the table; a directory
  // may provide several tables (glm_quat also provides glm_mix), so every file is read.
  std::map<std::string, std::string> result;
  const std::filesystem::path impls = std::filesystem::path(ROTORCERT_SOURCE_DIR) / "impls";
  std::error_code ec;
  for (const auto& dir : std::filesystem::directory_iterator(impls, ec))
    for (auto& [clause, why] : read_expected_failures(dir.path() / "expected_failures.json", impl_name, scalar))
      result[clause] = why;
  return result;
}

json levels_json(const Certificate& c, const std::vector<std::string>& levels) {
  json all = json::array();
  for (const std::string& level : levels) {
    std::map<std::string, int> counts;
    std::vector<std::string> not_pass;
    bool met = true, warnings = false, any = false;
    for (const engine::ClauseResult& r : c.clauses) {
      if (r.level != level) continue;
      any = true;
      const std::string code = engine::to_string(r.outcome);
      ++counts[code];
      if (r.outcome != Outcome::pass) not_pass.push_back(r.clause);
      if (r.outcome == Outcome::quality_warning) warnings = true;
      else if (r.outcome != Outcome::pass) met = false;
    }
    if (!any) continue;
    const std::string status = !met ? "not met" : warnings ? "met with warnings" : "met";
    all.push_back({{"level", level}, {"status", status}, {"counts", counts}, {"clauses", not_pass}});
  }
  return all;
}

json certificate_json(const spec::Spec& spec, const Certificate& c, const std::vector<std::string>& levels) {
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
            {"fp_environment", c.fp_environment}};
  const json lv = levels_json(c, levels);
  std::string met;
  for (const json& l : lv)
    if (l.at("status") != "not met") met += (met.empty() ? "" : ", ") + l.at("level").get<std::string>();
  j["claim"] = std::string("rotorcert ") + ROTORCERT_VERSION + ": " + (met.empty() ? "no level met" : met) + " (" +
               j.at("format").get<std::string>() + ")";
  j["levels"] = lv;
  json ef = json::array();
  for (const auto& [clause, why] : c.expected_failures) ef.push_back({{"clause", clause}, {"why", why}});
  j["expected_failures"] = ef;

  std::map<std::string, std::vector<std::string>> by_convention;
  json clauses = json::array();
  for (const engine::ClauseResult& r : c.clauses) {
    json cj = to_json(r, false);
    cj["claimed"] = claimed(c, r.clause);
    const auto ef_it = c.expected_failures.find(r.clause);
    cj["expected_failure"] = ef_it == c.expected_failures.end() ? json(nullptr) : json(ef_it->second);
    const auto rp = c.reproduce.find(r.clause);
    cj["reproduce"] = rp == c.reproduce.end() ? "" : rp->second;
    for (const std::string& conv : r.conventions) by_convention[conv].push_back(r.clause);
    clauses.push_back(std::move(cj));
  }
  j["clauses"] = clauses;
  json conv = json::array();
  for (const engine::Convention& cv : engine::conventions())
    if (const auto it = by_convention.find(cv.id); it != by_convention.end())
      conv.push_back({{"id", cv.id}, {"description", cv.description}, {"clauses", it->second}});
  j["conventions"] = conv;
  j["accuracy"] = accuracy_json(c);
  j["as_expected"] = as_expected(j);
  (void)spec;
  return j;
}

bool as_expected(const json& certificate) {
  if (!certificate.at("error").is_null()) return false;
  for (const json& r : certificate.at("clauses")) {
    if (!r.at("claimed").get<bool>()) continue;
    const std::string outcome = r.at("outcome");
    if (r.at("expected_failure").is_null() ? !claimed_clause_good(r) : outcome != "FAIL") return false;
  }
  // An expected failure of a clause that was not run (filtered out) is no surprise.
  return true;
}

json report_json(const spec::Spec& spec, const std::string& kind, const json& options, const json& run,
                 const std::vector<json>& certificates) {
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
  for (const char* code : {"PASS", "QUALITY_WARNING", "FAIL", "NOT_SUPPORTED", "CRASH", "TIMEOUT"}) counts[code] = 0;
  bool all_expected = true, all_pass = true;
  for (const json& c : certificates) {
    all_expected = all_expected && c.at("as_expected").get<bool>();
    if (!c.at("error").is_null()) all_pass = false;
    for (const json& r : c.at("clauses")) {
      ++counts[r.at("outcome").get<std::string>()];
      if (r.at("claimed").get<bool>() && !good(r.at("outcome"))) all_pass = false;
    }
  }
  // report: 0 when every table behaves as expected (known defects fail, the rest passes);
  // certify and vectors check: 0 when every claimed clause passes.
  const bool ok = kind == "report" || kind == "third-party" ? all_expected : all_pass;
  return {{"format", "rotorcert-report"},
          {"format_version", 1},
          {"rotorcert_version", ROTORCERT_VERSION},
          {"spec_version", spec.version},
          {"kind", kind},
          {"options", options},
          {"platform", platform_json()},
          {"run", run},
          {"spec", {{"levels", spec.levels}, {"clauses", clauses}, {"tolerance_classes", classes}}},
          {"implementations", certificates},
          {"summary",
           {{"tables", certificates.size()}, {"counts", counts}, {"as_expected", all_expected}, {"exit_code", ok ? 0 : 1}}},
          {"sections", json::object()}};
}

void print_certificate(std::ostream& out, const json& c, bool verbose) {
  out << c.at("name").get<std::string>() << " (" << c.at("scalar").get<std::string>() << ", "
      << c.at("source").get<std::string>() << "): " << c.at("claim").get<std::string>() << '\n';
  if (!c.at("error").is_null()) out << "  error: " << c.at("error").get<std::string>() << '\n';
  if (const json& env = c.at("fp_environment"); env.is_object() &&
      (env.at("flush_to_zero").get<bool>() || env.at("denormals_are_zero").get<bool>()))
    out << "  floating-point environment after loading the implementation: flush-to-zero "
        << (env.at("flush_to_zero").get<bool>() ? "ON" : "off") << ", denormals-are-zero "
        << (env.at("denormals_are_zero").get<bool>() ? "ON" : "off") << " (MXCSR " << env.at("mxcsr").get<std::string>()
        << "); it was tested so (NUM-1)\n";
  for (const json& r : c.at("clauses")) {
    const std::string outcome = r.at("outcome");
    const bool expected = !r.at("expected_failure").is_null();
    if (!verbose && outcome == "PASS") continue;
    if (!verbose && outcome == "NOT_SUPPORTED" && !r.at("claimed").get<bool>()) continue;
    out << "  " << std::left << std::setw(11) << r.at("id").get<std::string>() << std::setw(16) << outcome;
    if (const json& w = r.at("worst"); w.is_object()) {
      std::ostringstream err;
      if (w.at("error_eps").is_null()) err << "NaN/status";
      else err << std::setprecision(3) << w.at("error_eps").get<double>() << " eps";
      out << std::setw(14) << err.str() << w.at("op").get<std::string>() << " [" << w.at("label").get<std::string>()
          << "]";
    }
    if (expected) out << "  (known defect)";
    out << '\n';
    if (!r.at("note").get<std::string>().empty()) out << "      " << r.at("note").get<std::string>() << '\n';
    if (outcome != "PASS" && outcome != "NOT_SUPPORTED" && r.at("worst").is_object()) {
      out << "      input:  " << r.at("worst").at("input").get<std::string>() << '\n';
      if (verbose || !expected) out << "      detail: " << r.at("worst").at("detail").get<std::string>() << '\n';
    }
    if (!r.at("conventions").empty()) {
      out << "      consistent with convention:";
      for (const json& cv : r.at("conventions")) out << ' ' << cv.get<std::string>();
      out << '\n';
    }
    if (outcome != "PASS" && outcome != "NOT_SUPPORTED" && !expected && !r.at("reproduce").get<std::string>().empty())
      out << "      reproduce: " << r.at("reproduce").get<std::string>() << '\n';
  }
  out << "  levels:";
  for (const json& l : c.at("levels"))
    out << "  " << l.at("level").get<std::string>() << ": " << l.at("status").get<std::string>();
  out << '\n';
}

void write_atomically(const std::filesystem::path& file, const std::string& contents) {
  const std::filesystem::path dir = file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
  std::string tmpl = (dir / ("." + file.filename().string() + ".XXXXXX")).string();
  const int fd = ::mkstemp(tmpl.data());
  if (fd < 0) throw std::runtime_error("cannot create a temporary file in " + dir.string() + ": " + std::strerror(errno));
  const char* p = contents.data();
  std::size_t left = contents.size();
  while (left > 0) {
    const ssize_t w = ::write(fd, p, left);
    if (w < 0 && errno == EINTR) continue;
    if (w < 0) {
      const std::string why = std::strerror(errno);
      ::close(fd);
      ::unlink(tmpl.c_str());
      throw std::runtime_error("cannot write " + tmpl + ": " + why);
    }
    p += w;
    left -= static_cast<std::size_t>(w);
  }
  ::fchmod(fd, 0644);
  if (::fsync(fd) != 0 || ::close(fd) != 0) {
    ::unlink(tmpl.c_str());
    throw std::runtime_error("cannot flush " + tmpl);
  }
  if (::rename(tmpl.c_str(), file.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    ::unlink(tmpl.c_str());
    throw std::runtime_error("cannot rename " + tmpl + " to " + file.string() + ": " + why);
  }
}

void write_report(const std::filesystem::path& dir, const json& report) {
  std::filesystem::create_directories(dir);
  write_atomically(dir / "report.json", report.dump(2) + "\n");
  write_atomically(dir / "report.md", report::render_markdown(report));
  write_atomically(dir / "report.html", report::render_html(report));
}

}  // namespace rotorcert::certify
