#include <rotorcert/vectors/vector_file.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <stdexcept>

#include <rotorcert/engine/runner.hpp>
#include <rotorcert/vectors/error.hpp>
#include <rotorcert/vectors/flags.hpp>

#ifndef ROTORCERT_VERSION
#error "ROTORCERT_VERSION must be defined by the build"
#endif

namespace rotorcert::vectors {
namespace {

using nlohmann::json;
using nlohmann::ordered_json;
using engine::Real;

const char* measure_name(engine::Measure m) {
  using engine::Measure;
  switch (m) {
    case Measure::rotation: return "rotation";
    case Measure::quaternion: return "quaternion";
    case Measure::unit_rotation: return "unit_rotation";
    case Measure::signed_unit_rotation: return "signed_unit_rotation";
    case Measure::canonical_rotation: return "canonical_rotation";
    case Measure::vector: return "vector";
    case Measure::point: return "point";
    case Measure::bivector: return "bivector";
    case Measure::matrix: return "matrix";
    case Measure::angle: return "angle";
    case Measure::scalar: return "scalar";
    case Measure::rigid: return "rigid";
    case Measure::unit_rigid: return "unit_rigid";
    case Measure::dual_parts: return "dual_parts";
  }
  return "scalar";
}

/// How each measure is computed (engine/runner.cpp, SPEC section 3), for adapter authors.
const char* measure_doc(engine::Measure m) {
  using engine::Measure;
  switch (m) {
    case Measure::rotation: return "METRIC-1: the angle in radians of the rotation between got and expected, sign-free (q and -q are one rotation)";
    case Measure::quaternion: return "max(METRIC-1, max_i |q_i - r_i| / |r|): the quaternion itself, sign and scale included (COMPOSE-1, INV-1 are defined on non-unit input)";
    case Measure::unit_rotation: return "max(METRIC-1, METRIC-6 = | |q| - 1 |): a rotation that must be a unit quaternion";
    case Measure::signed_unit_rotation: return "max(METRIC-1, METRIC-6, max_i |q_i - r_i|): a unit quaternion whose sign is specified too (SLERP-3's endpoints a and b'), so -r costs 2";
    case Measure::canonical_rotation: return "unit_rotation, and when got . expected < 0 at least |w_expected|: the canonical sign w > 0 of MAT-2, enforced once |w| exceeds the bar";
    case Measure::vector: return "METRIC-3: |v - v_ref| / |v_ref|, absolute when |v_ref| is below the smallest normal number";
    case Measure::point: return "|p - p_ref| / max(1, |p|, |t|, ...) over the lengths of the case's inputs (rigid operations)";
    case Measure::bivector: return "METRIC-5: error of a rotation log, in radians";
    case Measure::matrix: return "METRIC-4: error of a rotation matrix";
    case Measure::angle: return "absolute error in radians";
    case Measure::scalar: return "relative error, absolute when the expected value is 0";
    case Measure::rigid: return "METRIC-7: max(METRIC-1 of the real parts, |t - t_ref| / max(1, |t_ref|)) after DQ-4 normalisation";
    case Measure::unit_rigid: return "METRIC-7, METRIC-6 of the real part and the orthogonality defect |r.d| / max(1, |t_ref|): a dual quaternion that must be unit";
    case Measure::dual_parts: return "max(max_i |r_i - r_ref_i|, |d - d_ref| / max(1, |xi_d|), METRIC-6 of r): a unit dual quaternion with a definite sign, its dual part relative to the size of the input's dual part (DQ-9)";
  }
  return "";
}

/// What an array holds, in words (impl_abi.h).
std::string layout(const std::string& op, const engine::Array& a) {
  std::string s;
  switch (a.stride) {
    case 4: s = "quaternion [x, y, z, w]"; break;
    case 8: s = "dual quaternion [real x, y, z, w, dual x, y, z, w], dual = 1/2 t real"; break;
    case 9: s = "3x3 rotation matrix, column-major m[c*3 + r]"; break;
    case 6: s = "dual vector [xi_r x, y, z, xi_d x, y, z]: the log of a unit dual quaternion (DQ-8)"; break;
    case 3:
      if ((op == "apply_bivector" && (a.name == "b" || a.name == "out_b"))) s = "bivector [e23, e31, e12]";
      else if ((op == "exp" && a.name == "v") || ((op == "log" || op == kRoundTripOp) && a.name == "out_v"))
        s = "rotation log [x, y, z] = (angle/2) axis";
      else if (a.name == "axis" || a.name == "u" || a.name == "out_axis") s = "axis [x, y, z]";
      else if (a.name == "t" || a.name == "ta" || a.name == "tb" || a.name == "out_t") s = "translation [x, y, z]";
      else s = "vector / point [x, y, z]";
      break;
    default:
      if (a.name == "w") s = "weight";
      else if (a.name == "t") s = "interpolation parameter t";
      else if (a.name == "angle" || a.name == "out_angle") s = "angle in radians";
      else if (a.name == "s" || a.name == "out_s") s = "trivector coefficient (e123)";
      else s = "scalar";
  }
  if (a.per_influence) s += ", one per influence (k per test)";
  return s;
}

std::string decimal(const Real& x, int digits) {
  if (mpfr::isnan(x)) return "nan";
  if (mpfr::isinf(x)) return x > 0 ? "inf" : "-inf";
  if (mpfr::iszero(x)) return mpfr::signbit(x) ? "-0" : "0";
  return x.toString("%." + std::to_string(digits) + "Rg");
}

ordered_json hex_dec(const std::vector<Real>& v, ref::Format f, int digits) {
  ordered_json hex = ordered_json::array(), dec = ordered_json::array();
  for (const Real& x : v) {
    hex.push_back(engine::hexfloat(x, f));
    dec.push_back(decimal(x, digits));
  }
  return ordered_json{{"hex", hex}, {"dec", dec}};
}

/// Digits that make an input's decimal round-trip to its value in the format.
int roundtrip_digits(ref::Format f) { return f == ref::Format::binary32 ? 9 : 17; }

/// Digits of an expected value: the 256-bit reference, beyond either format.
constexpr int kExpectedDigits = 20;

/// Wycheproof's three results with the meaning of ACC-1: "invalid" (DOMAIN_ERROR required, no
/// sentinel of ACC-1 acceptable: a NaN, an infinity, a reflection),
/// "acceptable" (an informative clause, or an input where an acceptable convention can give
/// another correct output: `acceptable` names them), "valid" (the expected output is the one
/// correct answer up to the tolerance).
std::string result_of(const spec::ToleranceClass& tc, ref::Status status, const std::vector<std::string>& acceptable) {
  if (status == ref::Status::domain_error) return acceptable.empty() ? "invalid" : "acceptable";
  if (tc.kind == "informative" || !acceptable.empty()) return "acceptable";
  return "valid";
}

/// The acceptable conventions of one vector (none for the EXP-2 round trip, which compares
/// rotations sign-free already, or for the exact class, which admits no other output).
std::vector<std::string> acceptable_of(const VectorFile& f, const spec::ToleranceClass& tc, const engine::Case& c) {
  if (f.round_trip() || tc.kind == "exact") return {};
  return engine::acceptable_for_case(f.abi_op(), c, f.format);  // zero_sentinel also outside the domain
}

/// The reference of one vector: the op's, or for the round trip exp of log.
engine::ReferenceResult reference(const VectorFile& f, const engine::Case& c) {
  if (!f.round_trip()) return f.abi_op().reference(c.inputs, c.k);
  engine::ReferenceResult log = engine::find_abi_op("log")->reference(c.inputs, 0);
  if (log.status != ref::Status::ok) return {log.status, {std::vector<Real>(4, ref::ScalarTraits<Real>::nan())}};
  return engine::find_abi_op("exp")->reference(log.outputs, 0);
}

std::string id_of(const std::string& clause, const std::string& op, ref::Format f, int tc) {
  char num[16];
  std::snprintf(num, sizeof num, "%04d", tc);
  return clause + "/" + op + "/" + format_name(f) + "/" + num;
}

bool same_value(const Real& a, const Real& b) {
  if (mpfr::isnan(a) || mpfr::isnan(b)) return mpfr::isnan(a) && mpfr::isnan(b);
  return a == b && mpfr::signbit(a) == mpfr::signbit(b);
}

/// Reads JSON with the file and path of every value at hand, for messages.
struct Reader {
  const std::filesystem::path& file;
  [[noreturn]] void fail(const std::string& path, const std::string& message) const {
    throw VectorsError(file, path, message);
  }
  const json& at(const json& obj, const std::string& key, const std::string& path) const {
    if (!obj.is_object()) fail(path, "expected an object");
    const auto it = obj.find(key);
    if (it == obj.end()) fail(path, "missing field \"" + key + "\"");
    return *it;
  }
  std::string string(const json& obj, const std::string& key, const std::string& path) const {
    const json& v = at(obj, key, path);
    if (!v.is_string()) fail(path + "/" + key, "expected a string");
    return v.get<std::string>();
  }
  std::int64_t integer(const json& obj, const std::string& key, const std::string& path) const {
    const json& v = at(obj, key, path);
    if (!v.is_number_integer()) fail(path + "/" + key, "expected an integer");
    return v.get<std::int64_t>();
  }
  const json& array(const json& obj, const std::string& key, const std::string& path) const {
    const json& v = at(obj, key, path);
    if (!v.is_array()) fail(path + "/" + key, "expected an array");
    return v;
  }
};

}  // namespace

const char* format_name(ref::Format f) { return f == ref::Format::binary32 ? "binary32" : "binary64"; }
const char* scalar_name(ref::Format f) { return f == ref::Format::binary32 ? "float" : "double"; }

const engine::AbiOp& VectorFile::abi_op() const { return engine::judged_op(clause, round_trip() ? "log" : op); }

std::vector<engine::Array> file_outputs(const std::string& clause, const std::string& file_op) {
  if (file_op == kRoundTripOp) return {engine::Array{"out_q", 4, false, engine::Measure::rotation}};
  if (engine::find_abi_op(file_op) == nullptr) return {};
  return engine::judged_op(clause, file_op).outputs;
}

std::vector<VectorFile> build_vector_files(const spec::Spec& spec, const BuildOptions& options) {
  std::vector<VectorFile> files;
  const engine::CaseOptions case_options{options.seed, options.cases_per_family, true};
  for (const spec::Clause& cl : spec.clauses) {
    if (cl.level == "Meta") continue;
    if (!options.clauses.empty() &&
        std::find(options.clauses.begin(), options.clauses.end(), cl.id) == options.clauses.end())
      continue;
    for (ref::Format format : options.formats) {
      const auto checks = engine::checks_for_clause(spec, cl.id, format, case_options, [](const std::string&) { return true; });
      for (const engine::Check& check : checks) {
        VectorFile f;
        f.clause = cl.id;
        f.clause_title = cl.title;
        f.level = cl.level;
        f.op = check.log_exp_round_trip ? kRoundTripOp : check.op;
        f.format = format;
        f.tolerance = check.tolerance.empty() ? cl.tolerance : check.tolerance;
        f.seed = options.seed;
        f.cases_per_family = options.cases_per_family;
        f.spec_version = spec.version;
        f.rotorcert_version = ROTORCERT_VERSION;
        const spec::ToleranceClass& tc = spec.lookup(f.tolerance);
        for (const engine::Case& c : check.cases) {
          Vector v;
          v.tc_id = static_cast<int>(f.tests.size()) + 1;
          v.id = id_of(f.clause, f.op, format, v.tc_id);
          v.input = c;
          v.flags = sorted_flags(c.flags);
          if (f.round_trip()) v.flags.insert(v.flags.begin(), "RoundTrip");
          engine::ReferenceResult r = reference(f, c);
          v.status = r.status;
          v.expected = std::move(r.outputs);
          v.acceptable = acceptable_of(f, tc, c);
          v.result = result_of(tc, v.status, v.acceptable);
          f.tests.push_back(std::move(v));
        }
        files.push_back(std::move(f));
      }
    }
  }
  return files;
}

std::string file_name(const VectorFile& f) {
  return f.clause + "_" + f.op + "_" + format_name(f.format) + ".json";
}

std::string render(const spec::Spec& spec, const VectorFile& f) {
  const spec::ToleranceClass& tc = spec.lookup(f.tolerance);
  const engine::AbiOp& op = f.abi_op();
  const Real eps = ref::format_epsilon<Real>(f.format);

  ordered_json tolerance{{"class", f.tolerance}, {"kind", tc.kind}};
  auto bar = [&](const std::optional<std::string>& text, const std::optional<Real>& value) -> ordered_json {
    if (value) {
      const double d = value->toDouble();  // 16, not 16.0: bars are counts of eps
      if (d == std::floor(d) && std::fabs(d) < 9.0e15) return static_cast<std::int64_t>(d);
      return d;
    }
    if (text) return *text;
    return nullptr;
  };
  tolerance["strict"] = bar(tc.strict, tc.strict_value());
  tolerance["loose"] = bar(tc.loose, tc.loose_value());
  tolerance["unit"] = tc.kind == "absolute" ? "absolute" : "eps";
  if (!tc.doc.empty()) tolerance["doc"] = tc.doc;

  ordered_json inputs = ordered_json::array(), outputs = ordered_json::array(), measures = ordered_json::object();
  for (const engine::Array& a : op.inputs)
    inputs.push_back({{"name", a.name}, {"stride", a.stride}, {"per_influence", a.per_influence}, {"layout", layout(f.op, a)}});
  for (const engine::Array& a : file_outputs(f.clause, f.op)) {
    outputs.push_back({{"name", a.name}, {"stride", a.stride}, {"measure", measure_name(a.measure)}, {"layout", layout(f.op, a)}});
    measures[measure_name(a.measure)] = measure_doc(a.measure);
  }
  std::set<std::string> used;
  for (const Vector& v : f.tests) used.insert(v.flags.begin(), v.flags.end());
  ordered_json flags = ordered_json::object();
  for (const std::string& name : used) flags[name] = flag_docs().at(name);

  std::string notes =
      "Decode every \"hex\" value exactly (C strtod/strtof, Python float.fromhex); \"dec\" is for reading. "
      "Call the operation on each test's inputs (one call per test, or batches of tests with the same k) and write "
      "its status and every output to a results file (conformance/VECTORS.md), then grade it with "
      "`rotorcert vectors check RESULTS.json`, which recomputes the reference at 256 bits and judges with the same "
      "code as `rotorcert certify`. "
      "result \"valid\": the status must be OK and each output's error (its measure, in units of eps = " +
      engine::hexfloat(eps, ref::Format::binary64) +
      " of the format) at most tolerance.strict for PASS, at most tolerance.loose for QUALITY_WARNING, else FAIL "
      "(TOL-1; a NaN where a number is expected is FAIL). expected.out holds the reference rounded to the format "
      "(hex) and to 20 significant digits (dec). "
      "result \"invalid\": the input is outside the operation's domain; the status must be DOMAIN_ERROR and every "
      "output component NaN (RESULT-2). "
      "result \"acceptable\": an informative clause (the error is reported, only a wrong status fails), or an input "
      "where a convention a correct library may choose gives another correct output (ACC-1: the test's \"acceptable\" "
      "lists them; the grader accepts such an output as ACCEPTABLE and names the convention). "
      "The worst test of a clause decides its result.";
  if (tc.kind == "exact") notes += " Class exact: the output must equal the expected value (the bars are 0).";
  if (tc.kind == "formula")
    notes += " Class " + f.tolerance + ": the bars depend on each test's input; they are given per test as bars_eps.";
  if (f.round_trip())
    notes += " Round trip (EXP-2): call log on q, then exp on log's output; out_q is exp's output, the status is OK "
             "only if both calls returned OK. out_q is compared with q itself (METRIC-1); expected.out is exp(log q) "
             "of the reference, for reading.";

  ordered_json header;
  header["format"] = "rotorcert-vectors";
  header["format_version"] = kFormatVersion;
  header["schema"] = "vectors.schema.json";
  header["rotorcert_version"] = f.rotorcert_version;
  header["spec_version"] = f.spec_version;
  header["seed"] = f.seed;
  header["cases_per_family"] = f.cases_per_family;
  header["clause"] = f.clause;
  header["clause_title"] = f.clause_title;
  header["level"] = f.level;
  header["op"] = f.op;
  header["abi_ops"] = f.round_trip() ? ordered_json{"log", "exp"} : ordered_json{f.op};
  header["nway"] = op.nway;
  header["scalar"] = scalar_name(f.format);
  header["number_format"] = format_name(f.format);
  header["eps"] = engine::hexfloat(eps, ref::Format::binary64);
  header["tolerance"] = tolerance;
  header["inputs"] = inputs;
  header["outputs"] = outputs;
  header["measures"] = measures;
  header["flags"] = flags;
  header["notes"] = notes;
  header["numberOfTests"] = f.tests.size();
  header["tests"] = nullptr;

  std::string tests = "[";
  for (std::size_t i = 0; i < f.tests.size(); ++i) {
    const Vector& v = f.tests[i];
    ordered_json t;
    t["tcId"] = v.tc_id;
    t["id"] = v.id;
    t["comment"] = v.input.label;
    t["flags"] = v.flags;
    t["k"] = v.input.k;
    ordered_json in = ordered_json::object();
    for (std::size_t a = 0; a < op.inputs.size(); ++a)
      in[op.inputs[a].name] = hex_dec(v.input.inputs[a], f.format, roundtrip_digits(f.format));
    t["in"] = in;
    ordered_json out = ordered_json::object();
    const auto outs = file_outputs(f.clause, f.op);
    for (std::size_t a = 0; a < outs.size(); ++a) out[outs[a].name] = hex_dec(v.expected[a], f.format, kExpectedDigits);
    t["expected"] = {{"status", ref::to_string(v.status)}, {"out", out}};
    if (tc.kind == "formula") {
      const ref::Bars b = engine::bars_for(tc, op, v.input, eps);
      if (std::isfinite(b.strict) && std::isfinite(b.loose)) t["bars_eps"] = {b.strict, b.loose};
    }
    t["result"] = v.result;
    if (!v.acceptable.empty()) t["acceptable"] = v.acceptable;
    tests += (i ? ",\n    " : "\n    ") + t.dump();
  }
  tests += f.tests.empty() ? "]" : "\n  ]";
  std::string text = header.dump(2);
  const std::string placeholder = "\"tests\": null";
  text.replace(text.rfind(placeholder), placeholder.size(), "\"tests\": " + tests);
  return text + "\n";
}

bool parse_value(const json& v, ref::Format f, Real& out, std::string& why) {
  if (v.is_number()) {
    // Read as binary64 (that is what a JSON number is to most parsers), then rounded to the format.
    out = engine::round_to(f, Real(v.get<double>()));
    return true;
  }
  if (!v.is_string()) {
    why = "expected a hexfloat string, a decimal string, \"nan\", \"inf\", \"-inf\" or a number";
    return false;
  }
  std::string s = v.get<std::string>();
  std::string lower = s;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (lower == "nan" || lower == "-nan" || lower == "+nan") {
    out = ref::ScalarTraits<Real>::nan();
    return true;
  }
  if (lower == "inf" || lower == "+inf" || lower == "infinity" || lower == "+infinity") {
    out = Real("inf");
    return true;
  }
  if (lower == "-inf" || lower == "-infinity") {
    out = -Real("inf");
    return true;
  }
  Real x;
  char* end = nullptr;
  if (s.empty() || std::isspace(static_cast<unsigned char>(s[0])) ||
      (mpfr_strtofr(x.mpfr_ptr(), s.c_str(), &end, 0, MPFR_RNDN), end == nullptr || *end != '\0' || end == s.c_str())) {
    why = "\"" + s + "\" is not a number (hexfloat such as \"0x1.8p+0\", decimal, \"nan\", \"inf\" or \"-inf\")";
    return false;
  }
  const Real r = engine::round_to(f, x);
  if (lower.find("0x") != std::string::npos && !same_value(r, x)) {
    why = "hexfloat \"" + s + "\" is not a " + format_name(f) + " value";
    return false;
  }
  out = r;
  return true;
}

VectorFile parse_vector_file(const spec::Spec& spec, const json& j, const std::filesystem::path& file) {
  const Reader r{file};
  if (!j.is_object()) r.fail("", "expected a JSON object");
  if (r.string(j, "format", "") != "rotorcert-vectors") r.fail("/format", "not a rotorcert-vectors file");
  if (r.integer(j, "format_version", "") != kFormatVersion)
    r.fail("/format_version", "format version " + std::to_string(kFormatVersion) + " expected");
  VectorFile f;
  f.path = file;
  f.spec_version = r.string(j, "spec_version", "");
  if (f.spec_version != spec.version)
    r.fail("/spec_version", "vectors of spec version " + f.spec_version + ", but this rotorcert checks spec version " +
                                spec.version + ": export them again with this version");
  f.rotorcert_version = r.string(j, "rotorcert_version", "");
  const std::int64_t seed = r.integer(j, "seed", "");
  if (seed < 0) r.fail("/seed", "expected a non-negative integer");
  f.seed = static_cast<std::uint64_t>(seed);
  f.cases_per_family = static_cast<int>(r.integer(j, "cases_per_family", ""));
  f.clause = r.string(j, "clause", "");
  const spec::Clause* cl = spec.find_clause(f.clause);
  if (cl == nullptr || cl->level == "Meta") r.fail("/clause", "\"" + f.clause + "\" is not a clause with test vectors in spec " + spec.version);
  f.clause_title = cl->title;
  f.level = cl->level;
  f.op = r.string(j, "op", "");
  const auto ops = engine::ops_for_clause(f.clause);
  const bool known = f.clause == "EXP-2" ? f.op == kRoundTripOp : std::find(ops.begin(), ops.end(), f.op) != ops.end();
  if (!known) r.fail("/op", "\"" + f.op + "\" is not an operation of clause " + f.clause);
  const std::string number_format = r.string(j, "number_format", "");
  if (number_format != "binary32" && number_format != "binary64") r.fail("/number_format", "expected \"binary32\" or \"binary64\"");
  f.format = number_format == "binary32" ? ref::Format::binary32 : ref::Format::binary64;
  if (r.string(j, "scalar", "") != scalar_name(f.format)) r.fail("/scalar", std::string("expected \"") + scalar_name(f.format) + "\"");
  const engine::AbiOp& op = f.abi_op();
  f.tolerance = r.string(r.at(j, "tolerance", ""), "class", "/tolerance");
  const std::string want_class = engine::tolerance_for(spec, f.clause, op.name);
  if (f.tolerance != want_class)
    r.fail("/tolerance/class", "spec " + spec.version + " judges " + f.clause + " / " + f.op + " with class " + want_class +
                                   ", not " + f.tolerance);
  const spec::ToleranceClass& tc = spec.lookup(f.tolerance);
  const auto outs = file_outputs(f.clause, f.op);

  const json& tests = r.array(j, "tests", "");
  if (r.integer(j, "numberOfTests", "") != static_cast<std::int64_t>(tests.size()))
    r.fail("/numberOfTests", "does not match the number of tests (" + std::to_string(tests.size()) + ")");
  for (std::size_t i = 0; i < tests.size(); ++i) {
    const std::string p = "/tests/" + std::to_string(i);
    const json& t = tests[i];
    Vector v;
    v.tc_id = static_cast<int>(r.integer(t, "tcId", p));
    v.id = r.string(t, "id", p);
    if (v.id != id_of(f.clause, f.op, f.format, v.tc_id))
      r.fail(p + "/id", "expected \"" + id_of(f.clause, f.op, f.format, v.tc_id) + "\" (clause/op/format/tcId)");
    v.input.label = r.string(t, "comment", p);
    for (const json& flag : r.array(t, "flags", p)) {
      if (!flag.is_string() || !flag_docs().count(flag.get<std::string>())) r.fail(p + "/flags", "unknown flag " + flag.dump());
      v.flags.push_back(flag.get<std::string>());
    }
    const std::int64_t k = r.integer(t, "k", p);
    if (k < 0 || (!op.nway && k != 0) || k > 1024) r.fail(p + "/k", op.nway ? "expected 0..1024" : "expected 0 (not an n-way operation)");
    v.input.k = static_cast<std::size_t>(k);
    // Inputs: exact values of the format, as many as the layout says.
    const json& in = r.at(t, "in", p);
    for (const engine::Array& a : op.inputs) {
      const std::string pa = p + "/in/" + a.name;
      const json& hex = r.array(r.at(in, a.name, p + "/in"), "hex", pa);
      const std::size_t n = static_cast<std::size_t>(a.stride) * (a.per_influence ? v.input.k : 1);
      if (hex.size() != n) r.fail(pa + "/hex", "expected " + std::to_string(n) + " values");
      std::vector<Real> values;
      for (std::size_t e = 0; e < n; ++e) {
        Real x;
        std::string why;
        if (!hex[e].is_string() || !parse_value(hex[e], f.format, x, why))
          r.fail(pa + "/hex/" + std::to_string(e), why.empty() ? "expected a hexfloat string" : why);
        values.push_back(x);
      }
      v.input.inputs.push_back(std::move(values));
    }
    // Expected status and outputs, checked against the reference.
    const json& expected = r.at(t, "expected", p);
    const std::string status = r.string(expected, "status", p + "/expected");
    if (status != "OK" && status != "DOMAIN_ERROR") r.fail(p + "/expected/status", "expected \"OK\" or \"DOMAIN_ERROR\"");
    v.status = status == "OK" ? ref::Status::ok : ref::Status::domain_error;
    const json& out = r.at(expected, "out", p + "/expected");
    for (const engine::Array& a : outs) {
      const std::string pa = p + "/expected/out/" + a.name;
      const json& hex = r.array(r.at(out, a.name, p + "/expected/out"), "hex", pa);
      if (hex.size() != static_cast<std::size_t>(a.stride)) r.fail(pa + "/hex", "expected " + std::to_string(a.stride) + " values");
      std::vector<Real> values;
      for (std::size_t e = 0; e < hex.size(); ++e) {
        Real x;
        std::string why;
        if (!hex[e].is_string() || !parse_value(hex[e], f.format, x, why))
          r.fail(pa + "/hex/" + std::to_string(e), why.empty() ? "expected a hexfloat string" : why);
        values.push_back(x);
      }
      v.expected.push_back(std::move(values));
    }
    v.result = r.string(t, "result", p);
    const engine::ReferenceResult want = reference(f, v.input);
    const std::string altered = ": the file was altered or comes from another version of rotorcert";
    if (want.status != v.status)
      r.fail(p + "/expected/status", std::string("the reference of spec ") + spec.version + " gives " + ref::to_string(want.status) + altered);
    for (std::size_t a = 0; a < outs.size(); ++a)
      for (std::size_t e = 0; e < v.expected[a].size(); ++e)
        if (!same_value(engine::round_to(f.format, want.outputs[a][e]), v.expected[a][e]))
          r.fail(p + "/expected/out/" + outs[a].name + "/hex/" + std::to_string(e),
                 "the reference of spec " + spec.version + " gives " + engine::hexfloat(want.outputs[a][e], f.format) +
                     ", the file says " + engine::hexfloat(v.expected[a][e], f.format) + altered);
    v.acceptable = acceptable_of(f, tc, v.input);
    if (v.result != result_of(tc, v.status, v.acceptable))
      r.fail(p + "/result", "expected \"" + result_of(tc, v.status, v.acceptable) + "\" for status " + status +
                                " under class " + f.tolerance + altered);
    f.tests.push_back(std::move(v));
  }
  return f;
}

}  // namespace rotorcert::vectors
