// rotor_gen: GA rotors whose algebra is generated from the reference (the paper's "automatically
// generated" GA code, as Gaigen and Gaalop produce it). generate_rotor_kernels.cpp reads the
// reference's blade tables at build time and writes rotor_gen_kernels.hpp: the geometric product,
// reverse, norm and sandwich of the even subalgebra of Cl(3,0), specialised, zero terms dropped.
//
// Quaternions map in by Phi(q) = w - x e23 - y e31 - z e12 (Q2R-1, as rotor_m2), claims and levels
// are rotor_m2's, and so are the results: the hot ops (normalize, compose, apply_vector, nlerp,
// slerp) are batch functions whose fast path runs the generated kernels on ordinary inputs and
// hands every other element to the shared robust code of impls/rotor/rotor3.hpp (RotorOps); the
// other ops are RotorOps as they are.
//
// Batching, apart from the scalar math (ozz-animation / klein style): a batch is cut into blocks of
// kBlock elements, copied into arrays of components (SoA). Pass 1 runs the fast path on every element
// of the block without branches (so it vectorises), writes into a block-local buffer (inputs and
// outputs may alias) and records each element's guard. Only a block where a guard failed is walked
// again, and its failing elements are recomputed by RotorOps. A guard is the cheap test of runtime/ordinary_range.hpp:
// |q|^2 computed without scaling lies in [2^-2W, 2^2W] (NaN, Inf and zero fail it), where the
// unscaled formula is as accurate as the scaled one (NORM-1, EDGE-5, EDGE-8); the hemisphere test
// adds the error bound of runtime/exact_sign.hpp's filter (EDGE-3).
#include <algorithm>
#include <cmath>
#include <math.h>  // sincos, sincosf
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

#include <rotorcert/impl_table.hpp>
#include <rotorcert/runtime/exact_sign.hpp>
#include <rotorcert/runtime/ordinary_range.hpp>
#include <rotorcert/runtime/target_clones.hpp>

#include "../rotor/rotor3.hpp"
#include "rotor_gen_kernels.hpp"

namespace {

using rotorcert::impl::Quat;
using rotorcert::impl::Status;
using rotorcert::impl::Vec3;
using rotorcert::rotor::Rotor3;
using rotorcert::rotor_gen::Cl3Even;
using rotorcert::rotor_gen::Cl3Vector;
namespace gen = rotorcert::rotor_gen;

constexpr std::size_t kBlock = 64;

// The batch functions are compiled for AVX2 and for the baseline (runtime/target_clones.hpp).

// ---- blocks of the ABI's arrays as algebra elements (LAYOUT-1 [x, y, z, w]; Phi of Q2R-1) --------

/// kBlock quaternions as four arrays (SoA), so that the fast paths' loops vectorise in binary64
/// too (GCC will not interleave stride-4 records into two-lane vectors). Element i is the rotor
/// Phi(q_i) = w - x e23 - y e31 - z e12.
template <class S>
struct QuatBlock {
  S x[kBlock], y[kBlock], z[kBlock], w[kBlock];

  void load(const S* q, std::size_t m) {
    for (std::size_t i = 0; i < m; ++i) x[i] = q[4 * i], y[i] = q[4 * i + 1], z[i] = q[4 * i + 2], w[i] = q[4 * i + 3];
  }
  void store(S* q, std::size_t m) const {
    for (std::size_t i = 0; i < m; ++i) q[4 * i] = x[i], q[4 * i + 1] = y[i], q[4 * i + 2] = z[i], q[4 * i + 3] = w[i];
  }
  Cl3Even<S> rotor(std::size_t i) const { return {w[i], -x[i], -y[i], -z[i]}; }
  void set(std::size_t i, const Cl3Even<S>& r) { x[i] = -r.e23, y[i] = -r.e31, z[i] = -r.e12, w[i] = r.s; }
  void set(std::size_t i, const Quat<S>& q) { x[i] = q[0], y[i] = q[1], z[i] = q[2], w[i] = q[3]; }
};

/// kBlock 3-vectors as three arrays.
template <class S>
struct VecBlock {
  S x[kBlock], y[kBlock], z[kBlock];

