// Bounded: the fast scalar of the two-level oracle (fuzz/README.md, "The fast oracle").
//
// A Bounded is an x87 extended-precision value v (64-bit significand, unit roundoff u = 2^-64)
// with a rigorous bound e on its distance from the exact real number that the same formula gives
// on the same (exact) inputs: |exact - v| <= e. The reference's clause templates run on it
// unchanged, as they run on mpfr::mpreal, so the fast answer is the reference's own formula.
//
// Rules (running error analysis, Higham, "Accuracy and Stability of Numerical Algorithms",
// 2nd ed., sec. 3.3):
//   - +, -, *, / and sqrt are correctly rounded (IEEE 754): the rounding adds u|v|.
//   - sin, cos, exp, log, atan2, acos, asin, hypot of glibc's long double libm: within kLibmUlps
//     ulp (2 u|v| each); glibc's tables of known errors list at most 3 ulp for these on x86-64,
//     and the agreement test (fuzz/test_fast_oracle.cpp) checks every bound against MPFR.
//   - each propagated bound is computed in round-to-nearest and then inflated by (1 + 16u), and
//     every operation adds kTiny (underflow is absolute, not relative).
// Whatever the rules cannot bound is *undecided*: a comparison whose operands' intervals overlap
// (a branch the exact computation might take the other way), a division by an interval holding 0,
// a square root or log of an interval reaching below 0, atan2 across its branch cut, a result
// that overflows, the type's epsilon (a series' truncation is not a rounding error). Each such
// event counts in BoundedScope; a caller that sees one discards the fast answer and asks MPFR.
#pragma once

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "quaternion.hpp"
#include "scalar.hpp"

namespace rotorcert::ref {

class Bounded {
 public:
  using F = long double;
  static constexpr F kU = LDBL_EPSILON / 2;  // 2^-64
  /// What every operation adds for underflow: the smallest *normal* long double. The smallest
  /// subnormal would bound it too, but x87 arithmetic on a subnormal operand takes a microcode
  /// assist (over a hundred cycles), and adding it to every bound was 80 % of a geometric
  /// product's time; a larger addend only widens the bound, by 2^-16382.
  static constexpr F kTiny = std::numeric_limits<F>::min();
  static constexpr F kLibmUlps = 4;

  Bounded() = default;
  Bounded(int x) : v_(x), nonneg_(x >= 0) {}        // NOLINT: exact, as mpreal's
  Bounded(double x) : v_(x), nonneg_(x >= 0) {}     // NOLINT: exact
  Bounded(F v, F e, bool nonneg = false) : v_(v), e_(e), nonneg_(nonneg || (e == 0 && v >= 0)) {}

  F value() const { return v_; }
  F bound() const { return e_; }
  bool exact() const { return e_ == 0; }
  /// Whether the exact value is known to be >= 0 (a square, a sum of such, an abs, a sqrt), so a
  /// square root of an interval reaching below 0 is still decided.
  bool nonneg() const { return nonneg_; }

  /// Counts the undecided events of this thread (see the file comment).
  static int& undecided() {
    static thread_local int n = 0;
    return n;
  }
  static void undecide() { ++undecided(); }

  /// A result v of an operation on finite operands whose propagated bound is `e`, plus the
  /// rounding `ulps_of_v` of v. An overflow is undecided.
  static Bounded result(F v, F e, F ulps_of_v) {
    if (!std::isfinite(v) || !std::isfinite(e)) {
      undecide();
      return {v, 0};
    }
    return {v, (e + ulps_of_v * 2 * kU * std::fabs(v)) * (1 + 16 * kU) + kTiny};
  }

