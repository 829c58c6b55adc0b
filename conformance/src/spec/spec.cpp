#include <rotorcert/spec/spec.hpp>

#include <rotorcert/spec/data_layout.hpp>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <mutex>
#include <set>
#include <sstream>

#include <rotorcert/spec/expr.hpp>

namespace rotorcert::spec {

using nlohmann::json;

SpecError::SpecError(std::filesystem::path file, std::string json_path, const std::string& message)
    : std::runtime_error(file.string() + (json_path.empty() ? "" : ": " + json_path) + ": " + message),
      file_(std::move(file)),
      json_path_(std::move(json_path)) {}

namespace {

const char* type_name(const json& j) { return j.type_name(); }

/// Reads fields of one JSON object, reporting problems with the file and JSON path.
class Reader {
 public:
  Reader(const json& j, const std::filesystem::path& file, std::string path)
      : j_(j), file_(file), path_(std::move(path)) {
    if (!j_.is_object()) fail("expected an object, found " + std::string(type_name(j_)));
  }

  [[noreturn]] void fail(const std::string& message) const { throw SpecError(file_, path_, message); }
  [[noreturn]] void fail_at(const std::string& key, const std::string& message) const {
    throw SpecError(file_, child(key), message);
  }
  std::string child(const std::string& key) const { return path_ + "/" + key; }

  const json* find(const std::string& key) const {
    const auto it = j_.find(key);
    return it == j_.end() ? nullptr : &*it;
  }
  const json& require(const std::string& key) const {
    const json* v = find(key);
    if (!v) fail("missing field \"" + key + "\"");
    return *v;
  }
  std::string string(const std::string& key) const {
    const json& v = require(key);
    if (!v.is_string()) fail_at(key, "expected a string, found " + std::string(type_name(v)));
    return v.get<std::string>();
  }
  std::optional<std::string> optional_string(const std::string& key) const {
    const json* v = find(key);
    if (!v) return std::nullopt;
    if (!v->is_string()) fail_at(key, "expected a string, found " + std::string(type_name(*v)));
    return v->get<std::string>();
  }
  /// A bar of a tolerance class: a number or a string; kept as text.
  std::optional<std::string> bar(const std::string& key) const {
    const json* v = find(key);
    if (!v) return std::nullopt;
    if (v->is_string()) return v->get<std::string>();
    if (v->is_number()) return v->dump();
    fail_at(key, "expected a number or a string, found " + std::string(type_name(*v)));
  }
  const json& object(const std::string& key) const {
    const json& v = require(key);
    if (!v.is_object()) fail_at(key, "expected an object, found " + std::string(type_name(v)));
    return v;
  }
  const json& array(const std::string& key) const {
    const json& v = require(key);
    if (!v.is_array()) fail_at(key, "expected an array, found " + std::string(type_name(v)));
    return v;
  }

