#include "oracle.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <mutex>
#include <optional>
#include <set>
#include <unordered_map>
#include <unordered_set>

#include <nlohmann/json.hpp>

#include <rotorcert/engine/abi_op.hpp>
#include <rotorcert/engine/cases.hpp>
#include <rotorcert/engine/declarations.hpp>
#include <rotorcert/engine/fast_oracle.hpp>
#include <rotorcert/reference/scalar.hpp>
#include <rotorcert/registry.hpp>

#include "embedded.hpp"

namespace rotorcert::fuzz {
namespace {

using engine::AbiOp;
using engine::Case;
using engine::Observed;
using ref::Real;

struct State {
  spec::Spec spec;
  std::set<std::string> expected;  // "table/scalar/clause"
};

State& state() {
  static State* s = [] {
    ref::use_reference_precision();
    auto* st = new State;
    const std::filesystem::path dir = "<embedded spec>";
    spec::parse_clauses(nlohmann::json::parse(embedded::clauses_json()), dir / "clauses.json", st->spec);
    st->spec.examples = spec::parse_examples(nlohmann::json::parse(embedded::examples_json()), dir / "examples.json",
                                             &st->spec.examples_version);
    for (const auto& [path, text] : embedded::expected_failures_json()) {
      const nlohmann::json j = nlohmann::json::parse(text);  // kept alive for the loop below
      for (const auto& f : j.at("failures"))
        st->expected.insert(f.at("table").get<std::string>() + "/" + f.at("scalar").get<std::string>() + "/" +
                            f.at("clause").get<std::string>());
    }
    return st;
  }();
  return *s;
}

const char* scalar_of(const rc_impl& t) { return t.scalar == RC_SCALAR_FLOAT32 ? "float" : "double"; }

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ",") + x;
  return s;
}

/// The raw words of element e of every input array, in hex (NaN payloads included).
std::string raw_words(const Decoded& d, std::size_t e) {
  std::string s;
  const std::size_t word = d.f64 ? 8 : 4;
  for (std::size_t a = 0; a < d.op->inputs.size(); ++a) {
    const std::size_t count = element_count(*d.op, a, d.k);
    s += (a ? " " : "") + d.op->inputs[a].name + "=[";
    for (std::size_t j = 0; j < count; ++j) {
      const unsigned char* p = d.raw[a].data() + (e * count + j) * word;
      char buf[24];
      if (d.f64) {
        std::uint64_t u;
        std::memcpy(&u, p, 8);
        std::snprintf(buf, sizeof buf, "%s0x%016llx", j ? " " : "", static_cast<unsigned long long>(u));
      } else {
        std::uint32_t u;
        std::memcpy(&u, p, 4);
        std::snprintf(buf, sizeof buf, "%s0x%08x", j ? " " : "", static_cast<unsigned>(u));
      }
      s += buf;
    }
    s += "]";
  }
  return s;
}

[[noreturn]] void print_and_abort(const Decoded& d, const Finding& f) {
  const rc_impl& t = *f.table;
  const std::size_t e = f.element;
  const engine::CaseVerdict& v = f.verdict;
  std::fprintf(stderr,
               "\n==== rotorcert fuzz finding ====\n"
               "implementation: %s (%s)\n"
               "op:             %s (element %zu of n = %zu, k = %zu)\n"
               "clauses:        %s, judged with class %s\n"
               "what:           %s\n"
               "error:          %g eps\n"
               "inputs:         %s\n"
               "raw bits:       %s\n"
               "detail:         %s\n"
               "================================\n",
               t.name, scalar_of(t), d.op->name.c_str(), e, d.n, d.k, join(clauses_judging(d.op->name)).c_str(),
               f.tolerance.c_str(), f.what.c_str(), v.error, engine::describe_inputs(*d.op, d.exact_case(e), d.format()).c_str(),
               raw_words(d, e).c_str(), v.detail.c_str());
  std::abort();
}

/// A table's results of one batch call, as the table wrote them: the judge reads them as exact
/// values only for the elements it has to judge (TableResults::observed), and the memo keys an
/// element's results by their bits (TableResults::key).
struct TableResults {
  int rc = 0;
  std::size_t word = 4;                          // bytes per scalar: 4 (binary32) or 8 (binary64)
  std::vector<std::vector<unsigned char>> out;   // per output array of the op: n x stride words
  std::vector<int> stride;                       // per output array: words per element
  std::vector<std::uint8_t> status;              // per element

  /// Word j of element e in output array a, as a double (every float is one exactly).
  double value(std::size_t a, std::size_t e, std::size_t j) const {
    const unsigned char* p = out[a].data() + (e * static_cast<std::size_t>(stride[a]) + j) * word;
    if (word == 8) {
      double x;
      std::memcpy(&x, p, 8);
      return x;
    }
    float x;
    std::memcpy(&x, p, 4);
    return x;
  }
  Observed observed(std::size_t e) const {
    Observed o;
    o.call_rc = rc;
    o.status = status[e];
    for (std::size_t a = 0; a < out.size(); ++a) {
      std::vector<Real> v;
      for (std::size_t j = 0; j < static_cast<std::size_t>(stride[a]); ++j) v.push_back(Real(value(a, e, j)));
      o.outputs.push_back(std::move(v));
    }
    return o;
  }
  /// Element e's outputs as exact Bounded values (every float and double is a long double), for
  /// the fast level without MPFR numbers; false where a word is not finite.
  bool bounded(std::size_t e, engine::BoundedValues& values) const {
    values.assign(out.size(), {});
    for (std::size_t a = 0; a < out.size(); ++a)
      for (std::size_t j = 0; j < static_cast<std::size_t>(stride[a]); ++j) {
        const double x = value(a, e, j);
        if (!std::isfinite(x)) return false;
        values[a].push_back(ref::Bounded(static_cast<long double>(x), 0));
      }
    return true;
  }
  /// Element e's results as bytes: the call's return value, the status byte and every output
  /// word. Equal keys are equal results, so a verdict on one holds for the other, whichever
  /// table returned them (the judge does not ask which).
  std::string key(std::size_t e) const {
    std::string k(reinterpret_cast<const char*>(&rc), sizeof rc);
    k.push_back(static_cast<char>(status[e]));
    for (std::size_t a = 0; a < out.size(); ++a) {
      const std::size_t bytes = static_cast<std::size_t>(stride[a]) * word;
      k.append(reinterpret_cast<const char*>(out[a].data() + e * bytes), bytes);
    }
    return k;
  }
};