  friend Bounded operator-(const Bounded& a) { return {-a.v_, a.e_}; }
  friend Bounded operator+(const Bounded& a, const Bounded& b) {
    const F v = a.v_ + b.v_;
    if (!std::isfinite(a.v_) || !std::isfinite(b.v_)) return {v, 0};  // exact specials: IEEE's answer
    if (a.exact() && b.exact() && exact_sum(a.v_, b.v_, v)) return {v, 0};
    Bounded r = result(v, a.e_ + b.e_, 0.5L);
    r.nonneg_ = a.nonneg_ && b.nonneg_;
    return r;
  }
  friend Bounded operator-(const Bounded& a, const Bounded& b) { return a + (-b); }
  friend Bounded operator*(const Bounded& a, const Bounded& b) {
    const F v = a.v_ * b.v_;
    if (!std::isfinite(a.v_) || !std::isfinite(b.v_)) {
      // An infinity times a factor that may be 0: NaN or an infinity, as the exact factor decides.
      if (may_be_zero(a) || may_be_zero(b)) undecide();
      return {v, 0};
    }
    // A zero factor is exact; other products carry their rounding (fmal, which would tell an exact
    // product, is software on x86-64 and costs more than it saves), except a scaling by an exact
    // power of two (2 atan2(...), t / 2): exact unless it leaves the normal range, its bound scaled.
    if ((a.exact() && a.v_ == 0) || (b.exact() && b.v_ == 0)) return {v, 0};
    if (b.exact() && power_of_two(b.v_)) {
      if (const auto r = scaled(a, b, v)) return *r;
    } else if (a.exact() && power_of_two(a.v_)) {
      if (const auto r = scaled(b, a, v)) return *r;
    }
    Bounded r = result(v, std::fabs(a.v_) * b.e_ + std::fabs(b.v_) * a.e_ + a.e_ * b.e_, 0.5L);
    r.nonneg_ = &a == &b || (a.nonneg_ && b.nonneg_);  // x * x of one object is a square
    return r;
  }
  friend Bounded operator/(const Bounded& a, const Bounded& b) {
    const F v = a.v_ / b.v_;
    const F bb = std::fabs(b.v_);
    if (!std::isfinite(a.v_) || !std::isfinite(b.v_)) return {v, 0};
    // Halving an angle is exact: without this a huge exact angle's half carried a rounding of its
    // own size, and every sine and cosine of it a bound wider than 1 (rotate_about_axis).
    if (b.exact() && power_of_two(b.v_) && a.v_ != 0) {
      if (const auto r = scaled(a, Bounded(1 / b.v_, 0), v)) return *r;
    }
    if (a.exact() && b.exact()) {
      if (bb == 0 || a.v_ == 0) return {v, 0};  // IEEE's exact answers (0, infinity, NaN), as MPFR's
      return result(v, 0, 0.5L);
    }
    if (bb <= b.e_ * (1 + 4 * kU)) {
      undecide();
      return {v, 0};
    }
    if (a.exact() && a.v_ == 0) return {v, 0};  // 0 / (surely nonzero) = 0
    const F e = (std::fabs(a.v_) * b.e_ + bb * a.e_) / (bb * (bb - b.e_ * (1 + 4 * kU)));
    return result(v, e, 0.5L);
  }
  Bounded& operator+=(const Bounded& b) { return *this = *this + b; }
  Bounded& operator-=(const Bounded& b) { return *this = *this - b; }
  Bounded& operator*=(const Bounded& b) { return *this = *this * b; }
  Bounded& operator/=(const Bounded& b) { return *this = *this / b; }

  /// -1, 0, +1: the sign of exact(a) - exact(b); decided = false when the intervals overlap.
  static int order(const Bounded& a, const Bounded& b, bool& decided) {
    decided = true;
    if (std::isnan(a.v_) || std::isnan(b.v_)) return 2;  // unordered, exactly (NaN inputs are exact)
    if (a.exact() && b.exact()) return a.v_ < b.v_ ? -1 : (a.v_ > b.v_ ? 1 : 0);
    const F gap = std::fabs(a.v_ - b.v_) * (1 - 4 * kU);
    if (gap > (a.e_ + b.e_) * (1 + 4 * kU)) return a.v_ < b.v_ ? -1 : 1;
    decided = false;
    return a.v_ < b.v_ ? -1 : (a.v_ > b.v_ ? 1 : 0);
  }
  static int order(const Bounded& a, const Bounded& b) {
    bool decided;
    const int o = order(a, b, decided);
    if (!decided) undecide();
    return o;
  }
  friend bool operator<(const Bounded& a, const Bounded& b) { return order(a, b) == -1; }
  friend bool operator>(const Bounded& a, const Bounded& b) { return order(a, b) == 1; }
  friend bool operator<=(const Bounded& a, const Bounded& b) { const int o = order(a, b); return o == -1 || o == 0; }
  friend bool operator>=(const Bounded& a, const Bounded& b) { const int o = order(a, b); return o == 1 || o == 0; }
  friend bool operator==(const Bounded& a, const Bounded& b) { return order(a, b) == 0; }
  friend bool operator!=(const Bounded& a, const Bounded& b) { return order(a, b) != 0; }

