#include <rotorcert/engine/declarations.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include <rotorcert/engine/cases.hpp>
#include <rotorcert/engine/runner.hpp>
#include <rotorcert/reference/metrics.hpp>
#include <rotorcert/reference/rigid_ops.hpp>
#include <rotorcert/reference/rotation_ops.hpp>

namespace rotorcert::engine {
namespace {

using Quat = ref::Quaternion<Real>;
using V3 = ref::Vec3<Real>;
namespace clause = ref::clause;

Quat quat(const std::vector<Real>& a, std::size_t i = 0) { return {a[i * 4 + 3], a[i * 4], a[i * 4 + 1], a[i * 4 + 2]}; }


/// ACC-1 nonfinite_limit's bars: class eps16 of spec/clauses.json (a test holds them equal).
constexpr ref::Bars kLimitBars{16, 256};

/// The near-unit band of the preconditions: 64 eps, wide enough for inputs that went through
/// a few roundings (a normalised quaternion is within 2 eps of unit), narrow enough that a
/// deliberately non-unit input (EDGE-5) is outside it.
Real unit_band(ref::Format f) { return Real(64) * ref::format_epsilon<Real>(f); }

bool all_finite(const Case& c) {
  for (const auto& a : c.inputs)
    for (const Real& x : a)
      if (!mpfr::isfinite(x)) return false;
  return true;
}

/// Whether every output component is +-0 (a sentinel of EDGE-6 and EDGE-7).
bool every_output_zero(const Values& got) {
  return std::all_of(got.begin(), got.end(), [](const std::vector<Real>& a) {
    return std::all_of(a.begin(), a.end(), [](const Real& x) { return x == 0; });
  });
}

/// Whether some output component is NaN or infinite: a non-finite input carried into the result.
bool some_output_nonfinite(const Values& got) {
  return std::any_of(got.begin(), got.end(), [](const std::vector<Real>& a) {
    return std::any_of(a.begin(), a.end(), [](const Real& x) { return !mpfr::isfinite(x); });
  });
}

/// Whether the all-zero output is no answer the op can give: it returns a rotation (quaternion,
/// dual quaternion, matrix) or a unit axis, never zero, so zero flags an error (EDGE-6, EDGE-7).
bool zero_is_no_answer(const AbiOp& op) {
  for (const Array& a : op.outputs)
    switch (a.measure) {
      case Measure::rotation:
      case Measure::quaternion:
      case Measure::unit_rotation:
      case Measure::signed_unit_rotation:
      case Measure::canonical_rotation:
      case Measure::matrix:
      case Measure::rigid:
      case Measure::unit_rigid:
      case Measure::dual_parts: return true;
      case Measure::vector:
        if (a.name == "out_axis") return true;
        break;
      case Measure::point:
      case Measure::bivector:
      case Measure::angle:
      case Measure::scalar: break;
    }
  return false;
}

std::size_t input_index(const AbiOp& op, const std::string& name) {
  for (std::size_t i = 0; i < op.inputs.size(); ++i)
    if (op.inputs[i].name == name) return i;
  return op.inputs.size();
}

bool has_stride(const AbiOp& op, int stride) {
  return std::any_of(op.inputs.begin(), op.inputs.end(), [&](const Array& a) { return a.stride == stride; });
}

bool is_interpolation(const AbiOp& op) { return op.name == "slerp" || op.name == "nlerp" || op.name == "dq_sclerp"; }

/// The quaternion a/|a| (exact, at the reference precision).
Quat unit(const Quat& q) { return ref::normalized(q); }

/// The rotation distance and norm defect of a quaternion output against `want` (METRIC-1, 6).
Real unit_rotation_error(const std::vector<Real>& got, const Quat& want) {
  return std::max(clause::METRIC_1_rotation_distance(quat(got), want), clause::METRIC_6_norm_defect(quat(got)));
}

/// The exact normalised dot product of two quaternion blocks: |a.b| / (|a||b|).
Real normalised_dot(const std::vector<Real>& a, std::size_t ia, const std::vector<Real>& b, std::size_t ib) {
  const Quat qa = quat(a, ia), qb = quat(b, ib);
  const Real na = block_norm(a, ia * 4, 4), nb = block_norm(b, ib * 4, 4);
  if (na == 0 || nb == 0) return Real(1);
  return ref::dot(qa, qb) / (na * nb);
}

// ---- the conventions' errors and answer-reading relevances, one formula at both levels -----
// Templates on the scalar: the judge runs them on Real (MPFR) through `error` and `relevant`, the
// fast oracle on ref::Bounded through `fast_error` and `fast_relevant`. Arrays<T> holds an op's
// arrays as Values holds them in Real.

template <class T>
using Arrays = std::vector<std::vector<T>>;

template <class T>
ref::Quaternion<T> quat_of(const std::vector<T>& a, std::size_t i = 0) {
  return {a[i * 4 + 3], a[i * 4], a[i * 4 + 1], a[i * 4 + 2]};
}
/// block_norm (abi_op.hpp) on either scalar.
template <class T>
T norm_of(const std::vector<T>& v, std::size_t from, std::size_t n) {
  using std::sqrt;
  T s(0);
  for (std::size_t i = from; i < from + n && i < v.size(); ++i) s += v[i] * v[i];
  return sqrt(s);
}
template <class T>
bool is_nan_of(const T& x) { return ref::ScalarTraits<T>::is_nan(x); }
template <class T>
T pi_of() { return ref::ScalarTraits<T>::pi(); }
/// std::max on Real, as the errors have always taken it (a NaN first operand wins); on Bounded
/// the 1-Lipschitz max of the intervals, NaN where either is (the fast level leaves a NaN error
/// to MPFR).
template <class T>
T larger(const T& a, const T& b) {
  if constexpr (std::is_same_v<T, ref::Bounded>) {
    if (is_nan_of(a) || is_nan_of(b)) return ref::ScalarTraits<T>::nan();
    return ref::max(a, b);
  } else {
    return std::max(a, b);
  }
}

/// METRIC-1 and METRIC-6 of a quaternion output against `want` (unit_rotation_error).
template <class T>
T rotation_error_of(const std::vector<T>& got, const ref::Quaternion<T>& want) {
  return larger(clause::METRIC_1_rotation_distance(quat_of(got), want), clause::METRIC_6_norm_defect(quat_of(got)));
}

/// AXANG-1: (theta, u) compared as rotations, with a unit axis required.
template <class T>
T axis_angle_error(const Arrays<T>& got, const Arrays<T>& want) {
  using std::abs, std::cos, std::sin;
  const T h = got[0][0] / T(2);
  const ref::Quaternion<T> g{cos(h), sin(h) * got[1][0], sin(h) * got[1][1], sin(h) * got[1][2]};
  const T hw = want[0][0] / T(2);
  const ref::Quaternion<T> w{cos(hw), sin(hw) * want[1][0], sin(hw) * want[1][1], sin(hw) * want[1][2]};
  const T axis_defect = abs(norm_of(got[1], 0, 3) - T(1));
  if (is_nan_of(axis_defect)) return axis_defect;
  return larger(clause::METRIC_1_rotation_distance(g, w), axis_defect);
}
/// AXANG-1's identity: angle 0 or 2 pi.
template <class T>
bool identity_angle(const Arrays<T>& want) {
  return want[0][0] == 0 || want[0][0] >= T(2) * pi_of<T>();
}

/// AXANG-3: the rotation angle rho(x) = 2 atan2(|sin(x/2)|, |cos(x/2)|) in [0, pi].
template <class T>
T rotation_angle(const T& x) {
  using std::abs, std::atan2, std::cos, std::sin;
  return T(2) * atan2(abs(sin(x / T(2))), abs(cos(x / T(2))));
}

/// | |u| - 1 | of an axis output.
template <class T>
T axis_defect(const std::vector<T>& u) {
  using std::abs;
  return abs(norm_of(u, 0, 3) - T(1));
}

/// SQRT-1 algebraic_root: the rotation of s/|s| against the reference and | |s|^2 / |q| - 1 |.
template <class T>
std::optional<T> algebraic_root_error(const std::vector<T>& q, const std::vector<T>& got, const std::vector<T>& want) {
  using std::abs;
  const T n = norm_of(got, 0, 4), nq = norm_of(q, 0, 4);
  if (is_nan_of(n) || n == 0 || nq == 0) return std::nullopt;
  const ref::Quaternion<T> s = quat_of(got);
  const ref::Quaternion<T> u{s.w / n, s.x / n, s.y / n, s.z / n};
  return larger(clause::METRIC_1_rotation_distance(u, quat_of(want)), T(abs(n * n / nq - T(1))));
}

/// SQRT-1 minus_one_axis: s'^2 against q^ = -1 with its sign, and s' unit.
template <class T>
T minus_one_root_error(const std::vector<T>& got) {
  using std::abs;
  const ref::Quaternion<T> s = quat_of(got);
  // max_i |(s'^2)_i - (-1)_i|: s' = 1 squares to +1, the same rotation as -1 but no square root of it.
  const ref::Quaternion<T> p = s * s;
  const T e = larger(larger(larger(T(abs(p.w + T(1))), T(abs(p.x))), T(abs(p.y))), T(abs(p.z)));
  if (is_nan_of(e)) return e;
  return larger(e, clause::METRIC_6_norm_defect(s));
}

/// LOG-1/LOG-2: exp of both logs compared as rotations, and the excess beyond the principal range.
template <class T>
T log_error(const Arrays<T>& got, const Arrays<T>& want) {
  const T n = norm_of(got[0], 0, 3);
  if (is_nan_of(n)) return n;
  const auto e = clause::EXP_1_exp(ref::Vec3<T>{got[0][0], got[0][1], got[0][2]});
  const auto w = clause::EXP_1_exp(ref::Vec3<T>{want[0][0], want[0][1], want[0][2]});
  const T excess = larger(T(0), T(n - pi_of<T>()));
  return larger(clause::METRIC_1_rotation_distance(e.value, w.value), excess);
}
/// LOG-2: the spec's log of a negative real quaternion, pi (0, 0, +-1).
template <class T>
bool negative_real_log(const Arrays<T>& want) {
  using std::abs;
  return want[0][0] == 0 && want[0][1] == 0 && want[0][2] != 0 && abs(want[0][2]) >= pi_of<T>() - T(1e-30);
}
/// w <= 0: at w = 0 (a half turn) log q and log(-q) are equally short, a tie either side of which
/// is the same rotation (the reference's |v| is pi/2 up to its own last bits there).
template <class T>
bool obtuse_log(const Arrays<T>& want) {
  return norm_of(want[0], 0, 3) >= pi_of<T>() / T(2) - T(1e-60);
}

/// DQ-8: METRIC-7 of DQ-9(xi') against sigma, and the excess beyond the principal range.
template <class T>
T dq_log_error(const std::vector<T>& sigma_in, const Arrays<T>& got) {
  const ref::Vec3<T> r{got[0][0], got[0][1], got[0][2]}, d{got[0][3], got[0][4], got[0][5]};
  const auto e = clause::DQ_9_exp(ref::DualVector<T>{r, d});
  if (e.status != ref::Status::ok) return ref::ScalarTraits<T>::nan();
  const ref::DualQuaternion<T> sigma{quat_of(sigma_in, 0), quat_of(sigma_in, 1)};
  const auto m = clause::METRIC_7_rigid_error(e.value, sigma);
  const T excess = larger(T(0), T(norm_of(got[0], 0, 3) - pi_of<T>()));
  return larger(larger(m.rotation, m.translation), excess);
}

/// The scalar of an op's arrays (Values: Real; AcceptableConvention::BoundedArrays: ref::Bounded).
template <class ArraysT>
using ScalarOf = std::decay_t<decltype(std::declval<ArraysT>()[0][0])>;

/// Sets the `error` and `fast_error` of convention `a` from one generic form
/// error(c, inputs, got, want) -> std::optional<T>, `inputs` c's inputs in the scalar of got:
/// the judge's on Real, the fast oracle's on Bounded, one body.
template <class Error>
void set_error(AcceptableConvention& a, Error error) {
  a.error = [error](const AbiOp&, const Case& c, const Values& got, const Values& want,
                    ref::Format) -> std::optional<Real> { return error(c, c.inputs, got, want); };
  a.fast_error = [error](const AbiOp&, const Case& c, const AcceptableConvention::BoundedArrays& in,
                         const AcceptableConvention::BoundedArrays& got, const AcceptableConvention::BoundedArrays& want,
                         ref::Format) -> std::optional<ref::Bounded> { return error(c, in, got, want); };
}

/// Sets the relevance of convention `a` that reads the spec's answer, and its fast form, from one
/// generic predicate relevant(want).
template <class Relevant>
void set_answer_relevance(AcceptableConvention& a, Relevant relevant) {
  a.relevant = [relevant](const AbiOp&, const Case&, const Values& want, ref::Format) { return relevant(want); };
  a.fast_relevant = [relevant](const AbiOp&, const Case&, const AcceptableConvention::BoundedArrays& want,
                               ref::Format) { return relevant(want); };
}

/// The tie band of ACC-1 (hemisphere_tie): |a.b| within 8 eps of 0, where the rounding of a
/// dot product in the format (4 products, 3 sums) can give either sign.
bool near_tie(const Real& d, ref::Format f) { return abs(d) <= Real(8) * ref::format_epsilon<Real>(f); }

/// For n-way inputs: the index of the pivot (first positive weight), or -1.
long pivot_of(const std::vector<Real>& w) {
  for (std::size_t i = 0; i < w.size(); ++i)
    if (w[i] > 0) return long(i);
  return -1;
}

/// The influences (of the quaternion array `qa`, block stride `s` in scalars: 4 or 8) whose
/// real part ties with the pivot's.
std::vector<std::size_t> tied_influences(const Case& c, std::size_t qa, std::size_t wa, int s, ref::Format f) {
  std::vector<std::size_t> tied;
  const long p = pivot_of(c.inputs[wa]);
  if (p < 0) return tied;
  const auto& v = c.inputs[qa];
  std::vector<Real> reals;  // the real parts as quaternion blocks
  for (std::size_t i = 0; i * s < v.size(); ++i)
    for (int j = 0; j < 4; ++j) reals.push_back(v[i * s + j]);
  for (std::size_t i = 0; i < c.k; ++i)
    if (long(i) != p && near_tie(normalised_dot(reals, i, reals, std::size_t(p)), f)) tied.push_back(i);
  return tied;
}

/// The case with every zero quaternion replaced by the identity (0, 0, 0, 1), every dual
/// quaternion of zero real part by the identity motion, and a zero axis by +z at angle 0: the
/// input whose output is the identity sentinel of ACC-1 zero_sentinel. nullopt when the case
/// has no zero block.
std::optional<Case> identity_substituted(const AbiOp& op, const Case& c) {
  Case id = c;
  bool any = false;
  for (std::size_t a = 0; a < op.inputs.size() && a < id.inputs.size(); ++a) {
    const Array& arr = op.inputs[a];
    auto& v = id.inputs[a];
    if (arr.stride == 4 || arr.stride == 8) {
      const std::size_t s = static_cast<std::size_t>(arr.stride);
      for (std::size_t j = 0; j + s <= v.size(); j += s) {
        if (block_norm(v, j, 4) != 0) continue;
        // The whole dual quaternion, not only its real part: a repair that keeps the dual part
        // (SciPy's from_dual_quat, pytransform3d's check_dual_quaternion) invents a translation
        // from an input that has no motion, which no caller can tell from a real one.
        for (std::size_t i = 0; i < s; ++i) v[j + i] = Real(i == 3 ? 1 : 0);
        any = true;
      }
    } else if (is_axis_input(op, arr) && v.size() == 3 && block_norm(v, 0, 3) == 0) {
      v = {Real(0), Real(0), Real(1)};
      const std::size_t angle = input_index(op, "angle");
      if (angle < id.inputs.size()) id.inputs[angle] = {Real(0)};
      any = true;
    }
  }
  if (!any) return std::nullopt;
  return id;
}

/// The exact product of compose (a b, QUAT-1) or dq_compose ((ra rb, ra db + da rb), DQ-2) on
/// the unnormalised inputs, in ABI layout.
std::vector<Real> algebraic_product(const AbiOp& op, const Case& c) {
  auto out = [](const Quat& q) { return std::vector<Real>{q.x, q.y, q.z, q.w}; };
  if (op.name == "compose") return out(quat(c.inputs[0]) * quat(c.inputs[1]));
  const Quat ra = quat(c.inputs[0], 0), da = quat(c.inputs[0], 1), rb = quat(c.inputs[1], 0), db = quat(c.inputs[1], 1);
  std::vector<Real> r = out(ra * rb);
  const std::vector<Real> d = out(ra * db + da * rb);
  r.insert(r.end(), d.begin(), d.end());
  return r;
}

/// The output's error against the op's answer for another input `sub` (the identity put in a
/// zero's place, the limit of an infinite quaternion), as any correct library may give that
/// answer: the least error under the conventions a table need not declare. nullopt where `sub`
/// is outside the domain too.
std::optional<Real> error_as_answer_to(const AbiOp& op, const Case& sub, const Values& got, ref::Format f);

/// ACC-1 nonfinite_limit: the case with every quaternion block that holds an infinity replaced by
/// the rotation it tends to as its infinite components grow alike, (sgn of each infinite
/// component, 0 for each finite one) normalised. nullopt when the case holds a NaN, an infinity
/// outside a quaternion input (a vector, t, a weight, a dual quaternion: no rotation to tend to),
/// or none.
std::optional<Case> infinity_limit(const AbiOp& op, const Case& c) {
  const auto quaternion = [&](std::size_t a) { return a < op.inputs.size() && op.inputs[a].stride == 4; };
  bool any = false;
  for (std::size_t a = 0; a < c.inputs.size(); ++a)
    for (const Real& x : c.inputs[a]) {
      if (mpfr::isnan(x) || (mpfr::isinf(x) && !quaternion(a))) return std::nullopt;
      any = any || mpfr::isinf(x);
    }
  if (!any) return std::nullopt;
  Case lim = c;
  for (std::size_t a = 0; a < lim.inputs.size(); ++a) {
    if (!quaternion(a)) continue;
    auto& v = lim.inputs[a];
    for (std::size_t j = 0; j + 4 <= v.size(); j += 4) {
      const auto count = std::count_if(v.begin() + long(j), v.begin() + long(j) + 4, [](const Real& x) { return mpfr::isinf(x); });
      if (count == 0) continue;
      const Real scale = Real(1) / sqrt(Real(long(count)));
      for (std::size_t i = j; i < j + 4; ++i) v[i] = mpfr::isinf(v[i]) ? (v[i] > 0 ? scale : Real(-scale)) : Real(0);
    }
  }
  return lim;
}

std::vector<Precondition> build_preconditions() {
  std::vector<Precondition> all;
  all.push_back({"finite", "every input component is finite (no NaN, no infinity)",
                 [](const AbiOp&) { return true; },
                 [](const AbiOp&, const Case& c, ref::Format) { return all_finite(c); }});
  all.push_back({"unit_quaternion", "every quaternion input is unit (within 64 eps)",
                 [](const AbiOp& op) { return has_stride(op, 4); },
                 [](const AbiOp& op, const Case& c, ref::Format f) {
                   if (!all_finite(c)) return false;
                   for (std::size_t a = 0; a < op.inputs.size(); ++a)
                     if (op.inputs[a].stride == 4)
                       for (std::size_t j = 0; j + 4 <= c.inputs[a].size(); j += 4)
                         if (abs(block_norm(c.inputs[a], j, 4) - Real(1)) > unit_band(f)) return false;
                   return true;
                 }});
  // A squared norm that overflows or underflows in the format: Eigen's normalized() documents the
  // copy of its input where norm() == 0, which an underflowed squared norm reaches, and offers
  // stableNormalized() for "avoiding underflow and overflow" (Dot.h). Zero itself is EDGE-6's.
  all.push_back({"norm_in_range",
                 "every quaternion input's squared norm is 0 or lies between the format's smallest normal number and "
                 "its largest finite number (x^2 + y^2 + z^2 + w^2 neither underflows nor overflows)",
                 [](const AbiOp& op) { return has_stride(op, 4); },
                 [](const AbiOp& op, const Case& c, ref::Format f) {
                   if (!all_finite(c)) return false;
                   const Real lowest = ref::format_min_normal<Real>(f);
                   const Real highest = f == ref::Format::binary32 ? Real(std::numeric_limits<float>::max())
                                                                   : Real(std::numeric_limits<double>::max());
                   for (std::size_t a = 0; a < op.inputs.size(); ++a)
                     if (op.inputs[a].stride == 4)
                       for (std::size_t j = 0; j + 4 <= c.inputs[a].size(); j += 4) {
                         const Real n = block_norm(c.inputs[a], j, 4);
                         const Real n2 = n * n;
                         if (n2 != 0 && (n2 < lowest || n2 > highest)) return false;
                       }
                   return true;
                 }});
  all.push_back({"unit_dual_quaternion", "every dual quaternion input is unit: |real| = 1 and real . dual = 0 (within 64 eps)",
                 [](const AbiOp& op) { return has_stride(op, 8); },
                 [](const AbiOp& op, const Case& c, ref::Format f) {
                   if (!all_finite(c)) return false;
                   for (std::size_t a = 0; a < op.inputs.size(); ++a)
                     if (op.inputs[a].stride == 8)
                       for (std::size_t j = 0; j + 8 <= c.inputs[a].size(); j += 8) {
                         const auto& v = c.inputs[a];
                         if (abs(block_norm(v, j, 4) - Real(1)) > unit_band(f)) return false;
                         Real d(0);
                         for (int i = 0; i < 4; ++i) d += v[j + i] * v[j + 4 + i];
                         if (abs(d) > unit_band(f) * std::max(Real(1), block_norm(v, j + 4, 4))) return false;
                       }
                   return true;
                 }});
  all.push_back({"unit_axis", "the axis input is a unit vector (within 64 eps)",
                 [](const AbiOp& op) { return op.name == "from_axis_angle" || op.name == "rotate_about_axis"; },
                 [](const AbiOp& op, const Case& c, ref::Format f) {
                   if (!all_finite(c)) return false;
                   for (std::size_t a = 0; a < op.inputs.size() && a < c.inputs.size(); ++a)
                     if (is_axis_input(op, op.inputs[a]) && abs(block_norm(c.inputs[a], 0, 3) - Real(1)) > unit_band(f))
                       return false;
                   return true;
                 }});
  all.push_back({"rotation_matrix", "the matrix is a rotation: |M^T M - I|_F <= 64 eps and det M > 0",
                 [](const AbiOp& op) { return op.name == "from_matrix"; },
                 [](const AbiOp&, const Case& c, ref::Format f) {
                   if (!all_finite(c)) return false;
                   const auto& m = c.inputs[0];
                   const Real det = m[0] * (m[4] * m[8] - m[7] * m[5]) - m[3] * (m[1] * m[8] - m[7] * m[2]) +
                                    m[6] * (m[1] * m[5] - m[4] * m[2]);
                   return orthogonality_defect(m) <= unit_band(f) && det > 0;
                 }});
  all.push_back({"t_in_unit_interval", "the interpolation parameter t lies in [0, 1]",
                 [](const AbiOp& op) { return is_interpolation(op); },
                 [](const AbiOp& op, const Case& c, ref::Format) {
                   const std::size_t a = input_index(op, "t");
                   return a < c.inputs.size() && !c.inputs[a].empty() && c.inputs[a][0] >= 0 && c.inputs[a][0] <= 1;
                 }});
  all.push_back({"same_hemisphere", "the two inputs of an interpolation have a.b >= 0 (the caller aligns them)",
                 [](const AbiOp& op) { return is_interpolation(op); },
                 [](const AbiOp&, const Case& c, ref::Format) {
                   if (!all_finite(c)) return false;
                   Real d(0);
                   for (int i = 0; i < 4; ++i) d += c.inputs[0][i] * c.inputs[1][i];
                   return d >= 0;
                 }});
  // Not at EDGE-3's tie (near_tie of the normalised a.b, the real parts for dq_sclerp): the
  // plane of the interpolation is not determined there, and a library may document that it
  // refuses it (nalgebra's sclerp panics "if the angle between both quaternion is 180 degrees").
  // A zero input has no rotation, so it is no tie (normalised_dot: 1): EDGE-6 still judges it.
  all.push_back({"not_half_turn_apart", "the two rotations of an interpolation are not a half turn apart: |a.b| > 8 eps |a| |b|",
                 [](const AbiOp& op) { return is_interpolation(op); },
                 [](const AbiOp&, const Case& c, ref::Format f) {
                   return all_finite(c) && !near_tie(normalised_dot(c.inputs[0], 0, c.inputs[1], 0), f);
                 }});
  return all;
}

std::vector<AcceptableConvention> build_conventions() {
  std::vector<AcceptableConvention> all;
  const auto is = [](const char* name) { return [name](const AbiOp& op) { return op.name == name; }; };

  // Each error below is one generic form (set_error): the judge runs it on Real, the fast oracle
  // on ref::Bounded; so is each relevance that reads the spec's answer (set_answer_relevance).
  const auto always = [](const AbiOp&, const Case&, ref::Format) { return true; };
  // (A convention's error and relevance are set after it is added.)
  const auto add = [&all](const char* id, const char* description, std::function<bool(const AbiOp&)> applies,
                          Relevance relevant) -> AcceptableConvention& {
    return all.emplace_back(AcceptableConvention{id, description, false, std::move(applies), std::move(relevant), {}});
  };

  // MAT-2: q and -q are one rotation; the canonical sign (w > 0) is the spec's choice.
  set_error(add("sign", "from_matrix returns -q of the canonical q (w > 0): the same rotation", is("from_matrix"), always),
            [](const Case&, const auto&, const auto& got, const auto& want) -> std::optional<ScalarOf<decltype(got)>> {
              return rotation_error_of(got[0], quat_of(want[0]));
            });

  // AXANG-1: (theta, u) and (2 pi - theta, -u), or (theta - 2 pi, u), describe one rotation; the
  // identity has every unit axis. Compared as rotations, with a unit axis required
  // (axis_angle_error).
  {
    AcceptableConvention& a = add("identity_axis", "to_axis_angle of the identity rotation (angle 0 or 2 pi) returns another unit axis",
                                  is("to_axis_angle"), {});
    set_answer_relevance(a, [](const auto& want) { return identity_angle(want); });
    set_error(a, [](const Case&, const auto&, const auto& got, const auto& want) -> std::optional<ScalarOf<decltype(got)>> {
      if (!identity_angle(want)) return std::nullopt;
      return axis_angle_error(got, want);
    });
  }
  {
    AcceptableConvention& a = add("angle_range", "to_axis_angle returns the angle in another range ([0, pi] with the axis flipped, or signed)",
                                  is("to_axis_angle"), {});
    set_answer_relevance(a, [](const auto& want) { return !identity_angle(want); });
    set_error(a, [](const Case&, const auto&, const auto& got, const auto& want) -> std::optional<ScalarOf<decltype(got)>> {
      if (identity_angle(want)) return std::nullopt;
      return axis_angle_error(got, want);
    });
  }

  // AXANG-3: an angle alone is another correct answer where it is the angle of the same rotation
  // about some unit axis: 2 pi - theta (the angle in [0, pi], about -u), or a signed angle.
  // Compared by the rotation angle rho(x) in [0, pi] (rotation_angle).
  set_error(add("angle_range", "to_angle returns the angle in another range ([0, pi], the angle about -u, or signed)",
                is("to_angle"), always),
            [](const Case&, const auto&, const auto& got, const auto& want) -> std::optional<ScalarOf<decltype(got)>> {
              using std::abs;
              if (is_nan_of(got[0][0])) return got[0][0];
              return abs(rotation_angle(got[0][0]) - rotation_angle(want[0][0]));
            });
  // AXANG-4: the axis of AXANG-1 alone. Where theta > pi (w < 0) a library whose angles lie in
  // [0, pi] (Eigen's AngleAxis, nalgebra) returns -u, the axis of the same rotation by 2 pi - theta:
  // the axis of its angle_range. The identity has every unit axis (identity_axis).
  const auto pure_real_input = [](const Case& c) {
    return !c.inputs.empty() && c.inputs[0].size() >= 4 && c.inputs[0][0] == 0 && c.inputs[0][1] == 0 &&
           c.inputs[0][2] == 0;
  };
  set_error(add("identity_axis", "to_axis of the identity rotation (angle 0 or 2 pi) returns another unit axis", is("to_axis"),
                [pure_real_input](const AbiOp&, const Case& c, ref::Format) { return pure_real_input(c); }),
            [pure_real_input](const Case& c, const auto&, const auto& got,
                              const auto&) -> std::optional<ScalarOf<decltype(got)>> {
              if (!pure_real_input(c)) return std::nullopt;
              return axis_defect(got[0]);
            });
  const auto obtuse_input = [pure_real_input](const Case& c) {
    return !pure_real_input(c) && !c.inputs.empty() && c.inputs[0].size() >= 4 && c.inputs[0][3] <= 0;
  };
  // |got + want| (the axis -u against u), and a unit axis.
  set_error(add("angle_range", "to_axis returns -u where theta >= pi: the axis of the same rotation by 2 pi - theta in [0, pi]",
                is("to_axis"), [obtuse_input](const AbiOp&, const Case& c, ref::Format) { return obtuse_input(c); }),
            [obtuse_input](const Case& c, const auto&, const auto& got,
                           const auto& want) -> std::optional<ScalarOf<decltype(got)>> {
              using T = ScalarOf<decltype(got)>;
              using std::sqrt;
              if (!obtuse_input(c)) return std::nullopt;
              T d(0);
              for (int i = 0; i < 3; ++i) d += (got[0][i] + want[0][i]) * (got[0][i] + want[0][i]);
              return larger(T(sqrt(d)), axis_defect(got[0]));
            });

  // SQRT-1: -s is the other square root of q^ and the same rotation (as MAT-2's -q); q^ = -1 has
  // every unit pure quaternion as a square root (+z is the spec's choice, as LOG-2's).
  set_error(add("sign", "sqrt returns -s of the canonical s (w > 0): the other square root, the same rotation", is("sqrt"),
                always),
            [](const Case&, const auto&, const auto& got, const auto& want) -> std::optional<ScalarOf<decltype(got)>> {
              return rotation_error_of(got[0], quat_of(want[0]));
            });
  // SQRT-1 on a non-unit q (EDGE-5): the algebra's square root s with s^2 = q has |s| = sqrt|q|
  // (numpy-quaternion's np.sqrt, GLM's and PyGLM's sqrt, kingdon's sqrt()): the rotation root
  // scaled, a correct answer of the algebra. Measured as the rotation of s/|s| against the
  // reference (sign-free, as `sign`) and the norm relation | |s|^2 / |q| - 1 |.
  set_error(add("algebraic_root", "sqrt of a non-unit q returns the algebra's root s (s^2 = q, |s| = sqrt|q|)", is("sqrt"),
                always),
            [](const Case&, const auto& in, const auto& got, const auto& want) {
              return algebraic_root_error(in[0], got[0], want[0]);
            });
  // SQRT-1 where w < 0: q^ and -q^ are one rotation; a library of rotations (not of quaternions:
  // SciPy's Rotation ** 0.5, nalgebra's powf(0.5)) returns the rotation's principal root, the
  // root of -q^, half of its angle in [0, pi] (for -1, the identity). Measured as `sign`.
  set_error(add("principal_root", "sqrt returns the root of -q^ where w < 0: the rotation's principal square root (half its angle in [0, pi])",
                is("sqrt"), [](const AbiOp&, const Case& c, ref::Format) { return c.inputs[0][3] < 0; }),
            [](const Case& c, const auto& in, const auto& got, const auto&) -> std::optional<ScalarOf<decltype(got)>> {
              if (!(c.inputs[0][3] < 0)) return std::nullopt;
              const auto root = clause::SQRT_1_sqrt(-quat_of(in[0]));
              if (root.status != ref::Status::ok) return std::nullopt;
              return rotation_error_of(got[0], root.value);
            });
  const auto minus_one_input = [pure_real_input](const Case& c) { return pure_real_input(c) && c.inputs[0][3] < 0; };
  set_error(add("minus_one_axis", "sqrt of a negative real quaternion returns another unit pure quaternion", is("sqrt"),
                [minus_one_input](const AbiOp&, const Case& c, ref::Format) { return minus_one_input(c); }),
            [minus_one_input](const Case& c, const auto&, const auto& got,
                              const auto&) -> std::optional<ScalarOf<decltype(got)>> {
              if (!minus_one_input(c)) return std::nullopt;
              return minus_one_root_error(got[0]);
            });

  // LOG-1/LOG-2: every v with exp(v) = +-q and |v| <= pi is a logarithm of the rotation; the
  // principal branch (and +z for a negative real q) is the spec's choice (log_error).
  {
    AcceptableConvention& a = add("minus_one_axis", "log of a negative real quaternion returns pi times another unit axis",
                                  is("log"), {});
    set_answer_relevance(a, [](const auto& want) { return negative_real_log(want); });
    set_error(a, [](const Case&, const auto&, const auto& got, const auto& want) -> std::optional<ScalarOf<decltype(got)>> {
      using T = ScalarOf<decltype(got)>;
      // pi u' only: a log near 0 is the log of -q, shorter_arc's case.
      if (!negative_real_log(want) || norm_of(got[0], 0, 3) < pi_of<T>() / T(2)) return std::nullopt;
      return log_error(got, want);
    });
  }
  // A negative real q included: its log of -q is 0 (log(-1) = 0, the identity's log).
  {
    AcceptableConvention& a = add("shorter_arc", "log returns the logarithm of -q (|v| <= pi/2) where w <= 0: the same rotation",
                                  is("log"), {});
    set_answer_relevance(a, [](const auto& want) { return obtuse_log(want); });
    set_error(a, [](const Case&, const auto&, const auto& got, const auto& want) -> std::optional<ScalarOf<decltype(got)>> {
      using T = ScalarOf<decltype(got)>;
      if (!obtuse_log(want)) return std::nullopt;
      if (negative_real_log(want) && norm_of(got[0], 0, 3) >= pi_of<T>() / T(2)) return std::nullopt;  // pi u': minus_one_axis
      return log_error(got, want);
    });
  }

  // DQ-8: every xi' with DQ-9(xi') = +-sigma and |xi'_r| <= pi is a logarithm of the rigid motion;
  // at r = -1 (minus_one_axis) the axis is free up to exp(xi') = sigma, and where r_w <= 0 the log
  // of -sigma (shorter_arc) is the same motion. Measured as METRIC-7 of DQ-9(xi') against sigma
  // (dq_log_error).
  set_error(add("minus_one_axis", "dq_log of a dual quaternion whose real part is a negative real returns another log of it (|xi_r| = pi)",
                is("dq_log"), [minus_one_input](const AbiOp&, const Case& c, ref::Format) { return minus_one_input(c); }),
            [minus_one_input](const Case& c, const auto& in, const auto& got,
                              const auto&) -> std::optional<ScalarOf<decltype(got)>> {
              using T = ScalarOf<decltype(got)>;
              if (!minus_one_input(c) || norm_of(got[0], 0, 3) < pi_of<T>() / T(2)) return std::nullopt;
              return dq_log_error(in[0], got);
            });
  {
    AcceptableConvention& a = add("shorter_arc", "dq_log returns the logarithm of -sigma (|xi_r| <= pi/2) where r_w <= 0: the same rigid motion",
                                  is("dq_log"), {});
    set_answer_relevance(a, [](const auto& want) { return obtuse_log(want); });
    set_error(a, [minus_one_input](const Case& c, const auto& in, const auto& got,
                                   const auto& want) -> std::optional<ScalarOf<decltype(got)>> {
      using T = ScalarOf<decltype(got)>;
      if (!obtuse_log(want)) return std::nullopt;
      if (minus_one_input(c) && norm_of(got[0], 0, 3) >= pi_of<T>() / T(2)) return std::nullopt;  // pi u': minus_one_axis
      return dq_log_error(in[0], got);
    });
  }

  // EDGE-3: at a hemisphere tie (|a.b| within rounding of 0) both arcs have the same length; the
  // spec breaks the tie one way ("flip iff a.b < 0 strictly"), a library may break it the other.
  const auto pairwise = [](const AbiOp& op) { return op.name == "slerp" || op.name == "nlerp"; };
  all.push_back({"hemisphere_tie", "at a hemisphere tie (|a.b| <= 8 eps) the other hemisphere is taken", false,
                 hemisphere_tie_applies,
                 [](const AbiOp& op, const Case& c, ref::Format f) { return hemisphere_tie_at_stake(op, c, f); },
                 [pairwise](const AbiOp& op, const Case& c, const Values& got, const Values&,
                            ref::Format f) -> std::optional<Real> {
                   if (!all_finite(c)) return std::nullopt;
                   if (pairwise(op)) {
                     const Real d = normalised_dot(c.inputs[0], 0, c.inputs[1], 0);
                     if (!near_tie(d, f)) return std::nullopt;
                     // The other branch: b' = -(the spec's b').
                     const Quat other = hemisphere_tie_other_branch(op.name == "slerp", quat(c.inputs[0]),
                                                                    quat(c.inputs[1]), c.inputs[2][0],
                                                                    hemisphere_rule_flips_b(c));
                     return unit_rotation_error(got[0], other);
                   }
                   // Blends and ScLERP: the reference on the exactly tied influences negated.
                   const std::optional<Values> in = hemisphere_tie_flipped_inputs(op, c, f);
                   if (!in) return std::nullopt;
                   const ReferenceResult alt = op.reference(*in, c.k);
                   if (alt.status != ref::Status::ok) return std::nullopt;
                   return output_error(op, got, alt.outputs, c, f);
                 }});
  // SLERP-3: the endpoints are a and b' to the sign; -a at t = 0 or -b' at t = 1 is the same
  // rotation, a sign a library may choose (CQRlib's HLERP, pyquaternion), as it may inside.
  all.push_back({"endpoint_sign", "slerp returns -a at t = 0 or -b' at t = 1: the same rotation with the other sign", false,
                 is("slerp"),
                 [](const AbiOp&, const Case& c, ref::Format) {
                   return c.inputs.size() > 2 && !c.inputs[2].empty() && (c.inputs[2][0] == 0 || c.inputs[2][0] == 1);
                 },
                 [](const AbiOp& op, const Case& c, const Values& got, const Values& want, ref::Format) -> std::optional<Real> {
                   if (op.outputs[0].measure != Measure::signed_unit_rotation) return std::nullopt;  // SLERP-3 only
                   if (c.inputs.size() < 3 || c.inputs[2].empty() || (c.inputs[2][0] != 0 && c.inputs[2][0] != 1))
                     return std::nullopt;
                   return unit_rotation_error(got[0], quat(want[0]));
                 }});
  // Declared only: an interpolation documented as oriented (no hemisphere flip: glm::mix) goes
  // from a to b itself, the long arc where a.b < 0. Undefined at an exact antipode.
  all.push_back({"oriented", "the interpolation is oriented: from a to b itself, no hemisphere flip (declared)", true, pairwise,
                 [](const AbiOp&, const Case& c, ref::Format) {
                   return all_finite(c) && hemisphere_rule_flips_b(c);
                 },
                 [](const AbiOp& op, const Case& c, const Values& got, const Values&, ref::Format) -> std::optional<Real> {
                   if (!all_finite(c) || !hemisphere_rule_flips_b(c)) return std::nullopt;
                   const Quat a = unit(quat(c.inputs[0])), b = unit(quat(c.inputs[1]));
                   const Real t = c.inputs[2][0];
                   if (op.name == "slerp") {
                     if (ref::dot(a, b) <= Real(-1)) return std::nullopt;  // antipodes: no oriented arc
                     return unit_rotation_error(got[0], clause::detail::quaternion(clause::detail::rotor_interpolation(
                                                            clause::detail::rotor(a), clause::detail::rotor(b), t, false)));
                   }
                   // nlerp: the chord s = (1 - t) a + t b, defined unless s = 0. Near an antipode it is
                   // ill-conditioned: rounding the sum moves its direction by about u / |s|, so the
                   // error counts times min(1, |s|) (ACC-1 oriented; DQ-8 scales by its condition too).
                   const Quat s = lerp_chord(a, b, t);
                   const Real length = ref::norm(s);
                   if (length == 0) return std::nullopt;
                   return unit_rotation_error(got[0], ref::normalized(s)) * std::min(Real(1), length);
                 }});

  // EDGE-6: a zero quaternion, zero dual real part or zero axis has no rotation; the spec answers
  // DOMAIN_ERROR. A library without a status channel must answer something, and two answers are
  // defined, deterministic and documented practice (Eigen's inverse() "returns an invalid result
  // to flag the error": zero; three.js, Babylon.js, Unity: the identity): ACCEPTABLE, never a
  // partly-NaN or arbitrary finite output.
  all.push_back({"zero_sentinel",
                 "a zero input (quaternion, dual real part or axis) gives the all-zero output or exactly the identity "
                 "rotation's output instead of DOMAIN_ERROR",
                 false,
                 [](const AbiOp& op) { return has_stride(op, 4) || has_stride(op, 8) || op.name == "from_axis_angle" ||
                                              op.name == "rotate_about_axis"; },
                 [](const AbiOp& op, const Case& c, ref::Format f) {
                   return robust_clause_of(op, c, f) == "EDGE-6" && identity_substituted(op, c).has_value();
                 },
                 [](const AbiOp& op, const Case& c, const Values& got, const Values&, ref::Format f) -> std::optional<Real> {
                   if (robust_clause_of(op, c, f) != "EDGE-6") return std::nullopt;
                   if (every_output_zero(got)) return Real(0);
                   const std::optional<Case> id = identity_substituted(op, c);
                   if (!id) return std::nullopt;
                   // The identity's output as any correct library may give it (identity_axis:
                   // Eigen's axis (1, 0, 0) for angle 0).
                   return error_as_answer_to(op, *id, got, f);
                 },
                 true});
  // EDGE-7: a library that checks nothing answers a non-finite input with whatever IEEE arithmetic
  // carries into the result, rarely NaN in every component (normalize((0, Inf, 0, 1)) = (0, NaN,
  // 0, 0): Inf/Inf and 0/Inf). The caller's finiteness test still finds it, so that answer is
  // ACCEPTABLE; so is the all-zero flag where zero is no answer of the op (Eigen's inverse() of a
  // NaN quaternion: "an invalid result to flag the error"). Any other finite answer hides the
  // input's NaN or infinity and stays a FAIL.
  AcceptableConvention propagation{"nonfinite_propagation",
                 "a non-finite input gives status OK with at least one output component NaN or infinite (IEEE "
                 "propagation), or the all-zero output of an op that never answers zero, instead of DOMAIN_ERROR",
                 false, [](const AbiOp&) { return true; },
                 [](const AbiOp&, const Case& c, ref::Format) { return !all_finite(c); },
                 [](const AbiOp& op, const Case& c, const Values& got, const Values&, ref::Format) -> std::optional<Real> {
                   if (all_finite(c)) return std::nullopt;
                   if (some_output_nonfinite(got) || (zero_is_no_answer(op) && every_output_zero(got))) return Real(0);
                   return std::nullopt;
                 },
                 true};
  // Exact (ACC-1: a rule, not a measurement), whatever class the op's numbers are judged in (the
  // fuzzers judge an op in its numeric class, whose formula bars are NaN for a NaN matrix).
  propagation.bars = ref::Bars{0, 0};
  all.push_back(std::move(propagation));
  // EDGE-7 with infinities only: a quaternion whose infinite components grow alike tends to a
  // rotation, and a library's IEEE arithmetic often lands on that rotation's answer (Eigen's
  // AngleAxis of (0, Inf, 0, 1) is pi: 2 atan2(Inf, 1)). The limit is a correct answer, not one a
  // maintainer would call a defect; judged in class eps16 (ACC-1), as the ordinary ops are.
  {
    AcceptableConvention a{"nonfinite_limit",
                           "a quaternion with infinite components gives the answer for the rotation it tends to as they grow "
                           "alike (each infinite component's sign, normalised), instead of DOMAIN_ERROR",
                           false, [](const AbiOp& op) { return has_stride(op, 4); },
                           [](const AbiOp& op, const Case& c, ref::Format) { return infinity_limit(op, c).has_value(); },
                           [](const AbiOp& op, const Case& c, const Values& got, const Values&, ref::Format f) -> std::optional<Real> {
                             if (some_output_nonfinite(got)) return std::nullopt;  // nonfinite_propagation's case
                             const std::optional<Case> lim = infinity_limit(op, c);
                             if (!lim) return std::nullopt;
                             return error_as_answer_to(op, *lim, got, f);
                           },
                           true};
    a.bars = kLimitBars;
    all.push_back(std::move(a));
  }
  // EDGE-7 where the answer does not depend on the non-finite components: the axis v/|v| is the
  // same for every w, so CQRlib's axis of (x, y, z, NaN) is the answer for any value the NaN could
  // have stood for. IEEE 754 (9.2.1) answers so too: hypot(Inf, NaN) = Inf, pow(NaN, 0) = 1. Checked
  // by putting several finite values in their place; an output that is the answer for all of
  // them is ACCEPTABLE (class eps16, as nonfinite_limit), one that depends on them stays a FAIL.
  {
    AcceptableConvention a{"nonfinite_irrelevant",
                           "a non-finite input gives the op's answer for every finite value put in place of its non-finite "
                           "components (the answer does not depend on them), instead of DOMAIN_ERROR",
                           false, [](const AbiOp&) { return true; },
                           [](const AbiOp&, const Case& c, ref::Format) { return !all_finite(c); },
                           [](const AbiOp& op, const Case& c, const Values& got, const Values&, ref::Format f) -> std::optional<Real> {
                             if (all_finite(c) || some_output_nonfinite(got)) return std::nullopt;
                             Real worst(0);
                             int answered = 0;
                             for (const double v : {0.0, 1.0, -1.0, 2.0, -0.5}) {
                               Case sub = c;
                               for (auto& arr : sub.inputs)
                                 for (Real& x : arr)
                                   if (!mpfr::isfinite(x)) x = Real(v);
                               const std::optional<Real> e = error_as_answer_to(op, sub, got, f);
                               if (!e) continue;  // outside the domain for this value (a zero quaternion)
                               ++answered;
                               if (mpfr::isnan(*e)) return std::nullopt;
                               worst = std::max(worst, *e);
                             }
                             if (answered < 2) return std::nullopt;
                             return worst;
                           },
                           true};
    a.bars = kLimitBars;
    all.push_back(std::move(a));
  }
  // EDGE-7 on one output of a combined call: a library without an angle-only (axis-only) query
  // gives its users the angle (axis) as one output of the call its to_axis_angle makes (gl-matrix's
  // getAxisAngle returns 2 acos(w) and writes the axis). A NaN in x, y, z leaves that angle finite
  // and reaches the axis: judged alone, the half hides what the whole call shows. Declared only
  // (DECL-1 requires to_axis_angle supported, where the whole call is judged on the same kind
  // of input, so hiding the NaN from both outputs still FAILs there).
  {
    AcceptableConvention a{"output_of_to_axis_angle",
                           "a non-finite input gives status OK with a finite output of an op that is one output of the call "
                           "to_axis_angle makes (declared; that call is judged whole under to_axis_angle)",
                           true, [](const AbiOp& op) { return op.name == "to_angle" || op.name == "to_axis"; },
                           [](const AbiOp&, const Case& c, ref::Format) { return !all_finite(c); },
                           [](const AbiOp&, const Case& c, const Values&, const Values&, ref::Format) -> std::optional<Real> {
                             if (all_finite(c)) return std::nullopt;
                             return Real(0);
                           },
                           true};
    a.bars = ref::Bars{0, 0};
    all.push_back(std::move(a));
  }
  // COMPOSE-1 and DQ-2 are defined on the unnormalised input: with a zero factor (real part) the
  // product of the algebra exists, and a general quaternion library returns it.
  all.push_back({"algebraic_product",
                 "compose with a zero factor (dual real part) returns the exact product of the algebra instead of DOMAIN_ERROR",
                 false, [](const AbiOp& op) { return op.name == "compose" || op.name == "dq_compose"; },
                 [](const AbiOp& op, const Case& c, ref::Format f) { return robust_clause_of(op, c, f) == "EDGE-6"; },
                 [](const AbiOp& op, const Case& c, const Values& got, const Values&, ref::Format f) -> std::optional<Real> {
                   if (robust_clause_of(op, c, f) != "EDGE-6") return std::nullopt;
                   const std::vector<Real> want = algebraic_product(op, c);
                   Real worst(0), size(0);
                   for (std::size_t i = 0; i < want.size(); ++i) {
                     worst = std::max(worst, Real(abs(got[0][i] - want[i])));
                     size = std::max(size, Real(abs(want[i])));
                   }
                   if (mpfr::isnan(worst)) return worst;
                   if (size == 0) return worst == 0 ? Real(0) : Real("inf");
                   return worst / size;
                 },
                 true});
  return all;
}

}  // namespace

Declarations declarations_of(const rc_impl& table) {
  Declarations d;
  if (table.abi_version < 2) return d;
  for (int i = 0; table.preconditions && table.preconditions[i]; ++i) d.preconditions.insert(table.preconditions[i]);
  for (int i = 0; table.conventions && table.conventions[i]; ++i) d.conventions.insert(table.conventions[i]);
  return d;
}

const std::vector<Precondition>& preconditions() {
  static const std::vector<Precondition> all = build_preconditions();
  return all;
}

const Precondition* find_precondition(const std::string& id) {
  for (const Precondition& p : preconditions())
    if (p.id == id) return &p;
  return nullptr;
}

const Precondition* violated_precondition(const Declarations& d, const AbiOp& op, const Case& c, ref::Format f) {
  if (d.preconditions.empty()) return nullptr;
  for (const Precondition& p : preconditions())
    if (d.has_precondition(op.name, p.id) && p.applies(op) && !p.holds(op, c, f)) return &p;
  return nullptr;
}

std::string declaration_problem(const Declarations& d, const std::function<bool(const std::string& op)>& supported) {
  // "op:id": the op's name, its ABI op (nullptr for "*", every op the id applies to, or for an
  // unknown name) and the id.
  struct Parsed {
    std::string name;
    const AbiOp* op;
    std::string id;
  };
  const auto parse = [](const std::string& decl) {
    const std::size_t colon = decl.find(':');
    const std::string name = decl.substr(0, colon);
    return Parsed{name, name == "*" ? nullptr : find_abi_op(name), decl.substr(colon + 1)};
  };
  for (const std::string& decl : d.preconditions) {
    const auto [name, op, id] = parse(decl);
    const Precondition* p = find_precondition(id);
    if (p == nullptr) return "precondition \"" + decl + "\": no DECL-1 precondition \"" + id + "\"";
    if (name != "*" && op == nullptr) return "precondition \"" + decl + "\": no ABI op \"" + name + "\"";
    if (op != nullptr && !p->applies(*op)) return "precondition \"" + decl + "\": " + id + " does not apply to " + name;
  }
  for (const std::string& decl : d.conventions) {
    const auto [name, op, id] = parse(decl);
    bool known = false, applies = false;
    for (const AcceptableConvention& a : acceptable_conventions())
      if (a.id == id) {
        known = true;
        applies = applies || op == nullptr || a.applies(*op);
      }
    if (!known) return "convention \"" + decl + "\": no ACC-1 convention \"" + id + "\"";
    if (name != "*" && op == nullptr) return "convention \"" + decl + "\": no ABI op \"" + name + "\"";
    if (!applies) return "convention \"" + decl + "\": " + id + " does not apply to " + name;
    // The combined call is judged whole under to_axis_angle: without it, nothing would be.
    if (id == "output_of_to_axis_angle" && !supported("to_axis_angle"))
      return "convention \"" + decl + "\": the table does not support to_axis_angle, the call it names";
  }
  return {};
}

const std::vector<AcceptableConvention>& acceptable_conventions() {
  static const std::vector<AcceptableConvention> all = build_conventions();
  return all;
}

namespace {

std::optional<Real> error_as_answer_to(const AbiOp& op, const Case& sub, const Values& got, ref::Format f) {
  const ReferenceResult r = op.reference(sub.inputs, sub.k);
  if (r.status != ref::Status::ok) return std::nullopt;
  Real e = output_error(op, got, r.outputs, sub, f);
  for (const AcceptableConvention& a : acceptable_conventions())
    if (!a.outside_domain && !a.declared_only && a.applies(op) && a.relevant(op, sub, r.outputs, f))
      if (const std::optional<Real> alt = a.error(op, sub, got, r.outputs, f); alt && *alt < e) e = *alt;
  return e;
}

}  // namespace

std::vector<std::string> acceptable_for_case(const AbiOp& op, const Case& c, ref::Format f) {
  std::vector<std::string> ids;
  const ReferenceResult want = op.reference(c.inputs, c.k);
  const bool outside = want.status != ref::Status::ok;
  for (const AcceptableConvention& a : acceptable_conventions())
    if (a.outside_domain == outside && a.applies(op) && a.relevant(op, c, want.outputs, f))
      ids.push_back(a.id);
  return ids;
}

std::optional<Values> hemisphere_tie_flipped_inputs(const AbiOp& op, const Case& c, ref::Format f) {
  if (!all_finite(c) || op.name == "slerp" || op.name == "nlerp") return std::nullopt;
  // The other side of an exact tie (a dot of -0 does not flip).
  Values in = c.inputs;
  if (op.name == "dq_sclerp") {
    if (normalised_dot(c.inputs[0], 0, c.inputs[1], 0) != 0) return std::nullopt;
    for (Real& x : in[1]) x = -x;
    return in;
  }
  const std::size_t wa = input_index(op, "w");
  const int s = op.name == "dq_blend" ? 8 : 4;
  bool any = false;
  for (std::size_t i : tied_influences(c, 0, wa, s, f)) {
    const long p = pivot_of(c.inputs[wa]);
    std::vector<Real> reals;
    for (std::size_t j = 0; j < 4; ++j) reals.push_back(c.inputs[0][i * s + j]);
    for (std::size_t j = 0; j < 4; ++j) reals.push_back(c.inputs[0][std::size_t(p) * s + j]);
    if (normalised_dot(reals, 0, reals, 1) != 0) continue;
    for (int j = 0; j < s; ++j) in[0][i * s + j] = -in[0][i * s + j];
    any = true;
  }
  if (!any) return std::nullopt;
  return in;
}

bool hemisphere_rule_flips_b(const Case& c) {
  return ref::hemisphere_sign(quat(c.inputs[0]), quat(c.inputs[1])) < 0;
}

bool hemisphere_tie_applies(const AbiOp& op) {
  return op.name == "slerp" || op.name == "nlerp" || op.name == "dq_sclerp" || op.name == "blend_qlb" ||
         op.name == "blend_log" || op.name == "dq_blend" || op.name == "skin_dual_quaternion";
}

bool hemisphere_tie_at_stake(const AbiOp& op, const Case& c, ref::Format f) {
  if (!hemisphere_tie_applies(op) || !all_finite(c)) return false;
  if (op.name == "slerp" || op.name == "nlerp" || op.name == "dq_sclerp")
    return near_tie(normalised_dot(c.inputs[0], 0, c.inputs[1], 0), f);
  const std::size_t wa = input_index(op, "w");
  return !tied_influences(c, 0, wa, op.name == "dq_blend" ? 8 : 4, f).empty();
}

}  // namespace rotorcert::engine