/// Calls `op` on the batch with the decoded bits; exact-size buffers, so ASan sees any overrun.
template <class S>
TableResults call_raw(const rc_impl& t, const AbiOp& op, std::size_t n, std::size_t k,
                      const std::vector<std::vector<unsigned char>>& raw) {
  std::vector<std::vector<S>> in(raw.size()), out(op.outputs.size());
  std::vector<const void*> in_ptrs;
  std::vector<void*> out_ptrs;
  for (std::size_t a = 0; a < raw.size(); ++a) {
    in[a].resize(raw[a].size() / sizeof(S));
    if (!raw[a].empty()) std::memcpy(in[a].data(), raw[a].data(), raw[a].size());
    in_ptrs.push_back(in[a].empty() ? nullptr : in[a].data());
  }
  for (std::size_t a = 0; a < op.outputs.size(); ++a) {
    out[a].assign(n * static_cast<std::size_t>(op.outputs[a].stride), S(0));
    out_ptrs.push_back(out[a].data());
  }
  TableResults r;
  r.word = sizeof(S);
  r.status.assign(n, 0xEE);  // a value no implementation writes
  r.rc = engine::call(t, op.name, n, k, in_ptrs, out_ptrs, r.status.data());
  for (std::size_t a = 0; a < op.outputs.size(); ++a) {
    const auto* p = reinterpret_cast<const unsigned char*>(out[a].data());
    r.out.emplace_back(p, p + out[a].size() * sizeof(S));
    r.stride.push_back(op.outputs[a].stride);
  }
  return r;
}

TableResults call_raw(const rc_impl& t, const AbiOp& op, std::size_t n, std::size_t k,
                      const std::vector<std::vector<unsigned char>>& raw) {
  return t.scalar == RC_SCALAR_FLOAT32 ? call_raw<float>(t, op, n, k, raw) : call_raw<double>(t, op, n, k, raw);
}

/// How much of an element is judged (see oracle.hpp).
enum class Judge { everything, status_only, nothing };

/// Whether values stay clear of the format's overflow and underflow: inputs other than
/// quaternions and dual quaternions (EDGE-5 asks those to work at every scale), the translation
/// a dual quaternion stands for, and the exact outputs, at most 2^(emax - 8) in magnitude;
/// matrix entries (their determinant is a cube) within 2^(+-(emax / 3 - 4)) unless zero.
/// ROTORCERT_FUZZ_DEBUG: why each decision was taken, on stderr. Read once, not per perturbation.
bool fuzz_debug() {
  static const bool on = std::getenv("ROTORCERT_FUZZ_DEBUG") != nullptr;
  return on;
}

/// The largest emax of the format's values: 127 (binary32) or 1023 (binary64).
int emax_of(ref::Format f) { return f == ref::Format::binary32 ? 127 : 1023; }

/// The magnitude beyond which an input or output has no headroom: 2^(emax - 8).
int headroom_exponent(ref::Format f) { return emax_of(f) - 8; }

/// Whether output array `a` of `op` is measured relative to its own size (componentwise relative
/// error: compose's and inverse's products, a scalar): below the normal range the format holds
/// it only to absolute precision (gradual underflow), so its size needs headroom from below too.
bool relative_to_its_size(const AbiOp& op, std::size_t a) {
  const engine::Measure m = op.outputs.at(a).measure;
  return m == engine::Measure::quaternion || m == engine::Measure::scalar;
}

/// The norm below which such an output has no headroom: 2^(emin + 8), emin = 1 - emax.
int underflow_exponent(ref::Format f) { return 1 - emax_of(f) + 8; }

bool within_headroom(const AbiOp& op, const engine::Values& inputs, const engine::Values& outputs, ref::Format f) {
  const int emax = emax_of(f);
  const Real big = ldexp(Real(1), headroom_exponent(f));
  const Real mat_big = ldexp(Real(1), emax / 3 - 4), mat_small = ldexp(Real(1), -(emax / 3 - 4));
  for (std::size_t a = 0; a < op.inputs.size(); ++a) {
    const int stride = op.inputs[a].stride;
    if (stride == 8) {
      // Any scale, but the translation it stands for (2 |d| / |r|) must fit the format.
      for (std::size_t e = 0; e + 8 <= inputs[a].size(); e += 8) {
        Real r(0), d(0);
        for (std::size_t m = 0; m < 4; ++m) {
          r += inputs[a][e + m] * inputs[a][e + m];
          d += inputs[a][e + 4 + m] * inputs[a][e + 4 + m];
        }
        if (mpfr::isfinite(r) && mpfr::isfinite(d) && r > 0 && Real(2) * sqrt(d / r) > big) return false;
      }
      continue;
    }
    if (stride == 4) continue;
    for (const Real& x : inputs[a]) {
      if (!mpfr::isfinite(x)) continue;  // a DOMAIN_ERROR, judged as such
      if (abs(x) > (stride == 9 ? mat_big : big)) return false;
      if (stride == 9 && x != 0 && abs(x) < mat_small) return false;
    }
  }
  for (const auto& arr : outputs)
    for (const Real& y : arr)
      if (mpfr::isfinite(y) && abs(y) > big) return false;
  const Real small = ldexp(Real(1), underflow_exponent(f));
  for (std::size_t a = 0; a < outputs.size(); ++a) {
    if (!relative_to_its_size(op, a)) continue;
    const Real n = engine::block_norm(outputs[a], 0, outputs[a].size());
    if (mpfr::isfinite(n) && n != 0 && n < small) return false;
  }
  return true;
}

/// MPFR forms the normwise step and the perturbed component at 256 bits, each rounded: a Bounded
/// perturbation holds the exact real one, and widened by 2^-240 of the magnitudes involved it
/// holds MPFR's too, so both levels judge the same perturbed input.
void cover_mpfr_rounding(Real&, const Real&) {}
void cover_mpfr_rounding(ref::Bounded& x, const ref::Bounded& step) {
  if (!std::isfinite(x.value()) || !std::isfinite(step.value())) return;  // exact specials
  // A step of exactly 0 (an element of zeros, whose norm is 0 in both levels) leaves x as it is in
  // MPFR too; widening an exact 0 by kTiny would make it "maybe 0" and every test of it undecided.
  if (step.exact() && step.value() == 0) return;
  const long double slack = std::ldexp(std::fabs(x.value()) + x.bound() + std::fabs(step.value()) + step.bound(), -240);
  x = ref::Bounded(x.value(), x.bound() + slack + ref::Bounded::kTiny);
}