 private:
  /// Whether the exact value may be 0 without being known to be: a finite, inexact interval that
  /// holds 0.
  static bool may_be_zero(const Bounded& x) {
    return std::isfinite(x.v_) && !x.exact() && std::fabs(x.v_) <= x.e_ * (1 + 4 * kU);
  }
  /// Whether x is +-2^k (a finite nonzero value with significand 1).
  static bool power_of_two(F x) {
    int e;
    return std::isfinite(x) && x != 0 && std::fabs(std::frexp(x, &e)) == F(0.5);
  }
  /// x times the exact power of two `p`, whose value is v: exact where v is normal and finite (no
  /// bits lost), with x's bound scaled by |p| (plus kTiny, where that product may have underflowed).
  /// nullopt where v left the normal range: the caller rounds it as any other product.
  static std::optional<Bounded> scaled(const Bounded& x, const Bounded& p, F v) {
    if (!std::isfinite(v) || std::fabs(v) < LDBL_MIN) return std::nullopt;
    const F e = x.e_ * std::fabs(p.v_);
    if (!std::isfinite(e)) return std::nullopt;
    return Bounded(v, e == 0 ? F(0) : e + kTiny, x.nonneg_ && p.v_ > 0);
  }
  /// Whether a + b == v exactly (Knuth's TwoSum error is zero; a sum never underflows inexactly).
  static bool exact_sum(F a, F b, F v) {
    if (!std::isfinite(v)) return false;
    const F bv = v - a, av = v - bv;
    return (a - av) + (b - bv) == 0;
  }

