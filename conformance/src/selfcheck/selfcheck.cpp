#include <rotorcert/conformance/selfcheck.hpp>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <map>
#include <ostream>
#include <stdexcept>

#include <unistd.h>

#include "ops.hpp"

namespace rotorcert::conformance {

using nlohmann::json;

const char* to_string(ClauseOutcome o) {
  switch (o) {
    case ClauseOutcome::pass: return "PASS";
    case ClauseOutcome::fail: return "FAIL";
    case ClauseOutcome::definition: return "DEF";
  }
  return "FAIL";
}

namespace {

/// 25 significant digits: enough to see a difference far below binary64's resolution.
std::string format(const Real& x, int digits = 25) {
  if (mpfr::isnan(x)) return "nan";
  return x.toString("%." + std::to_string(digits) + "Rg");
}

/// A mismatch of two numbers, printed with enough digits to tell them apart (25, or all 256
/// bits' worth when they agree to 25 digits), and their difference.
Mismatch numeric_mismatch(const std::string& field, const Real& expected, const Real& got) {
  int digits = 25;
  if (format(expected) == format(got)) digits = 80;
  Mismatch m{field, format(expected, digits), format(got, digits), ""};
  if (mpfr::isfinite(expected) && mpfr::isfinite(got)) m.message = "difference " + format(got - expected, 3);
  return m;
}

bool matches(const Real& got, const Real& expected, const Real& bar) {
  if (mpfr::isnan(expected)) return mpfr::isnan(got);
  if (mpfr::isnan(got)) return false;
  if (mpfr::isinf(expected) || mpfr::isinf(got)) return got == expected;
  return mpfr::abs(got - expected) <= bar * mpfr::max(Real(1), mpfr::abs(expected));
}

std::string component_name(const std::string& field, const Got& got, std::size_t i) {
  switch (got.kind) {
    case Got::Kind::scalar: return field;
    case Got::Kind::multivector: return field + "[" + blade_label(got.algebra, i) + "]";
    default: return field + "[" + std::to_string(i) + "]";
  }
}

/// The expected components of one output field, in the layout of `got`.
std::vector<Real> expected_values(const json& j, const Got& got, const std::string& path) {
  switch (got.kind) {
    case Got::Kind::scalar: return {decode_expression(j, path)};
    case Got::Kind::array: {
      if (!j.is_array() || j.size() != got.values.size())
        throw DecodeError(path + ": expected an array of " + std::to_string(got.values.size()) +
                          " expressions, found " + j.dump());
      std::vector<Real> v;
      for (std::size_t i = 0; i < j.size(); ++i) v.push_back(decode_expression(j[i], path + "/" + std::to_string(i)));
      return v;
    }
    case Got::Kind::multivector: return decode_multivector(j, got.algebra, path);
    case Got::Kind::text: break;
  }
  return {};
}

/// Compares one field; appends mismatches (none when it matches).
void compare_field(const std::string& name, const json& expected_json, const Got& got, bool rotation,
                   const Real& bar, const std::string& path, std::vector<Mismatch>& out) {
  if (got.kind == Got::Kind::text) {
    if (!expected_json.is_string()) throw DecodeError(path + ": expected a string, found " + expected_json.dump());
    const std::string expected = expected_json.get<std::string>();
    if (expected != got.text) out.push_back({name, expected, got.text, ""});
    return;
  }
  const std::vector<Real> expected = expected_values(expected_json, got, path);
  auto differences = [&](bool negate) {
    std::vector<Mismatch> d;
    for (std::size_t i = 0; i < expected.size(); ++i) {
      const Real g = negate ? Real(-got.values[i]) : got.values[i];
      if (!matches(g, expected[i], bar)) d.push_back(numeric_mismatch(component_name(name, got, i), expected[i], g));
    }
    return d;
  };
  std::vector<Mismatch> d = differences(false);
  if (!d.empty() && rotation && got.sign_free && differences(true).empty()) d.clear();
  out.insert(out.end(), d.begin(), d.end());
}

}  // namespace

std::vector<std::string> supported_ops() {
  std::vector<std::string> ops;
  for (const auto& [name, handler] : op_table()) ops.push_back(name);
  return ops;  // std::map: sorted
}

Real reference_bar(const spec::Spec& spec) {
  const auto bar = spec.lookup("ref").strict_value();
  if (!bar)
    throw spec::SpecError(spec.clauses_file(), "/tolerance_classes/ref", "the \"ref\" class has no numeric strict bar");
  return *bar;
}

namespace {

ExampleResult check(const spec::Example& example, const spec::Spec& spec, const Real& bar) {
  const std::string file = spec.examples_file().string();
  ExampleResult r;
  r.id = example.id;
  r.clause = example.clause;
  r.op = example.op;
  auto problem = [&](const std::string& message) { r.mismatches.push_back({"", "", "", message}); };

  const OpTable& table = op_table();
  const auto handler = table.find(example.op);
  if (handler == table.end()) {
    problem("unknown op \"" + example.op + "\": no handler in the selfcheck dispatcher (see the op table)");
    return r;
  }
  const std::string where = file + ": " + example.json_path;
  try {
    const Outputs got = handler->second(Inputs(example.in, where + "/in", &spec));
    const std::string status = ref::to_string(got.status);
    if (status != example.status) {
      r.mismatches.push_back({"status", example.status, status, ""});
      return r;
    }
    const bool rotation = example.compare.value_or("") == "rotation";
    for (const auto& item : example.out.items()) {
      const std::string name = item.key();  // (not a structured binding: clang 14 cannot capture those)
      const json& expected = item.value();
      const auto it = std::find_if(got.fields.begin(), got.fields.end(), [&](const auto& f) { return f.first == name; });
      if (it == got.fields.end()) {
        std::string names;
        for (const auto& f : got.fields) names += (names.empty() ? "" : ", ") + f.first;
        problem("output \"" + name + "\" is not an output of op \"" + example.op + "\" (outputs: " + names + ")");
        continue;
      }
      compare_field(name, expected, it->second, rotation, bar, where + "/out/" + name, r.mismatches);
    }
    if (example.out.empty()) problem("no expected outputs in \"out\"");
  } catch (const DecodeError& e) {
    problem(e.what());
  } catch (const std::exception& e) {
    problem(std::string("the reference threw: ") + e.what());
  }
  r.passed = r.mismatches.empty();
  return r;
}

}  // namespace

ExampleResult check_example(const spec::Example& example, const spec::Spec& spec) {
  return check(example, spec, reference_bar(spec));
}

SelfcheckReport run_selfcheck(const spec::Spec& spec) {
  SelfcheckReport report;
  report.spec_dir = spec.dir;
  report.spec_version = spec.version;
  const Real bar = reference_bar(spec);
  report.tolerance = *spec.lookup("ref").strict;

  std::map<std::string, std::vector<const spec::Example*>> by_clause;
  for (const auto& e : spec.examples) by_clause[e.clause].push_back(&e);
  for (const auto& c : spec.clauses) {
    ClauseResult cr;
    cr.id = c.id;
    cr.title = c.title;
    cr.has_op = c.op.has_value();
    for (const spec::Example* e : by_clause[c.id]) {
      ExampleResult er = check(*e, spec, bar);
      ++cr.examples_total;
      if (er.passed) ++cr.examples_passed;
      else cr.failures.push_back(std::move(er));
    }
    cr.outcome = cr.examples_total == 0 ? ClauseOutcome::definition
                 : cr.failures.empty()  ? ClauseOutcome::pass
                                        : ClauseOutcome::fail;
    report.examples_total += cr.examples_total;
    report.examples_passed += cr.examples_passed;
    if (cr.outcome == ClauseOutcome::pass) ++report.passed;
    else if (cr.outcome == ClauseOutcome::fail) ++report.failed;
    else ++report.definitions;
    report.clauses.push_back(std::move(cr));
  }
  for (const auto& e : spec.examples) {
    if (spec.find_clause(e.clause)) continue;
    ExampleResult er;
    er.id = e.id;
    er.clause = e.clause;
    er.op = e.op;
    er.mismatches.push_back({"", "", "", "names clause \"" + e.clause + "\", which is not in clauses.json"});
    ++report.examples_total;
    ++report.failed;
    report.orphans.push_back(std::move(er));
  }
  return report;
}

namespace {

void print_mismatches(std::ostream& out, const ExampleResult& e) {
  for (const auto& m : e.mismatches) {
    out << "      " << e.id << "  ";
    if (m.field.empty()) out << m.message << '\n';
    else if (m.message.empty()) out << m.field << ": expected " << m.expected << "  got " << m.got << '\n';
    else out << m.field << ": expected " << m.expected << "  got " << m.got << "  (" << m.message << ")\n";
  }
}

}  // namespace

void print_report(std::ostream& out, const SelfcheckReport& report, bool verbose) {
  std::size_t width = 0;
  for (const auto& c : report.clauses) width = std::max(width, c.id.size());
  constexpr std::size_t kTitle = 64;
  for (const auto& c : report.clauses) {
    std::string title = c.title;
    if (!verbose && title.size() > kTitle) title = title.substr(0, kTitle - 3) + "...";
    out << to_string(c.outcome) << std::string(6 - std::string(to_string(c.outcome)).size(), ' ') << c.id
        << std::string(width - c.id.size() + 2, ' ') << title << "  ";
    if (c.outcome == ClauseOutcome::definition)
      out << (c.has_op ? "(no worked example yet)" : "(definition: no worked example)") << '\n';
    else
      out << "(" << c.examples_passed << "/" << c.examples_total << " examples)\n";
    for (const auto& e : c.failures) print_mismatches(out, e);
  }
  for (const auto& e : report.orphans) {
    out << "FAIL  example " << e.id << '\n';
    print_mismatches(out, e);
  }
  out << "selfcheck: " << report.passed << " passed, " << report.failed << " failed, " << report.definitions
      << " definitions without examples (" << report.examples_passed << "/" << report.examples_total
      << " examples agree with the reference, bar " << report.tolerance << ")\n";
}

json to_json(const SelfcheckReport& report) {
  auto example_json = [](const ExampleResult& e) {
    json mismatches = json::array();
    for (const auto& m : e.mismatches) {
      json jm = json::object();
      if (!m.field.empty()) jm["field"] = m.field;
      if (!m.message.empty()) jm["message"] = m.message;
      if (!m.expected.empty() || !m.got.empty()) {
        jm["expected"] = m.expected;
        jm["got"] = m.got;
      }
      mismatches.push_back(jm);
    }
    return json{{"example", e.id}, {"clause", e.clause}, {"op", e.op}, {"mismatches", mismatches}};
  };
  json clauses = json::array();
  for (const auto& c : report.clauses) {
    json failures = json::array();
    for (const auto& e : c.failures) failures.push_back(example_json(e));
    clauses.push_back({{"id", c.id},
                       {"title", c.title},
                       {"result", to_string(c.outcome)},
                       {"examples_passed", c.examples_passed},
                       {"examples_total", c.examples_total},
                       {"failures", failures}});
  }
  json orphans = json::array();
  for (const auto& e : report.orphans) orphans.push_back(example_json(e));
  return {{"tool", "rotorcert selfcheck"},
          {"spec_dir", report.spec_dir.string()},
          {"spec_version", report.spec_version},
          {"precision_bits", mpfr::mpreal::get_default_prec()},
          {"tolerance", report.tolerance},
          {"summary",
           {{"passed", report.passed},
            {"failed", report.failed},
            {"definitions", report.definitions},
            {"examples_passed", report.examples_passed},
            {"examples_total", report.examples_total},
            {"ok", report.ok()}}},
          {"clauses", clauses},
          {"orphan_examples", orphans}};
}

void write_file_atomically(const std::filesystem::path& file, const std::string& text) {
  const std::filesystem::path dir = file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
  const std::filesystem::path temp = dir / ("." + file.filename().string() + ".tmp." + std::to_string(::getpid()));
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot write " + temp.string() + ": " + std::strerror(errno));
    out << text;
    out.flush();
    if (!out) {
      std::error_code ignored;
      std::filesystem::remove(temp, ignored);
      throw std::runtime_error("cannot write " + temp.string());
    }
  }
  std::error_code ec;
  std::filesystem::rename(temp, file, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(temp, ignored);
    throw std::runtime_error("cannot rename " + temp.string() + " to " + file.string() + ": " + ec.message());
  }
}

}  // namespace rotorcert::conformance