/// One perturbation of the inputs, as a backward-stable implementation in the format may
/// perturb them. pattern < 3: componentwise, every component times 1 +- u (u the unit roundoff;
/// all +, alternating, hashed signs). pattern >= 3: normwise, one element only (element
/// (pattern - 3) / 2 in input order: one quaternion, vector, dual quaternion or matrix, each
/// influence on its own), each of its components plus +- u |element| (hashed signs, then the
/// opposite ones): the error of a product or normalisation of that element. One element at a time, so that errors of two
/// inputs cannot cancel where the result depends on their difference (nlerp or slerp of nearby
/// rotations far outside [0, 1]); it also decides the hemisphere rule where a normalised dot
/// product is below u (a tie within the format). Returns false when there is no such element.
template <class T>
bool perturbed_values(const std::vector<std::vector<T>>& in, const AbiOp& op, int pattern, const T& u,
                      std::vector<std::vector<T>>& out) {
  out = in;
  const std::uint64_t bits = 0x9E3779B97F4A7C15ull;
  if (pattern < 3) {
    std::size_t j = 0;
    for (auto& arr : out)
      for (T& x : arr) {
        const bool minus = pattern == 0 ? false : pattern == 1 ? (j % 2 == 1) : ((bits >> (j % 64)) & 1) != 0;
        x *= minus ? T(1) - u : T(1) + u;
        ++j;
      }
    return true;
  }
  // Two patterns per element, with opposite signs: whichever way a near-tie leans, one of them
  // pushes it across.
  int unit = (pattern - 3) / 2;
  const bool negate = (pattern - 3) % 2 == 1;
  for (std::size_t a = 0; a < out.size(); ++a) {
    const std::size_t stride = static_cast<std::size_t>(op.inputs[a].stride);
    if (stride == 1) continue;  // scalars: the componentwise patterns cover them
    for (std::size_t first = 0; first + stride <= out[a].size(); first += stride) {
      if (unit-- > 0) continue;
      T norm(0);
      for (std::size_t m = first; m < first + stride; ++m) norm += in[a][m] * in[a][m];
      const T step = u * sqrt(norm);
      const std::uint64_t h = bits * (static_cast<std::uint64_t>((pattern - 3) / 2) * 2654435761ull + 1);
      for (std::size_t m = first; m < first + stride; ++m) {
        out[a][m] += (((h >> ((m - first + 7 * a) % 61)) & 1) != 0) != negate ? -step : step;
        cover_mpfr_rounding(out[a][m], step);
      }
      return true;
    }
  }
  return false;
}

bool perturbed(const Case& c, const AbiOp& op, int pattern, const Real& u, Case& p) {
  p.k = c.k;
  p.label = c.label;
  p.flags = c.flags;
  return perturbed_values(c.inputs, op, pattern, u, p.inputs);
}


/// Decides how much of an element is judged: the reference is evaluated on the inputs perturbed
/// (perturbed() above), its outputs rounded to the format
/// and judged by the same judge_case. A status that changes under perturbation: nothing is
/// judged (the input sits on the domain boundary, e.g. det M = 0 within rounding). Outputs that
/// move beyond the strict bar, or values without headroom: only the status.
/// Inputs that multiply the implementation's own rounding of an angle, so that one unit roundoff u
/// moves the result beyond the strict bar; then only the status is judged, decided before the
/// perturbations (which then compare statuses only), at both levels alike:
/// - an interpolation parameter multiplies the rounding of the angle between the endpoints, which
///   no perturbation of the inputs shows when the angle is a multiple of pi / 2 and t an even
///   integer (every binary64 beyond 2^54): one unit roundoff of that angle moves the result by
///   |t| u (SLERP-4);
/// - exp's rotation angle is 2|v| (EXP-1): the rounding of |v| turns it by 2|v| u, which is what
///   the first perturbation (every component times 1 + u) shows too. Said first, it spares the fast
///   level the sine of an argument whose bound spans a turn (|v| beyond 2^64), which it cannot
///   bound and sent to MPFR.
bool multiplied_rounding_beyond_strict_bar(const AbiOp& op, const spec::ToleranceClass& tc, const Case& c,
                                           ref::Format f) {
  const auto strict = tc.strict_value();
  if (tc.kind != "eps" || !strict) return false;
  const Real u = ref::format_epsilon<Real>(f) / Real(2);
  const Real bar = *strict * ref::format_epsilon<Real>(f);
  for (std::size_t a = 0; a < op.inputs.size(); ++a)
    if (op.inputs[a].name == "t")
      for (const Real& t : c.inputs[a])
        if (mpfr::isfinite(t) && abs(t) * u > bar) return true;
  if (op.name == "exp") {
    Real length2(0);
    for (const Real& x : c.inputs.at(0)) length2 += x * x;
    if (mpfr::isfinite(length2) && Real(2) * sqrt(length2) * u > bar) return true;
  }
  return false;
}

/// What one perturbed input p does to the judgement at the MPFR level: its reference status differs
/// (nothing is judged), or its result rounded to the format is not within the strict bar (the
/// numbers are not judged), or neither. `numbers`: whether the numbers are still to be judged.
enum class Perturbation { agrees, beyond_strict_bar, status_differs };
Perturbation mpfr_perturbation(const AbiOp& op, const spec::ToleranceClass& tc, const Case& c, ref::Format f,
                               const Case& p, int pattern, bool numbers, const engine::ReferenceResult& want) {
  const engine::ReferenceResult r = op.reference(p.inputs, c.k);
  if (r.status != want.status) return Perturbation::status_differs;
  if (!numbers) return Perturbation::agrees;
  Observed o;
  o.status = RC_OK;
  o.outputs = r.outputs;
  for (auto& arr : o.outputs)
    for (Real& x : arr) x = engine::round_to(f, x);
  const bool debug = fuzz_debug();
  const engine::CaseVerdict v = engine::judge_case_against(op, tc, c, o, f, want, debug);
  if (debug) std::fprintf(stderr, "perturbation %d: %g eps (%s)\n", pattern, v.error, v.detail.c_str());
  return v.verdict == ref::Verdict::pass ? Perturbation::agrees : Perturbation::beyond_strict_bar;
}

