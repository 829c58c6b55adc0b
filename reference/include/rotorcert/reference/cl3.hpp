// Cl(3,0): vectors, bivectors, rotors, and the quaternion view (ALG-1, ALG-5, ALG-6, Q2R-1).
//
// Bitmaps: e1 = 1, e2 = 2, e3 = 4, e12 = 3, e13 = 5, e23 = 6, e123 = 7.
// The spec names the bivector basis e23, e31, e12 (cyclic), so e31 = -e13 is read and written
// with a sign here and nowhere else.
#pragma once

#include <array>

#include "multivector.hpp"
#include "quaternion.hpp"

namespace rotorcert::ref::cl3 {

template <class T> using MV = Multivector<Cl3, T>;

inline constexpr Bitmap kE1 = 1, kE2 = 2, kE3 = 4, kE12 = 3, kE13 = 5, kE23 = 6, kE123 = 7;

template <class T> T e23(const MV<T>& m) { return m.c[kE23]; }
template <class T> T e31(const MV<T>& m) { return -m.c[kE13]; }
template <class T> T e12(const MV<T>& m) { return m.c[kE12]; }

/// x e1 + y e2 + z e3.
template <class T>
MV<T> vector(const std::array<T, 3>& v) {
  MV<T> m;
  m.c[kE1] = v[0];
  m.c[kE2] = v[1];
  m.c[kE3] = v[2];
  return m;
}
template <class T>
std::array<T, 3> vector_part(const MV<T>& m) { return {m.c[kE1], m.c[kE2], m.c[kE3]}; }

/// b23 e23 + b31 e31 + b12 e12 (LAYOUT-1 bivector order).
template <class T>
MV<T> bivector(const std::array<T, 3>& b) {
  MV<T> m;
  m.c[kE23] = b[0];
  m.c[kE13] = -b[1];
  m.c[kE12] = b[2];
  return m;
}
template <class T>
std::array<T, 3> bivector_part(const MV<T>& m) { return {e23(m), e31(m), e12(m)}; }

/// I = e123 (ALG-5).
template <class T> MV<T> I() { return MV<T>::blade(kE123); }

/// Dual A* = A lc I^-1 (Dorst, Fontijne & Mann). I^-1 = -I in Cl(3,0).
template <class T> MV<T> dual(const MV<T>& a) { return lc(a, -I<T>()); }
/// Undual A lc I, the inverse of dual.
template <class T> MV<T> undual(const MV<T>& a) { return lc(a, I<T>()); }

/// Q2R-1: Phi(q) = w - x e23 - y e31 - z e12.
template <class T>
MV<T> rotor_from_quaternion(const Quaternion<T>& q) {
  MV<T> r;
  r.c[0] = q.w;
  r.c[kE23] = -q.x;
  r.c[kE13] = q.y;  // -y e31 = +y e13
  r.c[kE12] = -q.z;
  return r;
}

/// Q2R-1, inverse map: w = <R>0, x = -R_e23, y = -R_e31, z = -R_e12. Odd grades are ignored.
template <class T>
Quaternion<T> quaternion_from_rotor(const MV<T>& r) {
  return {r.c[0], -e23(r), -e31(r), -e12(r)};
}

/// Sandwich R x ~R (ALG-6), divided by R ~R so that a non-unit R acts as R/|R|.
template <class T>
MV<T> sandwich(const MV<T>& r, const MV<T>& x) {
  return gp(gp(r, x), reverse(r)) / gp(r, reverse(r)).c[0];
}

/// |b| of a 3-vector of coefficients, scaled by the largest |component| so that it neither
/// underflows (subnormal angles) nor overflows in binary64.
template <class T>
T norm3(const std::array<T, 3>& b) {
  using std::abs;
  using std::max;
  using std::sqrt;
  const T m = max(max(abs(b[0]), abs(b[1])), abs(b[2]));
  if (m == 0) return T(0);
  const T x = b[0] / m, y = b[1] / m, z = b[2] / m;
  return m * sqrt(x * x + y * y + z * z);
}

/// EXP-1: exp(B) = cos|B| + B sin|B|/|B| for a bivector B, with exp(0) = 1 exactly.
template <class T>
MV<T> exp_bivector(const std::array<T, 3>& b) {
  using std::cos;
  using std::sin;
  const T angle = norm3(b);
  if (angle == 0) return MV<T>(T(1));
  const T s = sin(angle) / angle;  // MPFR's sin is correctly rounded: no cancellation here
  MV<T> r = bivector<T>({s * b[0], s * b[1], s * b[2]});
  r.c[0] = cos(angle);
  return r;
}

/// LOG-1, LOG-2: principal log of the rotor R/|R| as a bivector [e23, e31, e12], |B| in [0, pi].
/// log(s + B) = atan2(|B|, s) B/|B|; log(1) = 0; the cut log(-1) is -pi e12.
template <class T>
std::array<T, 3> log_rotor(const MV<T>& r) {
  using std::atan2;
  const std::array<T, 3> b = bivector_part(r);
  const T bn = norm3(b);
  const T s = r.c[0];
  if (bn == 0) {
    if (s > 0) return {T(0), T(0), T(0)};
    return {T(0), T(0), -ScalarTraits<T>::pi()};  // LOG-2
  }
  const T f = atan2(bn, s) / bn;
  return {f * b[0], f * b[1], f * b[2]};
}

}  // namespace rotorcert::ref::cl3