  F v_ = 0;
  F e_ = 0;
  bool nonneg_ = true;  // of the default 0
};

// ---- functions found by argument-dependent lookup, as mpreal's are ----

/// A coefficient is absent from a product (multivector.hpp) only when it is exactly 0. One whose
/// interval merely holds 0 is multiplied out: with a finite partner its product's interval holds
/// the 0 that skipping it would give, and with an infinite one operator* is undecided.
inline bool is_absent(const Bounded& x) { return x.exact() && x.value() == 0; }

inline Bounded abs(const Bounded& x) { return {std::fabs(x.value()), x.bound(), true}; }
inline Bounded fabs(const Bounded& x) { return abs(x); }
inline bool isnan(const Bounded& x) { return std::isnan(x.value()); }
inline bool isfinite(const Bounded& x) { return std::isfinite(x.value()); }
inline Bounded max(const Bounded& a, const Bounded& b) {  // 1-Lipschitz: no branch to decide
  return {std::max(a.value(), b.value()), std::max(a.bound(), b.bound())};
}
inline Bounded min(const Bounded& a, const Bounded& b) {
  return {std::min(a.value(), b.value()), std::max(a.bound(), b.bound())};
}
inline Bounded ldexp(const Bounded& x, int n) {
  const Bounded::F v = std::ldexp(x.value(), n);
  const bool exact_scale = v == 0 ? x.value() == 0 : std::fabs(v) >= LDBL_MIN && std::isfinite(v);
  if (x.exact() && exact_scale) return {v, 0};
  return Bounded::result(v, std::ldexp(x.bound(), n), exact_scale ? 0 : 0.5L);
}

inline Bounded sqrt(const Bounded& x) {
  using F = Bounded::F;
  const F r = std::sqrt(x.value());
  if (!std::isfinite(x.value()) || (x.exact() && x.value() < 0)) return {r, 0};  // exact specials: IEEE answers
  if (x.exact()) {
    if (x.value() == 0 || x.value() == 1) return {r, 0};
    const Bounded y = Bounded::result(r, 0, 0.5L);
    return {y.value(), y.bound(), true};
  }
  const F lo = x.value() - x.bound() * (1 + 4 * Bounded::kU);
  if (lo <= 0) {
    // Near 0 the root is not Lipschitz: of a radicand known to be >= 0, the exact root lies in
    // [0, sqrt(v + e)]; of any other, it may be undefined.
    if (!x.nonneg()) {
      Bounded::undecide();
      return {r, 0};
    }
    const F v = std::sqrt(std::max(x.value(), F(0)));
    Bounded y = Bounded::result(v, std::sqrt(x.value() + x.bound()) * (1 + 4 * Bounded::kU), 0.5L);
    return {y.value(), y.bound(), true};
  }
  const Bounded y = Bounded::result(r, x.bound() / (std::sqrt(lo) + r), 0.5L);
  return {y.value(), y.bound(), true};
}
inline Bounded sin(const Bounded& x) {
  return Bounded::result(std::sin(x.value()), x.bound(), Bounded::kLibmUlps);
}
inline Bounded cos(const Bounded& x) {
  return Bounded::result(std::cos(x.value()), x.bound(), Bounded::kLibmUlps);
}
inline Bounded exp(const Bounded& x) {
  using F = Bounded::F;
  const F r = std::exp(x.value());
  return Bounded::result(r, r * std::expm1(x.bound() * (1 + 4 * Bounded::kU)), Bounded::kLibmUlps);
}
inline Bounded log(const Bounded& x) {
  using F = Bounded::F;
  const F r = std::log(x.value());
  if (x.exact()) return x.value() > 0 ? Bounded::result(r, 0, Bounded::kLibmUlps) : Bounded(r, 0);
  const F lo = x.value() - x.bound() * (1 + 4 * Bounded::kU);
  if (!(lo > 0)) {
    Bounded::undecide();
    return {r, 0};
  }
  return Bounded::result(r, x.bound() / lo, Bounded::kLibmUlps);
}
inline Bounded hypot(const Bounded& x, const Bounded& y) {
  return Bounded::result(std::hypot(x.value(), y.value()), x.bound() + y.bound(), Bounded::kLibmUlps);
}
/// atan2 is Lipschitz with constant 1/r away from the origin, and jumps by 2 pi across the
/// negative x axis: both are undecided when the inputs' box reaches them.
inline Bounded atan2(const Bounded& y, const Bounded& x) {
  using F = Bounded::F;
  const F r = std::atan2(y.value(), x.value());
  if (!std::isfinite(x.value()) || !std::isfinite(y.value())) return {r, 0};
  if (x.exact() && y.exact()) {
    if (y.value() == 0 && !std::signbit(x.value())) return {r, 0};  // atan2(+-0, x >= +0) = +-0
    return Bounded::result(r, 0, Bounded::kLibmUlps);
  }
  const F spread = (x.bound() + y.bound()) * (1 + 4 * Bounded::kU);
  const F radius = std::hypot(x.value(), y.value()) * (1 - 8 * Bounded::kU) - spread;
  const bool may_cross_cut = x.value() - x.bound() <= 0 && std::fabs(y.value()) <= y.bound();
  if (!(radius > 0) || may_cross_cut) {
    Bounded::undecide();
    return {r, 0};
  }
  return Bounded::result(r, spread / radius, Bounded::kLibmUlps);
}
inline Bounded acos(const Bounded& x) {
  using F = Bounded::F;
  const F r = std::acos(x.value());
  if (x.exact()) return Bounded::result(r, 0, Bounded::kLibmUlps);
  const F reach = std::fabs(x.value()) + x.bound() * (1 + 4 * Bounded::kU);
  if (!(reach < 1)) {  // the derivative 1/sqrt(1 - x^2) is unbounded at +-1
    Bounded::undecide();
    return {r, 0};
  }
  return Bounded::result(r, x.bound() / std::sqrt((1 - reach) * (1 + reach) * (1 - 8 * Bounded::kU)),
                         Bounded::kLibmUlps);
}
inline Bounded asin(const Bounded& x) {
  const Bounded c = acos(x);  // asin = pi/2 - acos, with acos's bound
  return Bounded::result(std::asin(x.value()), c.bound(), Bounded::kLibmUlps);
}
inline Bounded tan(const Bounded& x) {
  using F = Bounded::F;
  const F r = std::tan(x.value());
  if (x.exact()) return Bounded::result(r, 0, Bounded::kLibmUlps);
  Bounded::undecide();  // not needed by any fast-pathed op; not worth a bound
  return {r, 0};
}

template <> struct ScalarTraits<Bounded> {
  static Bounded pi() { return {std::numbers::pi_v<long double>, 2 * Bounded::kU * 4}; }
  static Bounded nan() { return {std::numeric_limits<long double>::quiet_NaN(), 0}; }
  static bool is_nan(const Bounded& x) { return std::isnan(x.value()); }
  static bool is_finite(const Bounded& x) { return std::isfinite(x.value()); }
  static Bounded from_double(double x) { return Bounded(x); }
  static double to_double(const Bounded& x) { return static_cast<double>(x.value()); }
  /// A series or iteration that stops at the type's epsilon has a truncation error the bound
  /// does not carry: undecided, so MPFR answers.
  static Bounded epsilon() {
    Bounded::undecide();
    return Bounded(static_cast<double>(LDBL_EPSILON));
  }
};

/// The hemisphere rule's sign (quaternion.hpp) on Bounded inputs: the dot's sign where its bound
/// decides it, else undecided (a tie, a.b = 0, is MPFR's to decide exactly).
inline int hemisphere_sign(const Quaternion<Bounded>& a, const Quaternion<Bounded>& b) {
  return Bounded::order(dot(a, b), Bounded(0));
}

/// is_zero (result.hpp) of a Bounded quaternion: decided by any component surely nonzero, before
/// a component near 0 could leave it undecided (a half turn has w = 0 +- its bound).
inline bool is_zero(const Quaternion<Bounded>& q) {
  const Bounded* c[4] = {&q.w, &q.x, &q.y, &q.z};
  for (const Bounded* x : c)
    if (std::fabs(x->value()) > x->bound() * (1 + 4 * Bounded::kU)) return false;
  for (const Bounded* x : c)
    if (!(x->exact() && x->value() == 0)) {
      Bounded::undecide();
      return false;
    }
  return true;
}

/// Counts the undecided events of a fast evaluation: decided() is false when the fast answer must
/// not be used.
class BoundedScope {
 public:
  BoundedScope() : start_(Bounded::undecided()) {}
  bool decided() const { return Bounded::undecided() == start_; }

 private:
  int start_;
};

}  // namespace rotorcert::ref