 private:
  const json& j_;
  const std::filesystem::path& file_;
  std::string path_;
};

std::optional<ref::Real> bar_value(const ToleranceClass& c, const std::optional<std::string>& text) {
  if (!text) return std::nullopt;
  if (c.kind != "exact" && c.kind != "eps" && c.kind != "absolute") return std::nullopt;
  return evaluate(*text);
}

}  // namespace

std::optional<ref::Real> ToleranceClass::strict_value() const { return bar_value(*this, strict); }
std::optional<ref::Real> ToleranceClass::loose_value() const { return bar_value(*this, loose); }

const Clause* Spec::find_clause(const std::string& id) const {
  const auto it = std::find_if(clauses.begin(), clauses.end(), [&](const Clause& c) { return c.id == id; });
  return it == clauses.end() ? nullptr : &*it;
}

const ToleranceClass& Spec::lookup(const std::string& name) const {
  const auto it = tolerance_classes.find(name);
  if (it == tolerance_classes.end())
    throw SpecError(clauses_file(), "/tolerance_classes", "no tolerance class \"" + name + "\"");
  return it->second;
}

std::filesystem::path default_spec_dir() { return data_layout().spec_dir; }

std::filesystem::path resolve_spec_dir(const std::optional<std::filesystem::path>& option) {
  if (option) return *option;
  if (const char* env = std::getenv("ROTORCERT_SPEC_DIR"); env && *env) return std::filesystem::path(env);
  return default_spec_dir();
}

json read_json(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw SpecError(file, "", "cannot open the file");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  try {
    return json::parse(buffer.str());
  } catch (const json::parse_error& e) {
    throw SpecError(file, "", std::string("not valid JSON: ") + e.what());
  }
}

void parse_clauses(const json& j, const std::filesystem::path& file, Spec& spec) {
  const Reader top(j, file, "");
  spec.version = top.string("version");

  const json& levels = top.array("levels");
  spec.levels.clear();
  for (std::size_t i = 0; i < levels.size(); ++i) {
    if (!levels[i].is_string()) throw SpecError(file, "/levels/" + std::to_string(i), "expected a string");
    spec.levels.push_back(levels[i].get<std::string>());
  }

  spec.tolerance_classes.clear();
  for (const auto& [name, value] : top.object("tolerance_classes").items()) {
    const Reader r(value, file, "/tolerance_classes/" + name);
    ToleranceClass c;
    c.name = name;
    c.kind = r.string("kind");
    c.strict = r.bar("strict");
    c.loose = r.bar("loose");
    c.doc = r.optional_string("doc").value_or("");
    if ((c.kind == "exact" || c.kind == "eps" || c.kind == "absolute") && (!c.strict || !c.loose))
      r.fail("a class of kind \"" + c.kind + "\" needs \"strict\" and \"loose\"");
    for (const auto* bar : {&c.strict, &c.loose}) {
      try {
        (void)bar_value(c, *bar);
      } catch (const ExprError& e) {
        r.fail_at(bar == &c.strict ? "strict" : "loose", e.what());
      }
    }
    spec.tolerance_classes.emplace(name, std::move(c));
  }

  const json& clauses = top.array("clauses");
  spec.clauses.clear();
  std::set<std::string> seen;
  for (std::size_t i = 0; i < clauses.size(); ++i) {
    const Reader r(clauses[i], file, "/clauses/" + std::to_string(i));
    Clause c;
    c.id = r.string("id");
    c.title = r.string("title");
    c.level = r.string("level");
    c.tolerance = r.string("tolerance");
    c.op = r.optional_string("op");
    if (c.id.empty()) r.fail_at("id", "empty clause id");
    if (!seen.insert(c.id).second) r.fail_at("id", "duplicate clause id \"" + c.id + "\"");
    if (std::find(spec.levels.begin(), spec.levels.end(), c.level) == spec.levels.end())
      r.fail_at("level", "level \"" + c.level + "\" is not in /levels");
    if (!spec.tolerance_classes.count(c.tolerance))
      r.fail_at("tolerance", "tolerance class \"" + c.tolerance + "\" is not in /tolerance_classes");
    spec.clauses.push_back(std::move(c));
  }
}

std::vector<Example> parse_examples(const json& j, const std::filesystem::path& file, std::string* version) {
  const Reader top(j, file, "");
  if (version) *version = top.optional_string("version").value_or("");
  const json& list = top.array("examples");
  std::vector<Example> examples;
  std::set<std::string> seen;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string path = "/examples/" + std::to_string(i);
    const Reader r(list[i], file, path);
    Example e;
    e.json_path = path;
    e.id = r.string("id");
    e.clause = r.string("clause");
    e.op = r.string("op");
    e.in = r.object("in");
    e.out = r.object("out");
    e.status = r.string("status");
    e.compare = r.optional_string("compare");
    e.comment = r.optional_string("comment").value_or("");
    if (!seen.insert(e.id).second) r.fail_at("id", "duplicate example id \"" + e.id + "\"");
    if (e.status != "OK" && e.status != "DOMAIN_ERROR")
      r.fail_at("status", "expected \"OK\" or \"DOMAIN_ERROR\", found \"" + e.status + "\"");
    if (e.compare && *e.compare != "rotation")
      r.fail_at("compare", "the only comparison mode is \"rotation\", found \"" + *e.compare + "\"");
    examples.push_back(std::move(e));
  }
  return examples;
}

std::map<std::string, std::string> parse_pending(const json& j, const std::filesystem::path& file) {
  const Reader top(j, file, "");
  std::map<std::string, std::string> pending;
  for (const auto& [id, reason] : top.object("pending").items()) {
    if (!reason.is_string() || reason.get<std::string>().empty())
      throw SpecError(file, "/pending/" + id, "expected a nonempty string giving the reason");
    pending.emplace(id, reason.get<std::string>());
  }
  return pending;
}

Spec load_spec(const std::filesystem::path& dir) {
  Spec spec;
  spec.dir = dir;
  if (!std::filesystem::is_directory(dir)) throw SpecError(dir, "", "not a directory (the spec directory)");
  parse_clauses(read_json(spec.clauses_file()), spec.clauses_file(), spec);
  if (std::filesystem::exists(spec.examples_file()))
    spec.examples = parse_examples(read_json(spec.examples_file()), spec.examples_file(), &spec.examples_version);
  if (std::filesystem::exists(spec.pending_file()))
    spec.pending = parse_pending(read_json(spec.pending_file()), spec.pending_file());
  return spec;
}

ToleranceClass lookup(const std::string& name) {
  static std::mutex mutex;
  static std::optional<Spec> cached;
  const std::lock_guard<std::mutex> lock(mutex);
  if (!cached) cached = load_spec(resolve_spec_dir());
  return cached->lookup(name);
}

}  // namespace rotorcert::spec
