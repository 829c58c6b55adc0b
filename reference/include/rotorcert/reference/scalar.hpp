// Scalar types of the reference.
//
// The reference is generic over its scalar type. Two instantiations matter:
//   Real   = mpfr::mpreal at >= 256 bits: the oracle that defines expected results (NUM-2);
//   double : the same textbook code in binary64, used to show how far naive double drifts.
// Everything below uses unqualified sqrt/sin/cos/atan2/... so that argument-dependent lookup
// picks MPFR's correctly rounded functions for mpreal and <cmath> for double.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <mpreal.h>

namespace rotorcert::ref {

using Real = mpfr::mpreal;

/// NUM-2: the reference works with at least this many significand bits.
inline constexpr int kReferenceBits = 256;

/// Sets the default MPFR precision for every Real created afterwards on this thread.
/// Call once at start-up (tests do it in a global environment, tools in main()).
inline void use_reference_precision(int bits = kReferenceBits) {
  mpfr::mpreal::set_default_prec(bits);
}

template <class T> struct ScalarTraits;

template <> struct ScalarTraits<double> {
  static double pi() { return 3.14159265358979323846264338327950288; }
  static double nan() { return std::numeric_limits<double>::quiet_NaN(); }
  static bool is_nan(double x) { return std::isnan(x); }
  static bool is_finite(double x) { return std::isfinite(x); }
  static double from_double(double x) { return x; }
  static double to_double(double x) { return x; }
  /// Smallest relative step that this type resolves: the unit for "exact" identities.
  static double epsilon() { return std::numeric_limits<double>::epsilon(); }
};

/// long double: the unverified first step of a verified computation (bounded_from_matrix.hpp).
template <> struct ScalarTraits<long double> {
  static long double pi() { return 3.14159265358979323846264338327950288L; }
  static long double nan() { return std::numeric_limits<long double>::quiet_NaN(); }
  static bool is_nan(long double x) { return std::isnan(x); }
  static bool is_finite(long double x) { return std::isfinite(x); }
  static long double from_double(double x) { return x; }
  static double to_double(long double x) { return static_cast<double>(x); }
  static long double epsilon() { return std::numeric_limits<long double>::epsilon(); }
};

template <> struct ScalarTraits<Real> {
  static Real pi() { return mpfr::const_pi(); }
  static Real nan() { Real x; mpfr_set_nan(x.mpfr_ptr()); return x; }
  static bool is_nan(const Real& x) { return mpfr::isnan(x); }
  static bool is_finite(const Real& x) { return mpfr::isfinite(x); }
  static Real from_double(double x) { return Real(x); }  // exact: precision >= 53
  static double to_double(const Real& x) { return x.toDouble(); }
  static Real epsilon() { return mpfr::machine_epsilon(); }
};

/// Whether a multivector coefficient is 0, so that its blade is absent from a product
/// (multivector.hpp). ref::Bounded has its own: an interval around 0 is not absent there.
template <class T>
bool is_absent(const T& x) { return x == 0; }

/// The largest of |x|, |y|, ...: a scale factor of the overflow-free normalisations. Taken with
/// max, never with comparisons: in the fuzzers' interval arithmetic (ref::Bounded) two nearly equal
/// magnitudes leave a comparison undecided, while max is continuous and needs no branch. Any of the
/// magnitudes would do as the scale; for exact arithmetic this is the plain maximum.
template <class T, class... Rest>
T largest_magnitude(const T& x, const Rest&... rest) {
  using std::abs;
  using std::max;
  T m = abs(x);
  ((m = max(m, T(abs(rest)))), ...);
  return m;
}

}  // namespace rotorcert::ref
