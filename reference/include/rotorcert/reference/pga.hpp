// PGA Cl(3,0,1): points, motors and the dual-quaternion view (ALG-7, MOTOR-1).
//
// Bitmaps: e0 = 1, e1 = 2, e2 = 4, e3 = 8.
//   e01 = 3, e02 = 5, e03 = 9, e12 = 6, e13 = 10 (e31 = -e13), e23 = 12, e0123 = 15,
//   e012 = 7 (e021 = -e012), e013 = 11, e023 = 13 (e032 = -e023), e123 = 14.
// A point (x, y, z) is x e032 + y e013 + z e021 + e123 (the convention of klein).
#pragma once

#include <array>

#include "multivector.hpp"
#include "quaternion.hpp"

namespace rotorcert::ref::pga {

template <class T> using MV = Multivector<PGA3, T>;

inline constexpr Bitmap kE0 = 1, kE1 = 2, kE2 = 4, kE3 = 8;
inline constexpr Bitmap kE01 = 3, kE02 = 5, kE03 = 9, kE12 = 6, kE13 = 10, kE23 = 12;
inline constexpr Bitmap kE012 = 7, kE013 = 11, kE023 = 13, kE123 = 14, kE0123 = 15;

/// A Euclidean point as a trivector.
template <class T>
MV<T> point(const std::array<T, 3>& p) {
  MV<T> m;
  m.c[kE023] = -p[0];  // x e032
  m.c[kE013] = p[1];   // y e013
  m.c[kE012] = -p[2];  // z e021
  m.c[kE123] = T(1);
  return m;
}

/// The Euclidean coordinates of a finite point (divides by the e123 weight).
template <class T>
std::array<T, 3> point_coordinates(const MV<T>& m) {
  const T w = m.c[kE123];
  return {-m.c[kE023] / w, m.c[kE013] / w, -m.c[kE012] / w};
}

/// MOTOR-1: the motor of the dual quaternion (real, dual):
///   M = w_r - x_r e23 - y_r e31 - z_r e12 - x_d e01 - y_d e02 - z_d e03 - w_d e0123.
template <class T>
MV<T> motor_from_dual_quaternion(const Quaternion<T>& real, const Quaternion<T>& dual) {
  MV<T> m;
  m.c[0] = real.w;
  m.c[kE23] = -real.x;
  m.c[kE13] = real.y;
  m.c[kE12] = -real.z;
  m.c[kE01] = -dual.x;
  m.c[kE02] = -dual.y;
  m.c[kE03] = -dual.z;
  m.c[kE0123] = -dual.w;
  return m;
}

/// MOTOR-1, inverse map. Odd grades are ignored.
template <class T>
std::pair<Quaternion<T>, Quaternion<T>> dual_quaternion_from_motor(const MV<T>& m) {
  return {{m.c[0], -m.c[kE23], m.c[kE13], -m.c[kE12]},
          {-m.c[kE0123], -m.c[kE01], -m.c[kE02], -m.c[kE03]}};
}

/// Translator T(t) = 1 - (1/2)(tx e01 + ty e02 + tz e03): T P ~T = P + t for points.
template <class T>
MV<T> translator(const std::array<T, 3>& t) {
  MV<T> m(T(1));
  m.c[kE01] = -t[0] / T(2);
  m.c[kE02] = -t[1] / T(2);
  m.c[kE03] = -t[2] / T(2);
  return m;
}

/// Sandwich M X ~M, divided by the scalar part of M ~M so that a non-unit motor acts as M/|M|.
template <class T>
MV<T> sandwich(const MV<T>& m, const MV<T>& x) {
  return gp(gp(m, x), reverse(m)) / gp(m, reverse(m)).c[0];
}

/// Euclidean (rotation) bivector part [e23, e31, e12] and ideal part [e01, e02, e03].
template <class T> std::array<T, 3> euclidean_bivector(const MV<T>& m) { return {m.c[kE23], -m.c[kE13], m.c[kE12]}; }
template <class T> std::array<T, 3> ideal_bivector(const MV<T>& m) { return {m.c[kE01], m.c[kE02], m.c[kE03]}; }

template <class T>
MV<T> bivector(const std::array<T, 3>& euclidean, const std::array<T, 3>& ideal) {
  MV<T> m;
  m.c[kE23] = euclidean[0];
  m.c[kE13] = -euclidean[1];
  m.c[kE12] = euclidean[2];
  m.c[kE01] = ideal[0];
  m.c[kE02] = ideal[1];
  m.c[kE03] = ideal[2];
  return m;
}

}  // namespace rotorcert::ref::pga