  void load(const S* v, std::size_t m) {
    for (std::size_t i = 0; i < m; ++i) x[i] = v[3 * i], y[i] = v[3 * i + 1], z[i] = v[3 * i + 2];
  }
  void store(S* v, std::size_t m) const {
    for (std::size_t i = 0; i < m; ++i) v[3 * i] = x[i], v[3 * i + 1] = y[i], v[3 * i + 2] = z[i];
  }
  Cl3Vector<S> vector(std::size_t i) const { return {x[i], y[i], z[i]}; }
  void set(std::size_t i, const Cl3Vector<S>& v) { x[i] = v.e1, y[i] = v.e2, z[i] = v.e3; }
  void set(std::size_t i, const Vec3<S>& v) { x[i] = v[0], y[i] = v[1], z[i] = v[2]; }
};

/// sin and cos of one angle in one library call (glibc's sincos, a GNU extension of <math.h>).
inline void sin_cos(float x, float& s, float& c) { ::sincosf(x, &s, &c); }
inline void sin_cos(double x, double& s, double& c) { ::sincos(x, &s, &c); }

template <class S>
Cl3Even<S> times(const Cl3Even<S>& r, S k) { return {r.s * k, r.e23 * k, r.e31 * k, r.e12 * k}; }
template <class S>
Quat<S> quat_at(const S* q, std::size_t i) { return {q[4 * i], q[4 * i + 1], q[4 * i + 2], q[4 * i + 3]}; }
template <class S>
Vec3<S> vec_at(const S* v, std::size_t i) { return {v[3 * i], v[3 * i + 1], v[3 * i + 2]}; }

// A guard's answer is 0 (fast path) or 1 (slow path) held in the scalar type S, and guards combine
// by addition: SSE2 selects between floating-point constants under a comparison mask but not between
// 64-bit integers, and GCC vectorises a loop of doubles only with flags of the same width.

/// Whether the unscaled formulas fail |x|^2, branch-free: is_ordinary_square written with &
/// rather than &&, so that it if-converts and the loop vectorises.
template <class S>
S unusual(S norm2) {
  using Range = rotorcert::runtime::OrdinaryRange<S>;
  return ((norm2 >= Range::kLo) & (norm2 <= Range::kHi)) ? S(0) : S(1);
}

/// The filter of runtime::exact_dot_sign, whose bound 8 u s + 8 denorm_min (s = sum |a_i b_i|, any
/// order of summation) is enlarged to 16 u |a||b| + 8 denorm_min (s <= |a||b| by Cauchy-Schwarz,
/// the computed lengths within a few u of the exact ones): a dot beyond it has the sign of a.b.
/// Inside it (ties such as half turns, EDGE-3) the element takes the slow path, which decides exactly.
template <class S>
S sign_undecided(S dot, S length_a, S length_b) {
  constexpr S u = std::numeric_limits<S>::epsilon() / 2;
  const S bound = S(16) * u * (length_a * length_b) + S(8) * std::numeric_limits<S>::denorm_min();
  return std::abs(dot) > bound ? S(0) : S(1);
}

template <class S>
struct RotorGen : rotorcert::rotor::RotorOps<S, rotorcert::rotor::Method2> {
  using Base = rotorcert::rotor::RotorOps<S, rotorcert::rotor::Method2>;
  static constexpr const char* name = "rotor_gen";
  static constexpr const char* version = "1";
  static constexpr const char* description =
      "GA rotors, generated: Cl(3,0) kernels generated at build time from the reference algebra's blade "
      "tables (Gaigen/Gaalop style), rotor = Phi(q) = w - x e23 - y e31 - z e12; batched fast paths for "
      "ordinary inputs, the robust Cl(3,0) code otherwise";
  static constexpr std::uint32_t levels = rotorcert::rotor::kRotorLevels;
  static constexpr const char* const* clauses = rotorcert::rotor::kRotorClauses;
  using Flag = S;  // a guard's answer (see unusual)

