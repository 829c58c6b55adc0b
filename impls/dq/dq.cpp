// dq: dual quaternions for skinning, written here from the spec's formulas (no library).
//
// Data: the ABI arrays themselves (impl.hpp): quaternion [x, y, z, w], vector [x, y, z], dual
// quaternion [real xyzw, dual xyzw] with sigma = real + eps dual, dual = 1/2 t real (DQ-1).
// Inside, small structs with named fields (Quat, Vec, Dual) and short scalar functions in the
// format under test (float or double), in the manner of ozz-animation: no heap, no tables.
//
// Defined outcomes (EDGE-5 .. EDGE-9): a non-finite component anywhere, a zero real part (or a
// zero rotation), or bad weights give DOMAIN_ERROR (the adaptor writes the NaNs). A non-unit
// rotation stands for q/|q|, a non-unit dual quaternion for its DQ-4 normalisation; every
// normalisation first scales by a power of two near the largest |component| (exact), so that
// subnormal and near-overflow inputs keep full accuracy; where the unscaled sum of squares shows
// that no scaling is needed (runtime/ordinary_range.hpp), the same formula runs unscaled.
//
// Batches: the ordinary elements of dq_from_rotation_translation, dq_compose, dq_normalize,
// dq_apply_point, dq_blend, skin_dual_quaternion, skin_linear and rotate_about_axis
// (dlb_lanes.hpp), and of normalize, compose, inverse and apply_vector (the QuatLanes below), run
// in SIMD lanes with the element function's bits; every other element takes the checked element
// function (dq_blend's first tries the inline dlb_ordinary()).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <type_traits>

#include <rotorcert/runtime/exact_sign.hpp>
#include <rotorcert/runtime/lane_batch.hpp>
#include <rotorcert/runtime/lane_blocks.hpp>
#include <rotorcert/runtime/ordinary_range.hpp>
#include <rotorcert/runtime/perpendicular_part.hpp>
#include <rotorcert/runtime/scalar_real_part_log.hpp>
#include <rotorcert/runtime/target_clones.hpp>
#include <rotorcert/impl_table.hpp>

#include "dlb_lanes.hpp"