Judge how_to_judge(const AbiOp& op, const spec::ToleranceClass& tc, const Case& c, ref::Format f,
                   const std::function<const engine::ReferenceResult&()>& mpfr_want) {
  const Real u = ref::format_epsilon<Real>(f) / Real(2);
  if (op.name == "from_matrix" && engine::numerically_singular(c.inputs.at(0), f)) return Judge::nothing;
  const engine::ReferenceResult& want = mpfr_want();  // (a singular matrix above needs none)
  const bool headroom = within_headroom(op, c.inputs, want.outputs, f);
  // t or exp's angle beyond the strict bar settles the numbers before any perturbation is judged
  // (the perturbations then only compare statuses).
  bool numbers = want.status == ref::Status::ok && headroom && !multiplied_rounding_beyond_strict_bar(op, tc, c, f);
  Case p;
  for (int pattern = 0; perturbed(c, op, pattern, u, p); ++pattern) {
    const Perturbation step = mpfr_perturbation(op, tc, c, f, p, pattern, numbers, want);
    if (step == Perturbation::status_differs) return Judge::nothing;
    if (step == Perturbation::beyond_strict_bar) numbers = false;
  }
  if (want.status == ref::Status::domain_error || numbers) return Judge::everything;
  // MAT-3's domain is the sign of a cubic in the entries: without headroom the format cannot
  // decide it, so the status is not judged either.
  if (op.name == "from_matrix" && !headroom) return Judge::nothing;
  return Judge::status_only;
}

/// The TOL-1 verdicts of a perturbed result `r` rounded to the format, over every way it may round.
/// First the error bounded over all of them at once (one evaluation): where that settles the
/// caller's question (every rounding PASSes, or none does) it is the answer, since each rounding's
/// error lies inside that bound. Otherwise the candidates are enumerated where there are few (each
/// must give the verdict: the best of the bests, the worst of the worsts). nullopt where an error
/// is not bounded.
std::optional<engine::FastVerdicts> rounded_verdicts(const AbiOp& op, const engine::FastCase& fc,
                                                     const engine::FastReference& r, ref::Format f,
                                                     const engine::FastReference& want) {
  const auto at_once = engine::fast_verdicts_of_rounding(op, fc, r, f, want);
  if (at_once && (at_once->worst == ref::Verdict::pass || at_once->best != ref::Verdict::pass)) return at_once;
  const auto roundings = engine::fast_roundings(r, f);
  if (!roundings) return at_once;
  engine::FastVerdicts all{ref::Verdict::fail, ref::Verdict::pass};
  for (const engine::Values& outputs : *roundings) {
    Observed o;
    o.status = RC_OK;
    o.outputs = outputs;
    const auto v = engine::fast_verdicts(op, fc, o, want);
    if (!v) return std::nullopt;
    all.best = std::min(all.best, v->best);
    all.worst = std::max(all.worst, v->worst);
  }
  return all;
}

/// Element e's inputs as exact Bounded values, from its words (engine::bounded_values of its
/// exact case, without the MPFR numbers): every float and double is a long double.
engine::BoundedValues bounded_inputs(const Decoded& d, std::size_t e) {
  engine::BoundedValues in(d.op->inputs.size());
  for (std::size_t a = 0; a < in.size(); ++a)
    for (const double x : d.words(e, a)) in[a].push_back(ref::Bounded(static_cast<long double>(x), 0));
  return in;
}