  /// NORM-1: R (1 / sqrt(<R ~R>_0)): one division, not four (the reciprocal's rounding adds u/2
  /// per component, within eps4).
  ROTORCERT_TARGET_CLONES static int normalize_batch(std::size_t n, const S* q, S* out_q, std::uint8_t* status) {
    QuatBlock<S> in, result;
    Flag flags[kBlock];
    for (std::size_t first = 0; first < n; first += kBlock) {
      const std::size_t m = std::min(kBlock, n - first);
      in.load(q + 4 * first, m);
      for (std::size_t i = 0; i < m; ++i) {
        const Cl3Even<S> r = in.rotor(i);
        const S n2 = gen::cl3_norm2(r);
        flags[i] = unusual(n2);
        result.set(i, times(r, S(1) / std::sqrt(n2)));
      }
      finish_block(first, m, result, flags, out_q, status,
                   [&](std::size_t i, Quat<S>& o) { return Base::normalize(quat_at(q, i), o); });
    }
    return 0;
  }

  /// COMPOSE-1: Phi(a) Phi(b), no normalisation; |a|^2 and |b|^2 ordinary.
  ROTORCERT_TARGET_CLONES static int compose_batch(std::size_t n, const S* a, const S* b, S* out_q,
                                                 std::uint8_t* status) {
    QuatBlock<S> in_a, in_b, result;
    Flag flags[kBlock];
    for (std::size_t first = 0; first < n; first += kBlock) {
      const std::size_t m = std::min(kBlock, n - first);
      in_a.load(a + 4 * first, m);
      in_b.load(b + 4 * first, m);
      for (std::size_t i = 0; i < m; ++i) {
        const Cl3Even<S> ra = in_a.rotor(i), rb = in_b.rotor(i);
        flags[i] = unusual(gen::cl3_norm2(ra)) + unusual(gen::cl3_norm2(rb));
        result.set(i, gen::cl3_gp(ra, rb));
      }
      finish_block(first, m, result, flags, out_q, status,
                   [&](std::size_t i, Quat<S>& o) { return Base::compose(quat_at(a, i), quat_at(b, i), o); });
    }
    return 0;
  }

  /// APPLY-1: <R v ~R>_1 / <R ~R>_0. |R|^2 and |v|^2 ordinary: every term of the sandwich is then
  /// within 2^+-3W of |R|^2 |v|, so nothing overflows and what underflows is negligible (v = 0
  /// takes the slow path, which returns it exactly).
  ROTORCERT_TARGET_CLONES static int apply_vector_batch(std::size_t n, const S* q, const S* v, S* out_v,
                                                      std::uint8_t* status) {
    QuatBlock<S> in_q;
    VecBlock<S> in_v, result;
    Flag flags[kBlock];
    for (std::size_t first = 0; first < n; first += kBlock) {
      const std::size_t m = std::min(kBlock, n - first);
      in_q.load(q + 4 * first, m);
      in_v.load(v + 3 * first, m);
      for (std::size_t i = 0; i < m; ++i) {
        const Cl3Even<S> r = in_q.rotor(i);
        const Cl3Vector<S> x = in_v.vector(i);
        const S n2 = gen::cl3_norm2(r);
        flags[i] = unusual(n2) + unusual(x.e1 * x.e1 + x.e2 * x.e2 + x.e3 * x.e3);
        const Cl3Vector<S> y = gen::cl3_sandwich_vector(r, x);
        const S inv = S(1) / n2;
        result.set(i, Cl3Vector<S>{y.e1 * inv, y.e2 * inv, y.e3 * inv});
      }
      finish_block(first, m, result, flags, out_v, status, [&](std::size_t i, Vec3<S>& o) {
        return Base::apply_vector(quat_at(q, i), vec_at(v, i), o);
      });
    }
    return 0;
  }

