// The shared, CORRECT toolkit of the mutants: each mutant file writes the one faulty operation
// it exists for (and nothing else), using these helpers for everything that is not the bug.
// Quaternions are the ABI's [x, y, z, w], dual quaternions [real xyzw, dual xyzw].
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <span>

#include <rotorcert/impl_table.hpp>

namespace mutant {

namespace rci = rotorcert::impl;
using rci::Status;
template <class S> using Q = rci::Quat<S>;
template <class S> using V = rci::Vec3<S>;
template <class S> using D = rci::DualQuat<S>;
template <class S> using M = rci::Mat3<S>;

template <class S> bool finite(const Q<S>& q) {
  return std::isfinite(q[0]) && std::isfinite(q[1]) && std::isfinite(q[2]) && std::isfinite(q[3]);
}
template <class S> bool finite(const V<S>& v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }
template <class S> bool valid(const Q<S>& q) { return finite(q) && !(q[0] == 0 && q[1] == 0 && q[2] == 0 && q[3] == 0); }
template <class S> bool valid_weights(std::span<const S> w) {
  if (w.empty()) return false;
  S sum = 0;
  for (S x : w) {
    if (!std::isfinite(x) || x < 0) return false;
    sum += x;
  }
  return sum > 0;
}

/// Hamilton product (QUAT-1).
template <class S> Q<S> mul(const Q<S>& a, const Q<S>& b) {
  return {a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1], a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0],
          a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3], a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2]};
}
template <class S> Q<S> conj(const Q<S>& q) { return {-q[0], -q[1], -q[2], q[3]}; }
template <class S> Q<S> neg(const Q<S>& q) { return {-q[0], -q[1], -q[2], -q[3]}; }
template <class S> S dot(const Q<S>& a, const Q<S>& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]; }
template <class S> Q<S> scale(S k, const Q<S>& q) { return {k * q[0], k * q[1], k * q[2], k * q[3]}; }
template <class S> Q<S> add(const Q<S>& a, const Q<S>& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2], a[3] + b[3]}; }

/// ilogb(m), or 0 where m is 0 or NaN: ilogb is then INT_MIN, and -INT_MIN overflows (UB). The
/// callers' results for such inputs are unchanged (0/0 and NaN propagate to NaN either way).
template <class S> int scale_exponent(S m) { return m == 0 || std::isnan(m) ? 0 : std::ilogb(m); }

/// q/|q| after an exact power-of-two rescaling (no overflow or underflow).
template <class S> Q<S> normalized(const Q<S>& q) {
  const S m = std::max({std::abs(q[0]), std::abs(q[1]), std::abs(q[2]), std::abs(q[3])});
  const int e = scale_exponent(m);
  Q<S> r;
  for (int i = 0; i < 4; ++i) r[i] = std::scalbn(q[i], -e);
  const S n = std::sqrt(dot(r, r));
  for (S& c : r) c /= n;
  return r;
}

/// v + w t + u x t with t = 2 u x v, for unit q.
template <class S> V<S> rotate(const Q<S>& q, const V<S>& v) {
  const V<S> t{S(2) * (q[1] * v[2] - q[2] * v[1]), S(2) * (q[2] * v[0] - q[0] * v[2]), S(2) * (q[0] * v[1] - q[1] * v[0])};
  return {v[0] + q[3] * t[0] + (q[1] * t[2] - q[2] * t[1]), v[1] + q[3] * t[1] + (q[2] * t[0] - q[0] * t[2]),
          v[2] + q[3] * t[2] + (q[0] * t[1] - q[1] * t[0])};
}

/// LOG-1/LOG-2 of q/|q|: atan2(|v|, w) v/|v| (series for tiny |v|/w), log(-1) = (0, 0, pi).
template <class S> V<S> qlog(const Q<S>& q) {
  const S n = std::hypot(q[0], q[1], q[2]);
  if (n == 0) return q[3] > 0 ? V<S>{0, 0, 0} : V<S>{0, 0, std::numbers::pi_v<S>};
  const S f = std::atan2(n, q[3]) / n;
  return {f * q[0], f * q[1], f * q[2]};
}

