// Error metrics of the spec (METRIC-1 .. METRIC-7).
//
// Every metric is computed in the scalar type it is given; the suite evaluates them in MPFR on
// the exact values of the implementation's output and of the reference, so the metric adds no
// error of its own to what it measures.
#pragma once

#include <algorithm>

#include "quaternion.hpp"
#include "result.hpp"

namespace rotorcert::ref {

/// The implementation formats of NUM-1.
enum class Format { binary32, binary64 };

inline const char* to_string(Format f) { return f == Format::binary32 ? "float" : "double"; }

/// NUM-1: eps = 2^-23 for binary32, 2^-52 for binary64 (the distance from 1 to the next value).
template <class T>
T format_epsilon(Format f) {
  using std::ldexp;
  return f == Format::binary32 ? ldexp(T(1), -23) : ldexp(T(1), -52);
}

/// The smallest positive normal number of a format: the floor of METRIC-3's scale.
template <class T>
T format_min_normal(Format f) {
  using std::ldexp;
  return f == Format::binary32 ? ldexp(T(1), -126) : ldexp(T(1), -1022);
}

/// q / |q| computed without overflow or underflow: scale by the largest |component| first.
/// Precondition: q finite and nonzero.
template <class T>
Quaternion<T> normalized(const Quaternion<T>& q) {
  using std::abs;
  using std::max;
  using std::sqrt;
  const T m = max(max(abs(q.w), abs(q.x)), max(abs(q.y), abs(q.z)));
  const Quaternion<T> s{q.w / m, q.x / m, q.y / m, q.z / m};
  const T n = sqrt(dot(s, s));
  return {s.w / n, s.x / n, s.y / n, s.z / n};
}

namespace clause {

/// METRIC-1: the angle of the rotation that takes b to a, in [0, pi]:
///   4 atan2(min(|a-b|, |a+b|), max(|a-b|, |a+b|)) of the normalised inputs.
/// min/max is the sign canonicalisation (q and -q are one rotation). atan2 of the chord lengths
/// keeps full relative accuracy at tiny angles, where acos(|a.b|) returns 0 or loses half of
/// the digits (acos'(1) is infinite). NaN when either input is zero or not finite.
template <class T>
T METRIC_1_rotation_distance(const Quaternion<T>& a, const Quaternion<T>& b) {
  using std::atan2;
  using std::max;
  using std::min;
  if (!finite(a) || !finite(b) || is_zero(a) || is_zero(b)) return ScalarTraits<T>::nan();
  const Quaternion<T> u = normalized(a), v = normalized(b);
  const T minus = norm(u - v), plus = norm(u + v);
  return T(4) * atan2(min(minus, plus), max(minus, plus));
}

/// METRIC-2: an error in units of the format's eps.
template <class T>
T METRIC_2_eps_units(const T& err, Format f) { return err / format_epsilon<T>(f); }

/// METRIC-3: |v - ref| / max(|ref|, tiny), or |v - ref| when ref = 0. `tiny` is the format's
/// smallest normal number (format_min_normal): a subnormal reference vector cannot be resolved
/// to a few eps of its own length, only to a few eps of the normal range.
template <class T>
T METRIC_3_vector_error(const Vec3<T>& v, const Vec3<T>& ref, const T& tiny = T(0)) {
  using std::max;
  using std::sqrt;
  T d(0), r(0);
  for (int i = 0; i < 3; ++i) {
    const T di = v[i] - ref[i];  // one object squared: a Bounded knows the square is >= 0
    d += di * di;
    r += ref[i] * ref[i];
  }
  return r == 0 ? sqrt(d) : sqrt(d) / max(sqrt(r), tiny);
}

/// METRIC-4: max_ij |M_ij - Mref_ij| (rotation matrix entries lie in [-1, 1]).
template <class T>
T METRIC_4_matrix_error(const Mat3<T>& m, const Mat3<T>& ref) {
  using std::abs;
  using std::max;
  T e(0);
  for (int i = 0; i < 9; ++i) {
    const T d = abs(m[i] - ref[i]);
    if (ScalarTraits<T>::is_nan(d)) return d;  // a NaN entry is an infinite error, not a skipped one
    e = max(e, d);  // max, not a comparison: in interval arithmetic (ref::Bounded) two equal errors
                    // would make "d > e" undecidable, while max is continuous and needs no branch
  }
  return e;
}

/// METRIC-5: Euclidean norm of the coefficient difference of two bivectors (or logs), radians.
template <class T>
T METRIC_5_bivector_error(const Vec3<T>& b, const Vec3<T>& ref) {
  using std::sqrt;
  T d(0);
  for (int i = 0; i < 3; ++i) {
    const T di = b[i] - ref[i];
    d += di * di;
  }
  return sqrt(d);
}

/// METRIC-6: | |q| - 1 | for outputs that the spec requires to be unit.
template <class T>
T METRIC_6_norm_defect(const Quaternion<T>& q) {
  using std::abs;
  return abs(norm(q) - T(1));
}

template <class T>
struct RigidError {
  T rotation{0};     // METRIC-1 of the real parts, radians
  T translation{0};  // |t - t_ref| / max(1, |t_ref|), length units
};

/// The translation of a dual quaternion: the vector part of 2 d r* / |r|^2. (The part of d
/// along r, which DQ-4 removes, only adds to the scalar part.)
template <class T>
Vec3<T> dual_quaternion_translation(const DualQuaternion<T>& d) {
  const Quaternion<T> t = d.dual * conj(d.real);
  const T s = T(2) / dot(d.real, d.real);
  return {s * t.x, s * t.y, s * t.z};
}

/// METRIC-7: rotation distance of the real parts and the relative translation error.
template <class T>
RigidError<T> METRIC_7_rigid_error(const DualQuaternion<T>& d, const DualQuaternion<T>& ref) {
  using std::max;
  using std::sqrt;
  RigidError<T> e;
  e.rotation = METRIC_1_rotation_distance(d.real, ref.real);
  if (!finite(d) || is_zero(d.real)) {
    e.translation = ScalarTraits<T>::nan();
    return e;
  }
  const Vec3<T> t = dual_quaternion_translation(d), tr = dual_quaternion_translation(ref);
  T diff(0), len(0);
  for (int i = 0; i < 3; ++i) {
    const T di = t[i] - tr[i];
    diff += di * di;  // one factor twice: a square, which a bounded scalar knows to be >= 0
    len += tr[i] * tr[i];
  }
  e.translation = sqrt(diff) / max(T(1), sqrt(len));
  return e;
}

}  // namespace clause
}  // namespace rotorcert::ref