  /// NLERP-1: R_A/|R_A| + t (R_B'/|R_B| - R_A/|R_A|), normalised; R_B' = -R_B iff a.b < 0. The fast
  /// path also asks |t| <= 2^16 (so the sum cannot overflow and needs no 1/max(1, |t|) scaling)
  /// and a decided hemisphere; R_A = R_B' gives R_A exactly (EDGE-1).
  ROTORCERT_TARGET_CLONES static int nlerp_batch(std::size_t n, const S* a, const S* b, const S* t, S* out_q,
                                               std::uint8_t* status) {
    QuatBlock<S> in_a, in_b, result;
    Flag flags[kBlock];
    for (std::size_t first = 0; first < n; first += kBlock) {
      const std::size_t m = std::min(kBlock, n - first);
      in_a.load(a + 4 * first, m);
      in_b.load(b + 4 * first, m);
      const S* tb = t + first;
      for (std::size_t i = 0; i < m; ++i) {
        const Cl3Even<S> ra = in_a.rotor(i), rb = in_b.rotor(i);
        const S ti = tb[i];
        const S na2 = gen::cl3_norm2(ra), nb2 = gen::cl3_norm2(rb);
        const S la = std::sqrt(na2), lb = std::sqrt(nb2);
        const S dot = gen::cl3_scalar_product(rb, ra);  // a.b as given
        const Flag flag = unusual(na2) + unusual(nb2) + sign_undecided(dot, la, lb) +
                          (std::abs(ti) <= kMaxFastT ? S(0) : S(1));
        const Cl3Even<S> ua = times(ra, S(1) / la), ub = times(rb, (dot < 0 ? S(-1) : S(1)) / lb);
        const Cl3Even<S> sum{ua.s + ti * (ub.s - ua.s), ua.e23 + ti * (ub.e23 - ua.e23),
                             ua.e31 + ti * (ub.e31 - ua.e31), ua.e12 + ti * (ub.e12 - ua.e12)};
        const S ns2 = gen::cl3_norm2(sum);
        flags[i] = flag + unusual(ns2);
        result.set(i, times(sum, S(1) / std::sqrt(ns2)));
      }
      finish_block(first, m, result, flags, out_q, status, [&](std::size_t i, Quat<S>& o) {
        return Base::nlerp(quat_at(a, i), quat_at(b, i), t[i], o);
      });
    }
    return 0;
  }

