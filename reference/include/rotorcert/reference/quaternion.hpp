// Hamilton quaternions as plain numbers (QUAT-1), independent of the GA code on purpose:
// the homomorphism clause Q2R-2 is tested by comparing this hand-written product with the
// geometric product under the map of cl3.hpp.
//
// Layout (LAYOUT-1): in arrays a quaternion is [x, y, z, w]; this struct names the fields.
#pragma once

#include <array>

#include "scalar.hpp"

namespace rotorcert::ref {

template <class T>
struct Quaternion {
  T w{0}, x{0}, y{0}, z{0};

  static Quaternion identity() { return {T(1), T(0), T(0), T(0)}; }
  /// From the ABI order [x, y, z, w].
  static Quaternion from_xyzw(const std::array<T, 4>& a) { return {a[3], a[0], a[1], a[2]}; }
  std::array<T, 4> xyzw() const { return {x, y, z, w}; }
};

/// Hamilton product with i^2 = j^2 = k^2 = ijk = -1.
template <class T>
Quaternion<T> operator*(const Quaternion<T>& a, const Quaternion<T>& b) {
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
          a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
          a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}
template <class T>
Quaternion<T> operator+(const Quaternion<T>& a, const Quaternion<T>& b) {
  return {a.w + b.w, a.x + b.x, a.y + b.y, a.z + b.z};
}
template <class T>
Quaternion<T> operator-(const Quaternion<T>& a, const Quaternion<T>& b) {
  return {a.w - b.w, a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class T>
Quaternion<T> operator-(const Quaternion<T>& a) { return {-a.w, -a.x, -a.y, -a.z}; }
template <class T>
Quaternion<T> operator*(const T& s, const Quaternion<T>& a) { return {s * a.w, s * a.x, s * a.y, s * a.z}; }

template <class T>
Quaternion<T> conj(const Quaternion<T>& a) { return {a.w, -a.x, -a.y, -a.z}; }

template <class T>
T dot(const Quaternion<T>& a, const Quaternion<T>& b) { return a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z; }

/// The sign (-1, 0, +1) of a.b as the hemisphere rules use it (SLERP-1, EDGE-3: flip iff the dot
/// is < 0 strictly). For Real it is decided exactly: the four products and their sum are formed at
/// a precision that holds them exactly for any inputs of binary64 range, so a tie (a.b = 0 in exact
/// arithmetic) is never turned into a flip by rounding. Decide it on the inputs as given, before
/// any normalisation rounds them. For double it is the sign of the rounded dot.
inline int hemisphere_sign(const Quaternion<Real>& a, const Quaternion<Real>& b) {
  constexpr mpfr_prec_t exact_bits = 2 * kReferenceBits + 4400;  // products, and 2^-2200..2^2100 spread
  Real sum(0, exact_bits), product(0, exact_bits);
  const Real* pa[4] = {&a.w, &a.x, &a.y, &a.z};
  const Real* pb[4] = {&b.w, &b.x, &b.y, &b.z};
  for (int i = 0; i < 4; ++i) {
    mpfr_mul(product.mpfr_ptr(), pa[i]->mpfr_srcptr(), pb[i]->mpfr_srcptr(), MPFR_RNDN);
    mpfr_add(sum.mpfr_ptr(), sum.mpfr_srcptr(), product.mpfr_srcptr(), MPFR_RNDN);
  }
  return mpfr_sgn(sum.mpfr_srcptr());
}
inline int hemisphere_sign(const Quaternion<double>& a, const Quaternion<double>& b) {
  const double d = a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
  return (d > 0) - (d < 0);
}

template <class T>
T norm(const Quaternion<T>& a) {
  using std::sqrt;
  return sqrt(dot(a, a));
}

}  // namespace rotorcert::ref