/// how_to_judge from the fast level (engine/fast_oracle.hpp): the same decisions, each taken only
/// where the bounds settle it. A perturbation the bounds do not settle is taken at the MPFR level
/// alone (mpfr_perturbation against `mpfr_want()`, the element's exact reference, computed on first
/// use), so the answer is how_to_judge's and the other perturbations stay cheap. A perturbed
/// result's verdict is taken at the fast level only where every way its exact value may round to
/// the format gives it. The caller has taken how_to_judge's first test (a numerically singular
/// matrix: nothing judged), which needs no reference.
Judge how_to_judge_fast(const AbiOp& op, const spec::ToleranceClass& tc, const Case& c, ref::Format f,
                        const engine::BoundedValues& in, const engine::FastReference& want,
                        const std::optional<engine::FastCase>& fc,
                        const std::function<const engine::ReferenceResult&()>& mpfr_want) {
  const Real u = ref::format_epsilon<Real>(f) / Real(2);
  const bool ok = want.status == ref::Status::ok;
  // within_headroom compares each exact output's magnitude with 2^(emax - 8): an output whose
  // interval lies above it settles "no headroom" whatever the rest; one whose interval holds it is
  // read from the element's MPFR reference (one evaluation: the perturbations stay at the fast
  // level). The inputs are exact: within_headroom reads them as they are.
  bool outputs_beyond = false, outputs_unread = false;
  if (ok) {
    const long double big = std::ldexp(1.0L, headroom_exponent(f));
    for (const auto& arr : want.outputs)
      for (const ref::Bounded& y : arr) {
        if (!std::isfinite(y.value())) continue;
        constexpr long double lu = ref::Bounded::kU;
        const long double spread = y.bound() * (1 + 4 * lu);
        if ((std::fabs(y.value()) - spread) * (1 - 4 * lu) > big) outputs_beyond = true;
        else if ((std::fabs(y.value()) + spread) * (1 + 4 * lu) > big) outputs_unread = true;
      }
    // An output measured relative to its size: its norm's interval [lo, hi] (from its components'
    // intervals) against 2^(emin + 8) and 0, as within_headroom compares the exact norm.
    const long double small = std::ldexp(1.0L, underflow_exponent(f));
    for (std::size_t a = 0; a < want.outputs.size(); ++a) {
      if (!relative_to_its_size(op, a)) continue;
      constexpr long double lu = ref::Bounded::kU;
      long double lo2 = 0, hi2 = 0;
      bool exact_zero = true, finite = true;
      for (const ref::Bounded& y : want.outputs[a]) {
        if (!std::isfinite(y.value())) finite = false;
        const long double spread = y.bound() * (1 + 4 * lu);
        const long double lo = std::max(0.0L, (std::fabs(y.value()) - spread) * (1 - 4 * lu));
        const long double hi = (std::fabs(y.value()) + spread) * (1 + 4 * lu);
        lo2 += lo * lo, hi2 += hi * hi;
        exact_zero = exact_zero && y.exact() && y.value() == 0;
      }
      if (!finite || exact_zero) continue;
      const long double lo = std::sqrt(lo2) * (1 - 16 * lu), hi = std::sqrt(hi2) * (1 + 16 * lu);
      if (lo >= small) continue;
      if (hi < small && lo > 0) outputs_beyond = true;
      else outputs_unread = true;
    }
  }
  const bool headroom = !outputs_beyond && within_headroom(op, c.inputs, outputs_unread ? mpfr_want().outputs : engine::Values{}, f);
  // As in how_to_judge: t or exp's angle beyond the strict bar first, so the perturbations
  // compare statuses only.
  bool numbers = ok && headroom && !multiplied_rounding_beyond_strict_bar(op, tc, c, f);
  const bool debug = fuzz_debug();
  auto to_mpfr = [&](const char* why, int pattern) {
    if (debug) std::fprintf(stderr, "fast oracle: %s: %s; this perturbation goes to MPFR\n", op.name.c_str(), why);
    Case p;
    perturbed(c, op, pattern, u, p);
    return mpfr_perturbation(op, tc, c, f, p, pattern, numbers, mpfr_want());
  };
  // Where an acceptable convention is relevant, judge_case_against turns a result that fails the
  // strict bar into an ACCEPTABLE PASS when the first convention that accepts it (in the list's
  // order) does so with a PASS. Decided here only where the conventions have a fast form
  // (fast_acceptable_answers, formed once per element): surely PASS against the first answer, or
  // surely not PASS against the spec's and every other answer.
  std::optional<std::optional<std::vector<engine::AcceptableAnswer>>> acceptable;
  // A convention accepts a result when its verdict is not FAIL (where the spec's is a
  // QUALITY_WARNING: when it is PASS); the first that accepts gives the verdict. So: agrees where
  // a convention is surely PASS and every earlier one surely FAILs or says nothing; beyond the bar
  // where the spec's verdict and every convention's are surely not PASS; else MPFR's to decide.
  auto judged_with_conventions = [&](const engine::FastVerdicts& v, const engine::FastReference& r, int pattern) {
    if (!acceptable) acceptable = engine::fast_acceptable_answers(op, c, in, want, f);
    if (!*acceptable) return to_mpfr("an acceptable convention may be relevant and has no fast form", pattern);
    bool surely_not_pass = v.best != ref::Verdict::pass;
    bool earlier_decline = true;  // every earlier convention surely FAILs or says nothing
    std::optional<std::optional<engine::BoundedValues>> got;  // r rounded, as intervals (on first use)
    for (const engine::AcceptableAnswer& a : **acceptable) {
      std::optional<engine::FastVerdicts> av;
      if (a.answer) {
        av = rounded_verdicts(op, *fc, r, f, *a.answer);
      } else {
        if (!got) got = engine::rounded_intervals(r, f);
        if (*got) {
          const ref::BoundedScope scope;
          const std::optional<ref::Bounded> e = a.error(**got);
          if (scope.decided() && !e) continue;  // says nothing about this result
          if (scope.decided() && std::isfinite(e->value())) av = engine::fast_verdicts_of_error(*fc, *e);
        }
      }
      if (earlier_decline && av && av->worst == ref::Verdict::pass) return Perturbation::agrees;
      if (!av || av->best == ref::Verdict::pass) surely_not_pass = false;
      if (!av || av->best != ref::Verdict::fail) earlier_decline = false;
    }
    return surely_not_pass ? Perturbation::beyond_strict_bar
                           : to_mpfr("a perturbed result sits on the strict bar of the spec or a convention", pattern);
  };
  // The perturbations formed in Bounded arithmetic (perturbed_values) from `in`, c's inputs,
  // MPFR's only where one goes to MPFR.
  const ref::Bounded bu = engine::bounded_value(u);
  engine::BoundedValues p;
  for (int pattern = 0; perturbed_values(in, op, pattern, bu, p); ++pattern) {
    const auto r = engine::fast_reference(op, p, c.k);
    Perturbation step;
    if (!r) {
      step = to_mpfr("a perturbed reference is undecided", pattern);
    } else if (r->status != want.status) {
      step = Perturbation::status_differs;
    } else if (!numbers) {
      step = Perturbation::agrees;
    } else {
      // The perturbed result as rounded to the format, judged against the element's reference
      // whichever way it rounds: PASS for every rounding, or (where no acceptable convention could
      // make it an ACCEPTABLE PASS) surely beyond the strict bar for every one.
      const auto v = fc ? rounded_verdicts(op, *fc, *r, f, want) : std::nullopt;
      if (v && v->worst == ref::Verdict::pass) step = Perturbation::agrees;
      else if (!v) step = to_mpfr("a perturbed result's error is not bounded", pattern);
      else if (!engine::may_be_acceptable(op, c, f))
        step = v->best != ref::Verdict::pass ? Perturbation::beyond_strict_bar
                                              : to_mpfr("a perturbed result sits on the strict bar", pattern);
      else step = judged_with_conventions(*v, *r, pattern);
    }
    if (step == Perturbation::status_differs) return Judge::nothing;
    if (step == Perturbation::beyond_strict_bar) numbers = false;
  }
  if (!ok || numbers) return Judge::everything;
  if (op.name == "from_matrix" && !headroom) return Judge::nothing;
  return Judge::status_only;
}

/// Which level answers (ROTORCERT_FUZZ_ORACLE): "fast" (the default: the fast level where it
/// decides, MPFR elsewhere), "mpfr" (MPFR only), or "both" (both everywhere, and any difference
/// is a finding: the agreement check on fuzzed inputs).
enum class OracleMode { fast, mpfr, both };
OracleMode oracle_mode() {
  static const OracleMode mode = [] {
    const char* env = std::getenv("ROTORCERT_FUZZ_ORACLE");
    const std::string m = env ? env : "fast";
    if (m == "mpfr") return OracleMode::mpfr;
    if (m == "both") return OracleMode::both;
    if (m != "fast") std::fprintf(stderr, "ROTORCERT_FUZZ_ORACLE=%s: not fast, mpfr or both; using fast\n", m.c_str());
    return OracleMode::fast;
  }();
  return mode;
}

[[noreturn]] void oracle_disagreement(const Decoded& d, std::size_t e, const std::string& what) {
  std::fprintf(stderr,
               "\n==== rotorcert fuzz finding ====\n"
               "the fast oracle and MPFR disagree (ROTORCERT_FUZZ_ORACLE=both)\n"
               "op:             %s (element %zu of n = %zu, k = %zu)\n"
               "what:           %s\n"
               "inputs:         %s\n"
               "raw bits:       %s\n"
               "================================\n",
               d.op->name.c_str(), e, d.n, d.k, what.c_str(),
               engine::describe_inputs(*d.op, d.exact_case(e), d.format()).c_str(), raw_words(d, e).c_str());
  std::abort();
}