  /// SLERP-2: D = R_B' ~R_A (R_B' = -R_B iff a.b < 0, SLERP-1), log D = theta B/|B| for D = s + B,
  /// then exp(t log D) R_A = (cos(t theta) + sin(t theta) B/|B|) R_A. The angle is atan2(|B|, s),
  /// never acos (SLERP-1); the fast path asks s > 0 (the aligned hemisphere makes s >= 0, and s = 0
  /// is a right angle the slow path takes) and computes it as atan(|B|/s), the same function for
  /// s > 0 and a cheaper library call. Pass 1 does the algebra up to log D (vectorised), pass 2 the
  /// library's atan and sincos (scalar calls), pass 3 exp and the product. |B|^2 ordinary in the
  /// fast path: D = +-1 (B = 0, e.g. R_A = R_B', EDGE-1) takes the slow path, which returns R_A
  /// exactly.
  ROTORCERT_TARGET_CLONES static int slerp_batch(std::size_t n, const S* a, const S* b, const S* t, S* out_q,
                                               std::uint8_t* status) {
    QuatBlock<S> in_a, in_b, unit_a, result;
    // Per element: |B|/s of D, the unit bivector B/|B|, then cos and sin of t theta.
    S tan_theta[kBlock], u_23[kBlock], u_31[kBlock], u_12[kBlock], cos_ta[kBlock], sin_ta[kBlock];
    Flag flags[kBlock];
    for (std::size_t first = 0; first < n; first += kBlock) {
      const std::size_t m = std::min(kBlock, n - first);
      in_a.load(a + 4 * first, m);
      in_b.load(b + 4 * first, m);
      const S* tb = t + first;
      for (std::size_t i = 0; i < m; ++i) {
        const Cl3Even<S> qa = in_a.rotor(i), qb = in_b.rotor(i);
        const S na2 = gen::cl3_norm2(qa), nb2 = gen::cl3_norm2(qb);
        const S la = std::sqrt(na2), lb = std::sqrt(nb2);
        const S dot = gen::cl3_scalar_product(qb, qa);
        const Cl3Even<S> ua = times(qa, S(1) / la), ub = times(qb, (dot < 0 ? S(-1) : S(1)) / lb);
        const Cl3Even<S> d = gen::cl3_gp(ub, gen::cl3_reverse(ua));
        const S bivector2 = d.e23 * d.e23 + d.e31 * d.e31 + d.e12 * d.e12;
        flags[i] = unusual(na2) + unusual(nb2) + sign_undecided(dot, la, lb) + unusual(bivector2) +
                   (d.s > 0 ? S(0) : S(1)) + (tb[i] - tb[i] == 0 ? S(0) : S(1));  // s > 0, t finite
        const S len = std::sqrt(bivector2), inv = S(1) / len;
        unit_a.set(i, ua);
        tan_theta[i] = len / d.s;
        u_23[i] = d.e23 * inv, u_31[i] = d.e31 * inv, u_12[i] = d.e12 * inv;
      }
      for (std::size_t i = 0; i < m; ++i) {
        sin_cos(tb[i] * std::atan(tan_theta[i]), sin_ta[i], cos_ta[i]);
      }
      for (std::size_t i = 0; i < m; ++i) {
        const Cl3Even<S> e{cos_ta[i], sin_ta[i] * u_23[i], sin_ta[i] * u_31[i], sin_ta[i] * u_12[i]};
        result.set(i, gen::cl3_gp(e, unit_a.rotor(i)));
      }
      finish_block(first, m, result, flags, out_q, status, [&](std::size_t i, Quat<S>& o) {
        return Base::slerp(quat_at(a, i), quat_at(b, i), t[i], o);
      });
    }
    return 0;
  }

 private:
  static constexpr S kMaxFastT = S(65536);

  /// Ends a block: the fast results become the outputs (status OK) except where pass 1's flag says
  /// the element's guard failed; those are recomputed first by `slow_path(i, out)` (i counted from
  /// the batch start, returning the RotorOps status), before any output is written, so an output
  /// array that is also an input array still reads as an input. On DOMAIN_ERROR every output
  /// component is a quiet NaN (impl.hpp's rule).
  template <class Block, class SlowPath>
  static void finish_block(std::size_t first, std::size_t m, Block& result, const Flag* flags, S* out,
                           std::uint8_t* status, SlowPath slow_path) {
    Flag any = 0;
    for (std::size_t i = 0; i < m; ++i) any += flags[i];  // a count of failed guards, exact
    std::uint8_t block_status[kBlock];
    std::memset(block_status, RC_OK, m);
    if (any != 0) {
      for (std::size_t i = 0; i < m; ++i) {
        if (flags[i] == 0) continue;
        using Out = std::conditional_t<std::is_same_v<Block, QuatBlock<S>>, Quat<S>, Vec3<S>>;
        Out o;
        const Status s = slow_path(first + i, o);
        if (s != Status::ok) o.fill(std::numeric_limits<S>::quiet_NaN());
        result.set(i, o);
        block_status[i] = static_cast<std::uint8_t>(s);
      }
    }
    constexpr std::size_t width = std::is_same_v<Block, QuatBlock<S>> ? 4 : 3;
    result.store(out + width * first, m);
    std::memcpy(status + first, block_status, m);
  }
};

}  // namespace

ROTORCERT_DEFINE_ENTRY(rotor_gen, RotorGen<float>, RotorGen<double>)