/// EXP-1: (sin|v| v/|v|, cos|v|); exp(0) = 1 exactly.
template <class S> Q<S> qexp(const V<S>& v) {
  const S n = std::hypot(v[0], v[1], v[2]);
  if (n == 0) return {0, 0, 0, 1};
  const S f = std::sin(n) / n;
  return {f * v[0], f * v[1], f * v[2], std::cos(n)};
}

/// SLERP-1 for unit a, b with the hemisphere decision `flip` taken by the caller: a exp(t log(a* b')).
template <class S> Q<S> slerp_unit(const Q<S>& a, Q<S> b, S t, bool flip) {
  if (flip) b = neg(b);
  const V<S> l = qlog(mul(conj(a), b));
  return mul(a, qexp(V<S>{t * l[0], t * l[1], t * l[2]}));
}

/// MAT-1, column-major, of unit q.
template <class S> M<S> to_matrix(const Q<S>& q) {
  const S x = q[0], y = q[1], z = q[2], w = q[3];
  return {1 - 2 * (y * y + z * z), 2 * (x * y + w * z),     2 * (x * z - w * y),
          2 * (x * y - w * z),     1 - 2 * (x * x + z * z), 2 * (y * z + w * x),
          2 * (x * z + w * y),     2 * (y * z - w * x),     1 - 2 * (x * x + y * y)};
}

// ---- dual quaternions ----------------------------------------------------------------------------

template <class S> Q<S> real(const D<S>& d) { return {d[0], d[1], d[2], d[3]}; }
template <class S> Q<S> dual(const D<S>& d) { return {d[4], d[5], d[6], d[7]}; }
template <class S> D<S> make(const Q<S>& r, const Q<S>& d) { return {r[0], r[1], r[2], r[3], d[0], d[1], d[2], d[3]}; }
template <class S> bool valid(const D<S>& d) {
  return valid(real(d)) && finite(dual(d));
}
/// DQ-2.
template <class S> D<S> dmul(const D<S>& a, const D<S>& b) {
  return make(mul(real(a), real(b)), add(mul(real(a), dual(b)), mul(dual(a), real(b))));
}
/// DQ-4: (r/|r|, d/|r| - (r.d/|r|^3) r), after an exact common power-of-two rescaling of both parts.
template <class S> D<S> dnormalized(const D<S>& s) {
  const Q<S> r0 = real(s);
  const int e = scale_exponent(std::max({std::abs(r0[0]), std::abs(r0[1]), std::abs(r0[2]), std::abs(r0[3])}));
  Q<S> r, d;
  for (int i = 0; i < 4; ++i) r[i] = std::scalbn(s[i], -e), d[i] = std::scalbn(s[i + 4], -e);
  const S n = std::sqrt(dot(r, r));
  const Q<S> ru = scale(S(1) / n, r);
  return make(ru, scale(S(1) / n, add(d, scale(-dot(ru, d), ru))));
}
/// t = 2 vec(d r*) of a unit dual quaternion.
template <class S> V<S> translation(const D<S>& u) {
  const Q<S> t = mul(dual(u), conj(real(u)));
  return {S(2) * t[0], S(2) * t[1], S(2) * t[2]};
}
/// DQ-1: (r, 1/2 t r) for unit r.
template <class S> D<S> from_rt(const Q<S>& r, const V<S>& t) {
  return make(r, scale(S(0.5), mul(Q<S>{t[0], t[1], t[2], 0}, r)));
}
/// DQ-3 for a unit dual quaternion.
template <class S> V<S> apply_point(const D<S>& u, const V<S>& p) {
  const V<S> r = rotate(real(u), p), t = translation(u);
  return {r[0] + t[0], r[1] + t[1], r[2] + t[2]};
}

}  // namespace mutant

/// The metadata every mutant table carries (they claim nothing: the test names the clauses).
#define MUTANT_META(id, what)                                                 \
  static constexpr const char* name = "mutant_" #id;                          \
  static constexpr const char* version = "0";                                 \
  static constexpr const char* description = what;                            \
  static constexpr std::uint32_t levels = 0;                                  \
  static constexpr const char* const clauses[] = {nullptr};