namespace {

namespace rci = rotorcert::impl;
namespace runtime = rotorcert::runtime;
using rci::largest_weight;
using rci::Status;

// ---- small value types ------------------------------------------------------------------------

template <class S> struct Vec { S x, y, z; };
template <class S> struct Quat { S x, y, z, w; };   // q = w + x i + y j + z k
template <class S> struct Dual { Quat<S> r, d; };   // sigma = r + eps d

template <class S> Quat<S> load(const rci::Quat<S>& a) { return {a[0], a[1], a[2], a[3]}; }
template <class S> Vec<S> load(const rci::Vec3<S>& a) { return {a[0], a[1], a[2]}; }
template <class S> Dual<S> load(const rci::DualQuat<S>& a) {
  return {{a[0], a[1], a[2], a[3]}, {a[4], a[5], a[6], a[7]}};
}
template <class S> rci::Quat<S> store(const Quat<S>& q) { return {q.x, q.y, q.z, q.w}; }
template <class S> rci::Vec3<S> store(const Vec<S>& v) { return {v.x, v.y, v.z}; }
template <class S> rci::DualQuat<S> store(const Dual<S>& s) {
  return {s.r.x, s.r.y, s.r.z, s.r.w, s.d.x, s.d.y, s.d.z, s.d.w};
}

template <class S> Vec<S> operator+(const Vec<S>& a, const Vec<S>& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
template <class S> Vec<S> operator-(const Vec<S>& a, const Vec<S>& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
template <class S> Vec<S> operator*(S k, const Vec<S>& a) { return {k * a.x, k * a.y, k * a.z}; }
template <class S> S dot(const Vec<S>& a, const Vec<S>& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
template <class S> Vec<S> cross(const Vec<S>& a, const Vec<S>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

template <class S> Vec<S> vec(const Quat<S>& q) { return {q.x, q.y, q.z}; }
template <class S> Quat<S> operator+(const Quat<S>& a, const Quat<S>& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w};
}
template <class S> Quat<S> operator-(const Quat<S>& a, const Quat<S>& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z, a.w - b.w};
}
template <class S> Quat<S> operator-(const Quat<S>& a) { return {-a.x, -a.y, -a.z, -a.w}; }
template <class S> Quat<S> operator*(S k, const Quat<S>& a) { return {k * a.x, k * a.y, k * a.z, k * a.w}; }
template <class S> Quat<S> operator/(const Quat<S>& a, S k) { return {a.x / k, a.y / k, a.z / k, a.w / k}; }
template <class S> S dot(const Quat<S>& a, const Quat<S>& b) { return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w; }
template <class S> Quat<S> conj(const Quat<S>& q) { return {-q.x, -q.y, -q.z, q.w}; }

/// Hamilton product (QUAT-1): ij = k.
template <class S> Quat<S> operator*(const Quat<S>& a, const Quat<S>& b) {
  return {a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
          a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w,
          a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z};
}

/// DQ-2: (a_r b_r) + eps (a_r b_d + a_d b_r); apply b first.
template <class S> Dual<S> operator*(const Dual<S>& a, const Dual<S>& b) { return {a.r * b.r, a.r * b.d + a.d * b.r}; }

// ---- input checks -------------------------------------------------------------------------------

template <class S> bool finite(S x) { return std::isfinite(x); }
template <class S> bool finite(const Vec<S>& v) { return finite(v.x) && finite(v.y) && finite(v.z); }
template <class S> bool finite(const Quat<S>& q) { return finite(q.x) && finite(q.y) && finite(q.z) && finite(q.w); }
template <class S> bool is_zero(const Quat<S>& q) { return q.x == 0 && q.y == 0 && q.z == 0 && q.w == 0; }
/// A usable rotation: finite and nonzero (EDGE-6, EDGE-7).
template <class S> bool valid(const Quat<S>& q) { return finite(q) && !is_zero(q); }
/// A usable dual quaternion: every component finite, the real part nonzero.
template <class S> bool valid(const Dual<S>& s) { return valid(s.r) && finite(s.d); }

// ---- quaternions ----------------------------------------------------------------------------------

/// Binary exponent of the largest |component|: q scaled by 2^-e has its largest component in
/// [1, 2), exactly (a power of two), so squares neither overflow nor underflow.
template <class S> int scale_exponent(const Quat<S>& q) {
  using std::abs;
  return std::ilogb(std::max({abs(q.x), abs(q.y), abs(q.z), abs(q.w)}));
}
template <class S> Quat<S> scaled(const Quat<S>& q, int e) {
  return {std::scalbn(q.x, e), std::scalbn(q.y, e), std::scalbn(q.z, e), std::scalbn(q.w, e)};
}

/// The sign of a.b for the hemisphere rules, from the inputs as given (separately normalised
/// copies would turn an exact 0 into +-tiny).
template <class S> int hemisphere_dot(const Quat<S>& a, const Quat<S>& b) {
  return runtime::hemisphere_sign<S>({a.x, a.y, a.z, a.w}, {b.x, b.y, b.z, b.w});
}

/// NORM-1: q/|q| for finite nonzero q.
template <class S> Quat<S> normalized(const Quat<S>& q) {
  const S n2 = dot(q, q);
  if (runtime::is_ordinary_square(n2)) return q / std::sqrt(n2);
  const Quat<S> s = scaled(q, -scale_exponent(q));
  return s / std::sqrt(dot(s, s));
}

/// R v ~R for unit q in the form v + w t + u x t with t = 2 u x v (15 multiplies; no matrix).
template <class S> Vec<S> rotate(const Quat<S>& q, const Vec<S>& v) {
  const Vec<S> u = vec(q);
  const Vec<S> t = S(2) * cross(u, v);
  return v + q.w * t + cross(u, t);
}

// ---- dual quaternions ------------------------------------------------------------------------------

/// Both parts of s scaled by the exact power of two that keeps |r|^2 clear of overflow and
/// underflow (the normalisations below are invariant under a common scale), or s itself where
/// both parts are ordinary (runtime/ordinary_range.hpp: |r|^2 ordinary, and |d|^2 too or d = 0,
/// so that d / |r| and r'.d stay far from overflow).
template <class S> Dual<S> safely_scaled(const Dual<S>& s) {
  const S d2 = dot(s.d, s.d);
  if (runtime::is_ordinary_square(dot(s.r, s.r)) && (d2 == 0 || runtime::is_ordinary_square(d2))) return s;
  const int e = -scale_exponent(s.r);
  return {scaled(s.r, e), scaled(s.d, e)};
}

/// The dual part d' of DQ-4 without the subtraction, out of line (rare) so that the common path
/// of normalized() stays small enough to inline.
template <class S> [[gnu::noinline, gnu::cold]] Quat<S> perpendicular_dual_part(const Dual<S>& x, S n2) {
  const std::array<S, 4> p = runtime::perpendicular_times_norm2<S>({x.r.x, x.r.y, x.r.z, x.r.w}, {x.d.x, x.d.y, x.d.z, x.d.w});
  const S f = S(1) / (n2 * std::sqrt(n2));
  return {f * p[0], f * p[1], f * p[2], f * p[3]};
}

/// DQ-4 below on s whose r2 = |r|^2 and d2 = |d|^2 are ordinary (d2 may be 0), where safely_scaled()
/// is the identity, and whose projection does not cancel: the common case, inline, for the batch
/// fast paths. Returns false, having written nothing, elsewhere.
template <class S>
[[gnu::always_inline]] inline bool normalized_ordinary(const Dual<S>& s, S r2, S d2, Dual<S>& out) {
  if (!runtime::is_ordinary_square(r2) || !(d2 == 0 || runtime::is_ordinary_square(d2))) return false;
  const S n = std::sqrt(r2);
  const Quat<S> ru = s.r / n;
  const S along = dot(ru, s.d);
  if (runtime::projection_cancels(along, d2)) return false;
  out = {ru, (s.d - along * ru) / n};
  return true;
}

/// DQ-4: r' = r/|r|, d' = d/|r| - (r.d/|r|^3) r, written as d' = (d - (r'.d) r')/|r| on the
/// safely scaled parts; where that subtraction would cancel (d mostly parallel to r), the form
/// without it (runtime/perpendicular_part.hpp).
template <class S> Dual<S> normalized(const Dual<S>& s) {
  if (Dual<S> u; normalized_ordinary(s, dot(s.r, s.r), dot(s.d, s.d), u)) return u;
  const Dual<S> x = safely_scaled(s);
  const S n2 = dot(x.r, x.r), n = std::sqrt(n2);
  const Quat<S> ru = x.r / n;
  const S along = dot(ru, x.d);
  if (runtime::projection_cancels(along, dot(x.d, x.d))) [[unlikely]]
    return {ru, perpendicular_dual_part(x, n2)};
  return {ru, (x.d - along * ru) / n};
}

/// DQ-1: (q_r, 1/2 t q_r) for a unit q_r. With t pure, t q_r = (-t.v, w t + t x v).
template <class S> Dual<S> from_rotation_translation(const Quat<S>& ru, const Vec<S>& t) {
  const Vec<S> v = vec(ru);
  const Vec<S> dv = S(0.5) * (ru.w * t + cross(t, v));
  return {ru, {dv.x, dv.y, dv.z, S(-0.5) * dot(t, v)}};
}

/// t = 2 vec(d r*) of a unit dual quaternion: 2 (r_w d_v - d_w r_v + r_v x d_v). The part of d
/// along r only feeds the scalar part, so d need not be orthogonal to r.
template <class S> Vec<S> translation(const Dual<S>& u) {
  const Vec<S> rv = vec(u.r), dv = vec(u.d);
  return S(2) * (u.r.w * dv - u.d.w * rv + cross(rv, dv));
}

/// DQ-3 the fast way: p' = R p + t, with r and d divided by |r| (no projection needed: see
/// translation()).
template <class S> Vec<S> apply_point(const Dual<S>& s, const Vec<S>& p) {
  const Dual<S> x = safely_scaled(s);
  const S n = std::sqrt(dot(x.r, x.r));
  const Dual<S> u{x.r / n, x.d / n};
  return rotate(u.r, p) + translation(u);
}

/// Screw power u^t = exp(t log u) of a unit dual quaternion with real part w >= 0 (after the
/// hemisphere flip), by its screw parameters (Kavan et al. 2008):
///   u = cos(h^) + sin(h^) (l + eps m),  h^ = h + eps h_d  (half dual angle),
///   u^t = (cos th, sin th l) + eps (-t h_d sin th, sin(th) m + t h_d cos(th) l).
/// Reading off u = (w, s l) + eps (d_w, d_v): s = sin h, h = atan2(s, w), and (with r.d = 0)
///   h_d = w (l.d_v) - s d_w,   s m = d_v - h_d w l,
/// so the dual vector is a d_v + h_d (t cos th - a w) l with a = sin(th)/s. The bracket is
/// O(h^2) and loses relative accuracy as h -> 0, but it is multiplied by h_d l only: the
/// absolute error stays ~eps |h_d|, and no quotient is 0/0 while s > 0. s = 0 is a pure
/// translation: u^t = 1 + eps t d (linear in t).
template <class S> Dual<S> screw_power(const Dual<S>& u, S t) {
  const Vec<S> v = vec(u.r), dv = vec(u.d);
  const S s = std::sqrt(dot(v, v));
  if (s == 0) return {{0, 0, 0, 1}, t * u.d};
  const S w = u.r.w;
  const S h = std::atan2(s, w);
  const Vec<S> l = (S(1) / s) * v;
  const S sn = std::sin(t * h), cs = std::cos(t * h);
  const S a = sn / s;
  const S hd = w * dot(l, dv) - s * u.d.w;
  const Vec<S> rv = sn * l;
  const Vec<S> dual_v = a * dv + (hd * (t * cs - a * w)) * l;
  return {{rv.x, rv.y, rv.z, cs}, {dual_v.x, dual_v.y, dual_v.z, -t * hd * sn}};
}

/// The binary exponent of the largest |component| of a nonzero v, and v times 2^e exactly.
template <class S> int own_exponent(const Vec<S>& v) {
  using std::abs;
  return std::ilogb(std::max({abs(v.x), abs(v.y), abs(v.z)}));
}
template <class S> Vec<S> scaled(const Vec<S>& v, int e) { return {std::scalbn(v.x, e), std::scalbn(v.y, e), std::scalbn(v.z, e)}; }

/// |v| without overflow or underflow of the squares: scaled by the largest |component| (exact
/// power of two), so a subnormal vector part keeps its direction.
template <class S> S length(const Vec<S>& v) {
  if (const S n2 = dot(v, v); runtime::is_ordinary_square(n2)) return std::sqrt(n2);
  if (v.x == 0 && v.y == 0 && v.z == 0) return 0;
  const int e = own_exponent(v);
  const Vec<S> u = scaled(v, -e);
  return std::scalbn(std::sqrt(dot(u, u)), e);
}

/// v / len for len = |v| > 0: by the reciprocal where it is finite, else component by component
/// (a subnormal |v|, whose reciprocal overflows in binary32: EDGE-1's full exponent range).
template <class S> Vec<S> direction(const Vec<S>& v, S len) {
  if (const S r = S(1) / len; std::isfinite(r)) [[likely]]
    return r * v;
  return {v.x / len, v.y / len, v.z / len};
}

/// A dual vector xi = xi_r + eps xi_d (DQ-8, DQ-9): the ABI's 6 scalars.
template <class S> struct DualVec { Vec<S> r, d; };

/// DQ-8 on validated input: with (r, d) = DQ-4(sigma), r = (cos b, sin b n), b = atan2(|r_v|, r_w)
/// (no hemisphere flip): xi_r = b n, xi_d = a n + (b / sin b) d_perp with a = (d_v.n) cos b - d_w
/// sin b = t.n / 2. r = +1: (0, d_v); r = -1: the branch cut, (pi t/|t|, t/2) with t the
/// translation, +z for t = 0.
template <class S> DualVec<S> log(const Dual<S>& sigma) {
  const Vec<S> rv = vec(sigma.r);
  if (rv.x == 0 && rv.y == 0 && rv.z == 0) {
    const auto xi = runtime::log_of_scalar_real_part<S>(sigma.r.w, {sigma.d.x, sigma.d.y, sigma.d.z});
    return {{xi[0], xi[1], xi[2]}, {xi[3], xi[4], xi[5]}};
  }
  // Read off the input, not off DQ-4(sigma): where |r_v| << |r_w| the normalised vector part is
  // subnormal and has lost the axis (EDGE-1). With x = sigma at a common power-of-two scale and
  // t = DQ-1's translation of x:
  //   b = atan2(|r_v|, r_w), n = r_v / |r_v|, a = t.n / 2,
  //   (b / sin b) d'_perp = b (d_v)_perp / |r_v|   (d'_perp = (d_v)_perp / |r|, sin b = |r_v| / |r|),
  // n and the quotient each from r_v and d_v scaled by their own powers of two, so that neither
  // a tiny r_v nor huge parts lose bits or overflow on the way.
  const int er = scale_exponent(sigma.r), ev = own_exponent(rv);
  const Quat<S> r_own = scaled(sigma.r, -er);
  const Vec<S> rv_own = scaled(rv, -ev);
  const S len2 = dot(rv_own, rv_own);
  const S nr = std::sqrt(dot(r_own, r_own)), len_own = std::sqrt(len2);  // |r|, |r_v| / 2^e
  const S b = std::atan2(std::scalbn(len_own, ev - er), r_own.w);
  const Vec<S> n = (S(1) / len_own) * rv_own;
  const Dual<S> x = safely_scaled(sigma);
  const S a = dot(translation(x), n) / (S(2) * dot(x.r, x.r));
  const Vec<S> dv = vec(sigma.d);
  if (dv.x == 0 && dv.y == 0 && dv.z == 0) return {b * n, a * n};
  const int ed = own_exponent(dv);
  const Vec<S> dv_own = scaled(dv, -ed);
  // (d_v)_perp without the subtraction d_v - (d_v.n) n, which cancels where d_v is nearly parallel
  // to the axis and leaves eps |d_v| that b / sin b then magnifies near the cut: the fma form of
  // runtime/perpendicular_part.hpp on the exact r_v (scaled by a power of two), not the rounded n.
  const std::array<S, 4> pp =
      runtime::perpendicular_times_norm2<S>({rv_own.x, rv_own.y, rv_own.z, 0}, {dv_own.x, dv_own.y, dv_own.z, 0});
  const Vec<S> perp_own{pp[0] / len2, pp[1] / len2, pp[2] / len2};
  // (b / sin b) (d_v)_perp / |r|: up to pi/2 with sin b from b itself (b / sin b -> 1 exactly as b
  // -> 0, whatever b's rounding); beyond, with sin b = |r_v| / |r| (b is accurate near pi, sin b
  // is not).
  if (b <= S(1.5707963267948966)) {
    const S kappa = b == 0 ? S(1) : b / std::sin(b);  // b underflows where |r_v| / |r| does
    return {b * n, a * n + scaled((kappa / nr) * perp_own, ed - er)};
  }
  return {b * n, a * n + scaled((b / len_own) * perp_own, ed - ev)};
}

/// DQ-9: b = |xi_r|, n = xi_r / b, a = xi_d.n, xi_perp = xi_d - a n;
/// exp = (sin b n, cos b) + eps (a cos b n + (sin b / b) xi_perp, -a sin b); b = 0: (1, (xi_d, 0)).
template <class S> Dual<S> exp(const DualVec<S>& xi) {
  const S b = length(xi.r);
  if (b == 0) return {{0, 0, 0, 1}, {xi.d.x, xi.d.y, xi.d.z, 0}};
  const Vec<S> n = direction(xi.r, b);
  const S a = dot(xi.d, n);
  const Vec<S> perp = xi.d - a * n;
  const S c = std::cos(b), sn = std::sin(b);
  const Vec<S> rv = sn * n, dv = (a * c) * n + (sn / b) * perp;
  return {{rv.x, rv.y, rv.z, c}, {dv.x, dv.y, dv.z, -a * sn}};
}

/// DQ-5 on validated input: both DQ-4 normalised, b' = -b iff a_r.b_r < 0 strictly (EDGE-3,
/// decided on the inputs), then a (a* b')^t.
template <class S> Dual<S> sclerp(const Dual<S>& a_in, const Dual<S>& b_in, S t) {
  const Dual<S> a = normalized(a_in);
  Dual<S> b = normalized(b_in);
  if (hemisphere_dot(a_in.r, b_in.r) < 0) b = {-b.r, -b.d};
  const Dual<S> rel = Dual<S>{conj(a.r), conj(a.d)} * b;
  return a * screw_power(rel, t);
}

/// DQ-6 (DLB, Kavan et al. 2008) on validated input: s_i = -1 iff r_i.r_p < 0 against the
/// pivot p (first weight > 0), decided on the real parts as given (`real(i)`); the sum of
/// (w_i / w_max) s_i sigma_i over the unit influences `unit(i)` (EDGE-5: a non-unit input stands
/// for its DQ-4 normalisation), then DQ-4 of the sum.
template <class S, class Real, class Unit>
Dual<S> dlb(std::size_t k, Real real, Unit unit, std::span<const S> w, S w_max) {
  std::size_t p = 0;
  while (!(w[p] > 0)) ++p;
  const Quat<S> pivot = real(p);
  Dual<S> sum{{0, 0, 0, 0}, {0, 0, 0, 0}};
  for (std::size_t i = 0; i < k; ++i) {
    const Dual<S> u = unit(i);
    const S f = hemisphere_dot(real(i), pivot) < 0 ? -(w[i] / w_max) : w[i] / w_max;
    sum = {sum.r + f * u.r, sum.d + f * u.d};
  }
  return normalized(sum);
}

/// DQ-6 on an element of the batch (k influences of 8 scalars at d, k weights at w) whose input
/// passes the cheap tests: every weight in [0, max], some > 0; every influence with |r|^2
/// ordinary and |d|^2 ordinary or 0 (runtime/ordinary_range.hpp: then every component is
/// finite, r != 0 and safely_scaled() is the identity); no DQ-4 projection that cancels. There
/// it is dlb() above with the same operations in the same order, so the same bits, without the
/// checks, copies and calls that dominate the cost on ordinary input. Returns false, having
/// written nothing, where a test fails: the caller then takes the checked element path.
template <class S>
bool dlb_ordinary(std::size_t k, const S* d, const S* w, Dual<S>& out) {
  S w_max;
  std::size_t p;
  if (!rci::ordinary_weights(std::span<const S>(w, k), w_max, p)) return false;
  const Quat<S> pivot{d[8 * p], d[8 * p + 1], d[8 * p + 2], d[8 * p + 3]};
  Dual<S> sum{{0, 0, 0, 0}, {0, 0, 0, 0}};
  for (std::size_t i = 0; i < k; ++i) {
    const S* x = d + 8 * i;
    const Dual<S> s{{x[0], x[1], x[2], x[3]}, {x[4], x[5], x[6], x[7]}};
    const Quat<S>& r = s.r;
    Dual<S> u;
    if (!normalized_ordinary(s, dot(s.r, s.r), dot(s.d, s.d), u)) return false;
    const int side = runtime::filtered_dot_sign<S, 4>({r.x, r.y, r.z, r.w}, {pivot.x, pivot.y, pivot.z, pivot.w});
    if (side == 2) return false;  // only the exact sum can tell (EDGE-3)
    const S f = side < 0 ? -(w[i] / w_max) : w[i] / w_max;
    sum = {sum.r + f * u.r, sum.d + f * u.d};
  }
  if (!normalized_ordinary(sum, dot(sum.r, sum.r), dot(sum.d, sum.d), out)) out = normalized(sum);
  return true;
}

/// Validation shared by SKIN-1 and SKIN-2 (EDGE-6, EDGE-7, EDGE-9): returns the largest weight,
/// 0 when the input is outside the domain.
template <class S>
S skin_input_ok(std::span<const rci::Quat<S>> q, std::span<const rci::Vec3<S>> t, std::span<const S> w,
                const rci::Vec3<S>& v) {
  if (q.empty() || q.size() != t.size() || q.size() != w.size() || !finite(load(v))) return 0;
  for (std::size_t i = 0; i < q.size(); ++i)
    if (!valid(load(q[i])) || !finite(load(t[i]))) return 0;
  return largest_weight(w);
}

// ---- SoA lanes of the quaternion ops ----------------------------------------------------------------
//
// NORM-1, COMPOSE-1, INV-1 and APPLY-1 for L elements at once (runtime/lane_blocks.hpp runs them): each
// lane calls the functions above that the element functions call (operator/, operator*, rotate) on
// its element, with the element functions' ordinary-case operations, so the same bits; no branch
// depends on a lane, so the loops vectorise. A lane whose |q|^2 is not ordinary (which includes
// zero, NaN and Inf) or whose vector is not finite has `ok` false and takes the element function.

template <class S, std::size_t L>
struct QuatLanes {
  using Flag = std::int32_t;
  S x[4][L];
  Flag ok[L];
  void load_quats(const S* q) {
    for (std::size_t l = 0; l < L; ++l)
      for (std::size_t c = 0; c < 4; ++c) x[c][l] = q[4 * l + c];
  }
  Quat<S> quat(std::size_t l) const { return {x[0][l], x[1][l], x[2][l], x[3][l]}; }
};

/// NORM-1: q / sqrt(q.q), normalized()'s ordinary case.
template <class S, std::size_t L>
struct NormalizeLanes : QuatLanes<S, L> {
  S out[4][L];
  void run(const S* q, const S* /*unused*/) {
    this->load_quats(q);
    for (std::size_t l = 0; l < L; ++l) {
      const Quat<S> a = this->quat(l);
      const S n2 = dot(a, a);
      this->ok[l] = runtime::is_ordinary_square_lane(n2);
      const Quat<S> u = a / std::sqrt(n2);
      out[0][l] = u.x, out[1][l] = u.y, out[2][l] = u.z, out[3][l] = u.w;
    }
  }
};

/// COMPOSE-1: the Hamilton product a b as given.
template <class S, std::size_t L>
struct ComposeLanes : QuatLanes<S, L> {
  S y[4][L], out[4][L];
  void run(const S* a, const S* b) {
    this->load_quats(a);
    for (std::size_t l = 0; l < L; ++l)
      for (std::size_t c = 0; c < 4; ++c) y[c][l] = b[4 * l + c];
    for (std::size_t l = 0; l < L; ++l) {
      const Quat<S> p = this->quat(l), q{y[0][l], y[1][l], y[2][l], y[3][l]};
      const bool ordinary_p = runtime::is_ordinary_square_lane(dot(p, p));
      const bool ordinary_q = runtime::is_ordinary_square_lane(dot(q, q));
      this->ok[l] = ordinary_p & ordinary_q;
      const Quat<S> r = p * q;
      out[0][l] = r.x, out[1][l] = r.y, out[2][l] = r.z, out[3][l] = r.w;
    }
  }
};

/// APPLY-1: rotate(q / sqrt(q.q), v).
template <class S, std::size_t L>
struct ApplyVectorLanes : QuatLanes<S, L> {
  S v[3][L], out[3][L];
  void run(const S* q, const S* p) {
    this->load_quats(q);
    for (std::size_t l = 0; l < L; ++l)
      for (std::size_t c = 0; c < 3; ++c) v[c][l] = p[3 * l + c];
    for (std::size_t l = 0; l < L; ++l) {
      const Quat<S> a = this->quat(l);
      const S n2 = dot(a, a);
      const bool ordinary_q = runtime::is_ordinary_square_lane(n2);
      const bool finite_v = runtime::finite3_lane(v[0][l], v[1][l], v[2][l]);
      this->ok[l] = ordinary_q & finite_v;
      const Vec<S> r = rotate(a / std::sqrt(n2), Vec<S>{v[0][l], v[1][l], v[2][l]});
      out[0][l] = r.x, out[1][l] = r.y, out[2][l] = r.z;
    }
  }
};

/// INV-1: conj(q) / (q.q), inverse()'s ordinary case; q read in place (as dlb_lanes.hpp's
/// normalized_lane() does: faster than load_quats() here).
template <class S, std::size_t L>
struct InverseLanes : QuatLanes<S, L> {
  S out[4][L];
  void run(const S* q, const S* /*unused*/) {
    for (std::size_t l = 0; l < L; ++l) {
      const Quat<S> a{q[4 * l], q[4 * l + 1], q[4 * l + 2], q[4 * l + 3]};
      const S n2 = dot(a, a);
      this->ok[l] = runtime::is_ordinary_square_lane(n2);
      const Quat<S> r = conj(a) / n2;
      out[0][l] = r.x, out[1][l] = r.y, out[2][l] = r.z, out[3][l] = r.w;
    }
  }
};

// ---- the implementation ----------------------------------------------------------------------------

template <class S>
struct Dq {
  using Scalar = S;
  /// The most influences a batched binary32 blend runs in SIMD lanes (the suite uses n <= 8: 8.3).
  static constexpr std::size_t kLaneInfluences = 8;
  static constexpr const char* name = "dq";
  static constexpr const char* version = "0.1.0";
  static constexpr const char* description =
      "dual quaternions written from the spec (DQ-1..6, ScLERP by screw parameters, DLB, LBS/DQS)";
  // Core: only the clauses listed (no matrices, axis-angle); the bit marks that Core clauses are claimed.
  static constexpr std::uint32_t levels = RC_LEVEL_CORE | RC_LEVEL_RIGID | RC_LEVEL_SKINNING | RC_LEVEL_ROBUST;
  static constexpr const char* const clauses[] = {
      "NORM-1", "COMPOSE-1", "INV-1",  "APPLY-1", "QUAT-2",                                  // Core (partial)
      "DQ-1",   "DQ-2",      "DQ-3",   "DQ-4",    "DQ-5",   "DQ-6",   "AXIS-1",              // Rigid
      "SKIN-1", "SKIN-2",    "SKIN-3",                                                       // Skinning
      "DQ-7",   "DQ-8",      "DQ-9",   "RIGID-1", "RIGID-2", "RIGID-3",                      // Extended
      "EDGE-1", "EDGE-2",    "EDGE-3", "EDGE-4",  "EDGE-5", "EDGE-6", "EDGE-7", "EDGE-8", "EDGE-9",  // Robust
      nullptr};

  // -- Core: the quaternion operations of the real part ----------------------------------------

  static Status normalize(const rci::Quat<S>& q, rci::Quat<S>& out) {
    if (!valid(load(q))) return Status::domain_error;
    out = store(normalized(load(q)));
    return Status::ok;
  }

  /// COMPOSE-1: the exact product of the inputs as given (no normalisation).
  static Status compose(const rci::Quat<S>& a, const rci::Quat<S>& b, rci::Quat<S>& out) {
    if (!valid(load(a)) || !valid(load(b))) return Status::domain_error;
    out = store(load(a) * load(b));
    return Status::ok;
  }

  /// INV-1: q*/|q|^2 = 2^-e (q_s*/|q_s|^2) with q_s = 2^-e q: no overflow of |q|^2 for large
  /// q and no underflow for subnormal q.
  static Status inverse(const rci::Quat<S>& q_in, rci::Quat<S>& out) {
    const Quat<S> q = load(q_in);
    if (!valid(q)) return Status::domain_error;
    if (const S n2 = dot(q, q); runtime::is_ordinary_square(n2)) {
      out = store(conj(q) / n2);
      return Status::ok;
    }
    const int e = scale_exponent(q);
    const Quat<S> s = scaled(q, -e);
    out = store(scaled(conj(s) / dot(s, s), -e));
    return Status::ok;
  }

  static Status apply_vector(const rci::Quat<S>& q, const rci::Vec3<S>& v, rci::Vec3<S>& out) {
    if (!valid(load(q)) || !finite(load(v))) return Status::domain_error;
    out = store(rotate(normalized(load(q)), load(v)));
    return Status::ok;
  }

  /// The batches of normalize, compose, inverse and apply_vector: SIMD lanes (QuatLanes above: the
  /// same bits) in blocks of 16, then of 4; a lane that is not ok, and the last n mod 4 elements,
  /// by the element function.
  ROTORCERT_TARGET_CLONES_FLAT static int normalize_batch(std::size_t n, const S* q, S* out, std::uint8_t* status) {
    return runtime::lanes_or_element<NormalizeLanes, &Dq::normalize, 4, 4>(n, q, out, status);
  }
  ROTORCERT_TARGET_CLONES_FLAT static int compose_batch(std::size_t n, const S* a, const S* b, S* out,
                                                       std::uint8_t* status) {
    return runtime::lanes_or_element<ComposeLanes, &Dq::compose, 4, 4, 4>(n, a, b, out, status);
  }
  ROTORCERT_TARGET_CLONES_FLAT static int inverse_batch(std::size_t n, const S* q, S* out, std::uint8_t* status) {
    return runtime::lanes_or_element<InverseLanes, &Dq::inverse, 4, 4>(n, q, out, status);
  }
  ROTORCERT_TARGET_CLONES_FLAT static int apply_vector_batch(std::size_t n, const S* q, const S* v, S* out,
                                                            std::uint8_t* status) {
    return runtime::lanes_or_element<ApplyVectorLanes, &Dq::apply_vector, 4, 3, 3>(n, q, v, out, status);
  }

  // -- Rigid ------------------------------------------------------------------------------------

  static Status dq_from_rotation_translation(const rci::Quat<S>& q, const rci::Vec3<S>& t, rci::DualQuat<S>& out) {
    if (!valid(load(q)) || !finite(load(t))) return Status::domain_error;
    out = store(from_rotation_translation(normalized(load(q)), load(t)));
    return Status::ok;
  }

  /// The batch of dq_from_rotation_translation: SIMD lanes (dlb_lanes.hpp: the same bits) in
  /// blocks of 16, then of 4, with the clones' widths of dq_apply_point_batch; a lane that is not
  /// ok, and the last n mod 4 elements, by the checked function above. dq_compose_batch and
  /// dq_normalize_batch below run the same way.
  ROTORCERT_TARGET_CLONES_FLAT static int dq_from_rotation_translation_batch(std::size_t n, const S* q, const S* t,
                                                                            S* out, std::uint8_t* status) {
    return runtime::lanes_or_element<rotorcert::dq_lanes::FromRotationTranslationLanes,
                                     &Dq::dq_from_rotation_translation, 4, 3, 8>(n, q, t, out, status);
  }

  /// DQ-2 on the DQ-4-normalised inputs. The clause defines the product of the inputs as given;
  /// the dual norm is multiplicative, so this is that product's DQ-4 normalisation, the same
  /// rigid motion, which is what METRIC-7 compares.
  static Status dq_compose(const rci::DualQuat<S>& a, const rci::DualQuat<S>& b, rci::DualQuat<S>& out) {
    if (!valid(load(a)) || !valid(load(b))) return Status::domain_error;
    out = store(normalized(load(a)) * normalized(load(b)));
    return Status::ok;
  }

  /// The batch of dq_compose (dlb_lanes.hpp DqComposeLanes), as dq_from_rotation_translation_batch.
  ROTORCERT_TARGET_CLONES_FLAT static int dq_compose_batch(std::size_t n, const S* a, const S* b, S* out,
                                                          std::uint8_t* status) {
    return runtime::lanes_or_element<rotorcert::dq_lanes::DqComposeLanes, &Dq::dq_compose, 8, 8, 8>(n, a, b, out,
                                                                                                   status);
  }

  static Status dq_apply_point(const rci::DualQuat<S>& d, const rci::Vec3<S>& p, rci::Vec3<S>& out) {
    if (!valid(load(d)) || !finite(load(p))) return Status::domain_error;
    out = store(apply_point(load(d), load(p)));
    return Status::ok;
  }

  /// The batch of dq_apply_point: SIMD lanes (dlb_lanes.hpp: the same bits) in blocks of 16, then
  /// of 4 (runtime/lane_blocks.hpp); a lane that is not ok, and the last n mod 4 elements, by the
  /// checked function above. The AVX2 clone (runtime/target_clones.hpp) holds 8
  /// binary32 or 4 binary64 lanes per vector; the baseline clone does not vectorise binary64 (GCC
  /// 12: no vector type for its mix of int and double) and runs its lanes at scalar speed.
  ROTORCERT_TARGET_CLONES_FLAT static int dq_apply_point_batch(std::size_t n, const S* d, const S* p, S* out,
                                                              std::uint8_t* status) {
    return runtime::lanes_or_element<rotorcert::dq_lanes::ApplyPointLanes, &Dq::dq_apply_point, 8, 3, 3>(n, d, p, out,
                                                                                                     status);
  }

  /// DQ-7 (ABI version 3): DQ-4, then q = r' and t = 2 vec(d' r'*) (DQ-1 read backwards).
  static Status dq_to_rotation_translation(const rci::DualQuat<S>& d, rci::Quat<S>& q, rci::Vec3<S>& t) {
    if (!valid(load(d))) return Status::domain_error;
    const Dual<S> u = normalized(load(d));
    q = store(u.r);
    t = store(translation(u));
    return Status::ok;
  }

  /// DQ-8 (ABI version 4): the log of DQ-4(sigma), out = [xi_r, xi_d].
  static Status dq_log(const rci::DualQuat<S>& d, std::array<S, 6>& out) {
    if (!valid(load(d))) return Status::domain_error;
    const DualVec<S> xi = log(load(d));
    out = {xi.r.x, xi.r.y, xi.r.z, xi.d.x, xi.d.y, xi.d.z};
    return Status::ok;
  }

  /// DQ-9 (ABI version 4).
  static Status dq_exp(const std::array<S, 6>& xi, rci::DualQuat<S>& out) {
    const DualVec<S> x{{xi[0], xi[1], xi[2]}, {xi[3], xi[4], xi[5]}};
    if (!finite(x.r) || !finite(x.d)) return Status::domain_error;
    out = store(exp(x));
    return Status::ok;
  }

  // -- rigid transforms as rotation + translation (ABI version 4) ---------------------------------

  /// RIGID-1: (q^_a q^_b, R_a t_b + t_a).
  static Status rigid_compose(const rci::Quat<S>& qa, const rci::Vec3<S>& ta, const rci::Quat<S>& qb,
                              const rci::Vec3<S>& tb, rci::Quat<S>& q, rci::Vec3<S>& t) {
    if (!valid(load(qa)) || !valid(load(qb)) || !finite(load(ta)) || !finite(load(tb))) return Status::domain_error;
    const Quat<S> ua = normalized(load(qa));
    q = store(ua * normalized(load(qb)));
    t = store(rotate(ua, load(tb)) + load(ta));
    return Status::ok;
  }

  /// RIGID-2: R p + t.
  static Status rigid_apply(const rci::Quat<S>& q, const rci::Vec3<S>& t, const rci::Vec3<S>& p, rci::Vec3<S>& out) {
    if (!valid(load(q)) || !finite(load(t)) || !finite(load(p))) return Status::domain_error;
    out = store(rotate(normalized(load(q)), load(p)) + load(t));
    return Status::ok;
  }

  /// RIGID-3: (q^*, -R^-1 t).
  static Status rigid_inverse(const rci::Quat<S>& q_in, const rci::Vec3<S>& t_in, rci::Quat<S>& q, rci::Vec3<S>& t) {
    if (!valid(load(q_in)) || !finite(load(t_in))) return Status::domain_error;
    const Quat<S> inv = conj(normalized(load(q_in)));
    q = store(inv);
    t = store(S(-1) * rotate(inv, load(t_in)));
    return Status::ok;
  }

  static Status dq_normalize(const rci::DualQuat<S>& d, rci::DualQuat<S>& out) {
    if (!valid(load(d))) return Status::domain_error;
    out = store(normalized(load(d)));
    return Status::ok;
  }

  /// The batch of dq_normalize (dlb_lanes.hpp DqNormalizeLanes), as dq_from_rotation_translation_batch.
  ROTORCERT_TARGET_CLONES_FLAT static int dq_normalize_batch(std::size_t n, const S* d, S* out, std::uint8_t* status) {
    return runtime::lanes_or_element<rotorcert::dq_lanes::DqNormalizeLanes, &Dq::dq_normalize, 8, 8>(n, d, out, status);
  }

  static Status dq_sclerp(const rci::DualQuat<S>& a, const rci::DualQuat<S>& b, const S& t, rci::DualQuat<S>& out) {
    if (!valid(load(a)) || !valid(load(b)) || !finite(t)) return Status::domain_error;
    out = store(sclerp(load(a), load(b), t));
    return Status::ok;
  }

  static Status dq_blend(std::span<const rci::DualQuat<S>> d, std::span<const S> w, rci::DualQuat<S>& out) {
    if (d.empty() || d.size() != w.size()) return Status::domain_error;
    for (const auto& x : d)
      if (!valid(load(x))) return Status::domain_error;
    const S w_max = largest_weight(w);
    if (!(w_max > 0)) return Status::domain_error;
    out = store(dlb<S>(
        d.size(), [&](std::size_t i) { return load(d[i]).r; }, [&](std::size_t i) { return normalized(load(d[i])); }, w,
        w_max));
    return Status::ok;
  }

  /// The batch of dq_blend. k <= kLaneInfluences: SIMD lanes (dlb_lanes.hpp: the same bits as
  /// the checked path) in blocks of 16, then of 4 (runtime/lane_blocks.hpp), with the clones'
  /// widths of dq_apply_point_batch; a lane that is not ok goes to the checked element function.
  /// The last n mod 4 elements, and every element of more influences: dlb_ordinary(), the same
  /// bits too, else the checked function.
  ROTORCERT_TARGET_CLONES_FLAT static int dq_blend_batch(std::size_t n, std::size_t k, const S* d, const S* w, S* out,
                                                        std::uint8_t* status) {
    const auto checked = [&](std::size_t e) {
      rci::detail::blend<&Dq::dq_blend, S, 8, 8>(1, k, d + 8 * k * e, w + k * e, out + 8 * e, status + e);
    };
    const auto single = [&](std::size_t i) {
      Dual<S> r;
      if (k > 0 && dlb_ordinary(k, d + 8 * k * i, w + k * i, r)) [[likely]] {
        const rci::DualQuat<S> o = store(r);
        std::copy(o.begin(), o.end(), out + 8 * i);
        status[i] = RC_OK;
      } else {
        checked(i);
      }
    };
    if (k > 0 && k <= kLaneInfluences) {
      runtime::in_lanes_or_checked<rotorcert::dq_lanes::DlbLanes>(
          n, d, 8 * k, w, k, [&](auto& lanes, const S* dd, const S* ww) { lanes.run(k, dd, ww); },
          runtime::copy_lane_outputs<8>(out, status), checked, single);
      return 0;
    }
    for (std::size_t i = 0; i < n; ++i) single(i);
    return 0;
  }

  /// AXIS-1 as a dual quaternion: T(c) R T(-c) = (q, 1/2 (c q - q c)), then DQ-3. Its
  /// translation is c - R c, so p' = R p + (c - R c) = R (p - c) + c.
  static Status rotate_about_axis(const rci::Vec3<S>& c_in, const rci::Vec3<S>& u_in, const S& angle,
                                  const rci::Vec3<S>& p, rci::Vec3<S>& out) {
    const Vec<S> c = load(c_in), u = load(u_in);
    if (!finite(c) || !finite(u) || !finite(angle) || !finite(load(p))) return Status::domain_error;
    if (u.x == 0 && u.y == 0 && u.z == 0) return Status::domain_error;
    const Quat<S> axis = normalized(Quat<S>{u.x, u.y, u.z, 0});
    const S sn = std::sin(angle / 2), cs = std::cos(angle / 2);
    const Quat<S> q{sn * axis.x, sn * axis.y, sn * axis.z, cs};
    const Quat<S> cq{c.x, c.y, c.z, 0};
    const Dual<S> sigma{q, S(0.5) * (cq * q - q * cq)};
    out = store(rotate(q, load(p)) + translation(sigma));
    return Status::ok;
  }

  /// The batch of rotate_about_axis: SIMD lanes (dlb_lanes.hpp RotateAboutAxisLanes: the same
  /// bits) in blocks of 16, then of 4; a lane that is not ok, and the last n mod 4 elements, by
  /// the checked function above.
  ROTORCERT_TARGET_CLONES_FLAT static int rotate_about_axis_batch(std::size_t n, const S* c, const S* u, const S* angle,
                                                                 const S* p, S* out, std::uint8_t* status) {
    return runtime::lanes_or_element<rotorcert::dq_lanes::RotateAboutAxisLanes, &Dq::rotate_about_axis, 3, 3, 3, 3>(
        n, c, u, angle, p, out, status);
  }

  // -- Skinning ---------------------------------------------------------------------------------

  /// SKIN-1: the blended matrix sum w_i M_i (MAT-1 of q_i/|q_i|) and translation sum w_i t_i,
  /// applied to v and divided by W (weights first divided by the largest one).
  static Status skin_linear(std::span<const rci::Quat<S>> q, std::span<const rci::Vec3<S>> t, std::span<const S> w,
                            const rci::Vec3<S>& v_in, rci::Vec3<S>& out) {
    const S w_max = skin_input_ok(q, t, w, v_in);
    if (!(w_max > 0)) return Status::domain_error;
    S m[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};  // column-major
    Vec<S> tsum{0, 0, 0};
    S total = 0;
    for (std::size_t i = 0; i < q.size(); ++i) {
      const S f = w[i] / w_max;
      const Quat<S> r = normalized(load(q[i]));
      const S xx = r.x * r.x, yy = r.y * r.y, zz = r.z * r.z, xy = r.x * r.y, xz = r.x * r.z, yz = r.y * r.z;
      const S wx = r.w * r.x, wy = r.w * r.y, wz = r.w * r.z;
      const S mi[9] = {1 - 2 * (yy + zz), 2 * (xy + wz),     2 * (xz - wy),
                       2 * (xy - wz),     1 - 2 * (xx + zz), 2 * (yz + wx),
                       2 * (xz + wy),     2 * (yz - wx),     1 - 2 * (xx + yy)};
      for (int j = 0; j < 9; ++j) m[j] += f * mi[j];
      tsum = tsum + f * load(t[i]);
      total += f;
    }
    const Vec<S> v = load(v_in);
    const Vec<S> mv{m[0] * v.x + m[3] * v.y + m[6] * v.z, m[1] * v.x + m[4] * v.y + m[7] * v.z,
                    m[2] * v.x + m[5] * v.y + m[8] * v.z};
    out = store((S(1) / total) * (mv + tsum));
    return Status::ok;
  }

  /// The batch of skin_linear. k <= kLaneInfluences: SIMD lanes (dlb_lanes.hpp SkinLinearLanes:
  /// the same bits) in blocks of 16, then of 4; a lane that is not ok, the last n mod 4 elements
  /// and every element of more influences by the checked function above.
  ROTORCERT_TARGET_CLONES_FLAT static int skin_linear_batch(std::size_t n, std::size_t k, const S* q, const S* t,
                                                           const S* w, const S* v, S* out, std::uint8_t* status) {
    return runtime::skin_lanes_or_element<rotorcert::dq_lanes::SkinLinearLanes, &Dq::skin_linear, kLaneInfluences>(
        n, k, q, t, w, v, out, status);
  }

  /// SKIN-2: sigma_i = DQ-1(q_i, t_i) (unit by construction), DLB, DQ-3.
  static Status skin_dual_quaternion(std::span<const rci::Quat<S>> q, std::span<const rci::Vec3<S>> t,
                                     std::span<const S> w, const rci::Vec3<S>& v, rci::Vec3<S>& out) {
    const S w_max = skin_input_ok(q, t, w, v);
    if (!(w_max > 0)) return Status::domain_error;
    const auto influence = [&](std::size_t i) { return from_rotation_translation(normalized(load(q[i])), load(t[i])); };
    const Dual<S> sigma = dlb<S>(q.size(), [&](std::size_t i) { return load(q[i]); }, influence, w, w_max);
    out = store(rotate(sigma.r, load(v)) + translation(sigma));
    return Status::ok;
  }

  /// The batch of skin_dual_quaternion, as skin_linear_batch (dlb_lanes.hpp
  /// SkinDualQuaternionLanes); a lane whose hemisphere sign the filter cannot decide (EDGE-3) or
  /// whose blended sum is not ordinary goes to the checked function too.
  ROTORCERT_TARGET_CLONES_FLAT static int skin_dual_quaternion_batch(std::size_t n, std::size_t k, const S* q,
                                                                    const S* t, const S* w, const S* v, S* out,
                                                                    std::uint8_t* status) {
    return runtime::skin_lanes_or_element<rotorcert::dq_lanes::SkinDualQuaternionLanes, &Dq::skin_dual_quaternion,
                                          kLaneInfluences>(n, k, q, t, w, v, out, status);
  }
};

}  // namespace

ROTORCERT_DEFINE_ENTRY(dq, Dq<float>, Dq<double>)