/// With ROTORCERT_FUZZ_STATS set: per op, how many elements were judged how (printed at exit),
/// to see how much of what a harness generates is judged in full.
struct Stats {
  std::map<std::string, std::array<std::size_t, 4>> counts;  // by Judge; [3]: no result needed it
  std::map<std::string, std::size_t> fast;      // elements the fast level judged without MPFR
  std::map<std::string, std::size_t> memo_hits;  // elements whose judgement came from the memo
  ~Stats() {
    if (std::getenv("ROTORCERT_FUZZ_STATS") == nullptr) return;
    auto at = [](const std::map<std::string, std::size_t>& m, const std::string& k) {
      return m.count(k) ? m.at(k) : std::size_t{0};
    };
    for (const auto& [op, c] : counts)
      std::fprintf(stderr,
                   "stats: %-28s everything %8zu  status only %8zu  nothing %8zu  not needed %8zu  without MPFR %8zu  "
                   "from the memo %8zu\n",
                   op.c_str(), c[0], c[1], c[2], c[3], at(fast, op), at(memo_hits, op));
  }
};
Stats& stats() {
  static Stats s;
  return s;
}

/// What an element's judgement needs besides the tables' outputs: a pure function of the op, the
/// format, k and the element's input bits, so it is kept between executions. libFuzzer's
/// mutations mostly change one element of a batch and leave the others' bits as they were, and
/// the reference evaluations (fast and MPFR, of the element and of its perturbations) are nearly
/// all of an execution's cost. The tables are still called on every execution, since a table's
/// result may depend on an element's place in the batch (SIMD lanes and tails); what a table
/// returns is judged again only when its bits differ from results already cleared.
struct ElementJudgement {
  std::optional<Judge> judge;  // how_to_judge's answer, once a table's result has needed it
  ref::Status status = ref::Status::ok;
  std::optional<engine::FastReference> fast;
  std::optional<engine::FastCase> fast_case;
  std::optional<engine::ReferenceResult> exact;
  /// Results judged not to be a finding, by any table (TableResults::key; for log's round trip,
  /// the log results' key followed by exp's): the verdict is a function of the element and these
  /// bits alone.
  std::unordered_set<std::string> cleared;
};

/// The memo, keyed by the op, format, k and the element's raw input words. Bounded: emptied
/// when full (a simple policy: the corpus inputs a campaign keeps mutating refill it at once).
class JudgementMemo {
 public:
  static constexpr std::size_t kCapacity = 1 << 13;

  static std::string key(const Decoded& d, std::size_t e) {
    std::string k;
    k.reserve(64);
    k.append(d.op->name).push_back('\0');
    k.push_back(d.f64 ? 'd' : 'f');
    k.push_back(static_cast<char>(d.k));
    const std::size_t word = d.f64 ? 8 : 4;
    for (std::size_t a = 0; a < d.op->inputs.size(); ++a) {
      const std::size_t bytes = element_count(*d.op, a, d.k) * word;
      k.append(reinterpret_cast<const char*>(d.raw[a].data() + e * bytes), bytes);
    }
    return k;
  }
  ElementJudgement* find(const std::string& k) {
    const auto it = map_.find(k);
    return it == map_.end() ? nullptr : &it->second;
  }
  void put(std::string k, ElementJudgement j) {
    if (map_.size() >= kCapacity) map_.clear();
    map_.insert_or_assign(std::move(k), std::move(j));
  }

 private:
  std::unordered_map<std::string, ElementJudgement> map_;
};

/// At most this many cleared results per element: a table whose results vary from call to call
/// (a bug the judge would see as well) cannot make an entry grow without bound.
constexpr std::size_t kClearedPerElement = 64;

JudgementMemo& memo() {
  static JudgementMemo m;
  return m;
}

/// ROTORCERT_FUZZ_MEMO=0 turns the memo off (to measure what it saves, or to rule it out).
bool memo_enabled() {
  static const bool on = [] {
    const char* env = std::getenv("ROTORCERT_FUZZ_MEMO");
    return env == nullptr || std::string(env) != "0";
  }();
  return on;
}

}  // namespace

void init() { (void)state(); }

const spec::Spec& embedded_spec() { return state().spec; }

bool is_expected_failure(const std::string& table, const std::string& scalar, const std::string& clause) {
  return state().expected.count(table + "/" + scalar + "/" + clause) != 0;
}

std::vector<std::string> clauses_judging(const std::string& op) {
  std::vector<std::string> r;
  for (const spec::Clause& cl : embedded_spec().clauses) {
    if (cl.level == "Meta") continue;
    const auto ops = engine::ops_for_clause(cl.id);
    if (std::find(ops.begin(), ops.end(), op) != ops.end()) r.push_back(cl.id);
  }
  return r;
}

std::string fuzz_tolerance_uncached(const std::string& op) {
  const spec::Spec& s = embedded_spec();
  std::string best;
  double best_loose = -1;
  for (const std::string& clause : clauses_judging(op)) {
    if (clause == "EXP-2") continue;  // the round trip, judged on its own
    const std::string name = engine::tolerance_for(s, clause, op);
    const spec::ToleranceClass& tc = s.lookup(name);
    double loose = -1;
    if (tc.kind == "formula") loose = 1e300;  // inherited-mat: 256 eps + 8 delta, the loosest there is
    else if (tc.kind == "eps") loose = tc.loose_value()->toDouble();
    else continue;  // exact (identity inputs only), outcome (status only), informative
    if (loose > best_loose) {
      best_loose = loose;
      best = name;
    }
  }
  return best;
}

/// Memoised per op: the spec does not change during a run.
std::string fuzz_tolerance(const std::string& op) {
  static std::map<std::string, std::string> cache;
  static std::mutex m;
  const std::lock_guard<std::mutex> lock(m);
  auto it = cache.find(op);
  if (it == cache.end()) it = cache.emplace(op, fuzz_tolerance_uncached(op)).first;
  return it->second;
}

bool eligible_uncached(const rc_impl& table, const std::string& op, std::string* why) {
  if (!engine::supports(table, op)) {
    if (why) *why = "no such op";
    return false;
  }
  const auto claimed = engine::claimed_clauses(table);
  for (const std::string& clause : clauses_judging(op)) {
    if (std::find(claimed.begin(), claimed.end(), clause) == claimed.end()) {
      if (why) *why = "does not claim " + clause;
      return false;
    }
    if (is_expected_failure(table.name, scalar_of(table), clause)) {
      if (why) *why = "known defect " + clause;
      return false;
    }
  }
  return true;
}

bool eligible(const rc_impl& table, const std::string& op, std::string* why) {
  if (why != nullptr) return eligible_uncached(table, op, why);
  static std::map<std::pair<const rc_impl*, std::string>, bool> cache;  // built-in tables live as long
  static std::mutex m;
  const std::lock_guard<std::mutex> lock(m);
  auto it = cache.find({&table, op});
  if (it == cache.end()) it = cache.emplace(std::make_pair(&table, op), eligible_uncached(table, op, nullptr)).first;
  return it->second;
}

namespace {

/// Memoised per table, as eligible(): a table's declarations (DECL-1) do not change during a run.
const engine::Declarations& declarations(const rc_impl& table) {
  static std::map<const rc_impl*, engine::Declarations> cache;
  static std::mutex m;
  const std::lock_guard<std::mutex> lock(m);
  auto it = cache.find(&table);
  if (it == cache.end()) it = cache.emplace(&table, engine::declarations_of(table)).first;
  return it->second;
}

}  // namespace

int check(const Decoded& d) {
  static const std::vector<const rc_impl*> tables = impl::builtin_tables();  // static tables: listed once
  return check(d, tables, print_and_abort);
}

int check(const Decoded& d, const std::vector<const rc_impl*>& tables, const FindingHandler& on_finding) {
  init();
  const spec::Spec& s = embedded_spec();
  const AbiOp& op = *d.op;
  const ref::Format f = d.format();
  const std::string tol_name = fuzz_tolerance(op.name);
  const spec::ToleranceClass& tc = s.lookup(tol_name);

  // Per element: the reference status, from the fast level where it decides; the MPFR reference
  // is computed only where it is needed. How much of an element is judged (its perturbations: most
  // of an element's cost) is decided only when a table's result needs it (judge_of below).
  const OracleMode mode = oracle_mode();
  std::vector<std::optional<Judge>> judge(d.n);
  std::vector<ref::Status> status(d.n, ref::Status::ok);
  std::vector<std::optional<engine::FastReference>> fast(d.n);
  std::vector<std::optional<engine::FastCase>> fast_case(d.n);  // per element, shared by every table
  std::vector<std::optional<engine::ReferenceResult>> exact(d.n);
  auto mpfr_want = [&](std::size_t e) -> const engine::ReferenceResult& {
    if (!exact[e]) exact[e] = op.reference(d.exact_case(e).inputs, d.k);
    return *exact[e];
  };
  // The memo serves the fast mode only: "mpfr" measures MPFR alone, "both" compares the levels
  // on every element it sees.
  const bool use_memo = mode == OracleMode::fast && memo_enabled();
  std::vector<std::string> keys(use_memo ? d.n : 0);  // (keys[e] is moved from only after its last use)
  std::vector<bool> remembered(d.n, false);

  // how_to_judge of element e at the fast level where it decides, else MPFR's; in "both" mode
  // both, and a difference is a finding.
  auto decide = [&](std::size_t e) {
    std::optional<Judge> j;
    if (fast[e]) {
      const engine::BoundedValues in = bounded_inputs(d, e);
      j = how_to_judge_fast(op, tc, d.exact_case(e), f, in, *fast[e], fast_case[e],
                            [&]() -> const engine::ReferenceResult& { return mpfr_want(e); });
    }
    if (!j || mode == OracleMode::both) {
      const Judge m = how_to_judge(op, tc, d.exact_case(e), f, [&]() -> const engine::ReferenceResult& { return mpfr_want(e); });
      if (j && *j != m)
        oracle_disagreement(d, e, "how much is judged: fast " + std::to_string(static_cast<int>(*j)) + ", MPFR " +
                                      std::to_string(static_cast<int>(m)));
      if (fast[e] && mode == OracleMode::both && fast[e]->status != mpfr_want(e).status)
        oracle_disagreement(d, e, "the reference status");
      j = m;
    }
    return *j;
  };
  // Lazy in the fast mode: a result surely within the loose bar (or, for an ill-conditioned
  // element, with status OK) is no finding whichever way the element is judged, so only a result
  // that may be one asks for the judgement.
  auto judge_of = [&](std::size_t e) {
    if (!judge[e]) judge[e] = decide(e);
    return *judge[e];
  };

  for (std::size_t e = 0; e < d.n; ++e) {
    if (use_memo) {
      keys[e] = JudgementMemo::key(d, e);
      if (const ElementJudgement* m = memo().find(keys[e])) {
        judge[e] = m->judge;
        status[e] = m->status;
        fast[e] = m->fast;
        fast_case[e] = m->fast_case;
        exact[e] = m->exact;
        remembered[e] = true;
        ++stats().memo_hits[op.name];
        continue;
      }
    }
    if (op.name == "from_matrix" && engine::numerically_singular(d.exact_case(e).inputs.at(0), f)) {
      judge[e] = Judge::nothing;  // how_to_judge's first test, on the input alone: no reference needed
      continue;
    }
    if (mode != OracleMode::mpfr) {
      fast[e] = engine::fast_reference(op, bounded_inputs(d, e), d.k);
      // Undecided (a branch the element's own bound cannot settle): its MPFR reference is the
      // fast level's want, so that the perturbations, most of which the bounds still settle, stay
      // at the fast level, and so do the tables' verdicts.
      if (!fast[e]) {
        if (fuzz_debug())
          std::fprintf(stderr, "fast oracle: %s: the element's reference is undecided; its MPFR reference is the want: %s\n",
                       op.name.c_str(), engine::describe_inputs(op, d.exact_case(e), f).c_str());
        fast[e] = engine::fast_reference_from(op, mpfr_want(e));
      }
    }
    if (fast[e]) fast_case[e] = engine::fast_case(op, tc, d.exact_case(e), f);
    if (!fast[e] || mode != OracleMode::fast) judge_of(e);  // MPFR alone, or both levels everywhere
    status[e] = fast[e] ? fast[e]->status : mpfr_want(e).status;
  }

  // EXP-2's class and, per element, its fast bars: the same for every table that runs the round trip.
  const std::string rt_name = op.name == "log" ? engine::tolerance_for(s, "EXP-2", "log") : std::string();
  std::vector<std::optional<engine::FastCase>> round_trip_case(d.n);
  if (op.name == "log" && mode != OracleMode::mpfr)
    for (std::size_t e = 0; e < d.n; ++e)
      if (status[e] == ref::Status::ok && judge[e] != Judge::nothing)
        round_trip_case[e] = engine::fast_case(op, s.lookup(rt_name), d.exact_case(e), f);

  // Per element, the results already cleared: the memo's set for a remembered element, a new one
  // (remembered below) for the others. Nothing is put into the memo before the tables have run,
  // so the pointers stay valid.
  std::vector<std::unordered_set<std::string>> new_cleared(use_memo ? d.n : 0);
  std::vector<std::unordered_set<std::string>*> cleared(d.n, nullptr);
  if (use_memo)
    for (std::size_t e = 0; e < d.n; ++e) {
      ElementJudgement* m = remembered[e] ? memo().find(keys[e]) : nullptr;
      cleared[e] = m != nullptr ? &m->cleared : &new_cleared[e];
    }
  auto is_cleared = [&](std::size_t e, const std::string& key) { return cleared[e] && cleared[e]->count(key) != 0; };
  auto clear = [&](std::size_t e, std::string key) {
    if (cleared[e] && cleared[e]->size() < kClearedPerElement) cleared[e]->insert(std::move(key));
  };

  // A finding is reported and its result is not cleared (a handler that returns sees it again).
  auto finding = [&](const rc_impl& t, std::size_t e, const std::string& what, const std::string& tolerance,
                     const engine::CaseVerdict& v) { on_finding(d, Finding{&t, e, what, tolerance, v}); };
  int run = 0;
  for (const rc_impl* t : tables) {
    if ((t->scalar == RC_SCALAR_FLOAT64) != d.f64 || !eligible(*t, op.name)) continue;
    ++run;
    // DECL-1: an input outside a precondition the library documents is not judged, as in certify.
    const engine::Declarations& declared = declarations(*t);
    const TableResults got = call_raw(*t, op, d.n, d.k, d.raw);
    engine::BoundedValues got_values;
    for (std::size_t e = 0; e < d.n; ++e) {
      if (judge[e] == Judge::nothing) continue;
      std::string got_key = got.key(e);
      if (is_cleared(e, got_key)) continue;
      // Surely within the loose bar is never a FAIL: MPFR's verdict is PASS or QUALITY_WARNING,
      // which an acceptable convention can only turn into an ACCEPTABLE PASS. With status OK it is
      // no finding where only the status is judged either. The words are read as Bounded values
      // directly; MPFR numbers only where MPFR judges.
      std::optional<engine::FastVerdicts> fv;
      if (fast[e] && fast_case[e] && got.rc == 0 && got.status[e] == RC_OK && got.bounded(e, got_values))
        fv = engine::fast_verdicts_of_values(op, *fast_case[e], got_values, *fast[e]);
      const bool surely_within = fv && fv->worst != ref::Verdict::fail;
      if (mode == OracleMode::both && surely_within && judge_of(e) == Judge::everything &&
          engine::judge_case_against(op, tc, d.exact_case(e), got.observed(e), f, mpfr_want(e), false).verdict ==
              ref::Verdict::fail)
        oracle_disagreement(d, e, std::string("the verdict on ") + t->name + ": fast not FAIL, MPFR FAIL");
      if (!surely_within) {
        // (Read only here: within the bar a result is no finding whatever the precondition says.)
        if (!declared.preconditions.empty() && engine::violated_precondition(declared, op, d.exact_case(e), f)) continue;
        const Judge j = judge_of(e);
        if (j == Judge::nothing) continue;
        if (j == Judge::everything) {
          const engine::CaseVerdict v =
              engine::judge_case_against(op, tc, d.exact_case(e), got.observed(e), f, mpfr_want(e), false);
          if (v.verdict == ref::Verdict::fail) {
            finding(*t, e, "FAIL against the reference", tol_name, v);
            continue;
          }
        } else if (got.rc != 0 || got.status[e] != RC_OK) {
          finding(*t, e, "ill-conditioned input inside the domain: status OK required", tol_name,
                  {ref::Verdict::fail, NAN,
                   "call returned " + std::to_string(got.rc) + ", status byte " + std::to_string(got.status[e])});
          continue;
        }
      }
      clear(e, std::move(got_key));
    }
    // EXP-2: exp(log q) = q through the implementation, on log's own outputs (their words as the
    // table wrote them are exp's inputs).
    if (op.name == "log" && engine::supports(*t, "exp") && eligible(*t, "exp")) {
      const AbiOp& exp_op = *engine::find_abi_op("exp");
      const TableResults back = call_raw(*t, exp_op, d.n, 0, {got.out.at(0)});
      const spec::ToleranceClass& rt_tc = s.lookup(rt_name);
      for (std::size_t e = 0; e < d.n; ++e) {
        if (status[e] != ref::Status::ok || judge[e] == Judge::nothing) continue;
        std::string rt_key = got.key(e) + back.key(e);
        if (is_cleared(e, rt_key)) continue;
        const Observed got_e = got.observed(e), back_e = back.observed(e);
        // Surely not a FAIL at the fast level: MPFR's distance is not needed (in "both" mode it
        // is computed as well, and a FAIL there is a disagreement).
        const auto& fc = round_trip_case[e];
        const auto fv = fc ? engine::fast_round_trip_verdicts(*fc, d.exact_case(e), got_e, back_e) : std::nullopt;
        if (fv && fv->worst != ref::Verdict::fail) {
          if (mode == OracleMode::both && judge_of(e) != Judge::nothing &&
              engine::judge_round_trip(rt_tc, d.exact_case(e), got_e, back_e, f).verdict == ref::Verdict::fail)
            oracle_disagreement(d, e, std::string("EXP-2 on ") + t->name + ": fast not FAIL, MPFR FAIL");
        } else if (judge_of(e) != Judge::nothing) {
          const engine::CaseVerdict v = engine::judge_round_trip(rt_tc, d.exact_case(e), got_e, back_e, f);
          if (v.verdict == ref::Verdict::fail) {
            engine::CaseVerdict shown = v;
            shown.detail += "; log q = [";
            for (const Real& x : got_e.outputs.at(0)) shown.detail += engine::hexfloat(x, f) + " ";
            shown.detail += "]";
            finding(*t, e, "EXP-2: exp(log q) != q through the implementation", rt_name, shown);
            continue;
          }
        }
        clear(e, std::move(rt_key));
      }
    }
  }
  // Per element: how it was judged ("not needed": no result asked), and whether without MPFR.
  for (std::size_t e = 0; e < d.n; ++e) {
    ++stats().counts[op.name][judge[e] ? static_cast<std::size_t>(*judge[e]) : 3];
    if (!remembered[e] && fast[e] && !exact[e]) ++stats().fast[op.name];
  }
  // Remembered after the tables: an MPFR reference and a judgement they needed are kept too.
  if (use_memo)
    for (std::size_t e = 0; e < d.n; ++e) {
      if (!remembered[e])
        memo().put(std::move(keys[e]), ElementJudgement{judge[e], status[e], std::move(fast[e]), std::move(fast_case[e]),
                                                        std::move(exact[e]), std::move(new_cleared[e])});
      else if (ElementJudgement* m = memo().find(keys[e])) {  // (an entry the loop above evicted is not updated)
        if (exact[e] && !m->exact) m->exact = std::move(exact[e]);
        if (judge[e] && !m->judge) m->judge = judge[e];
      }
    }
  return run;
}

}  // namespace rotorcert::fuzz
