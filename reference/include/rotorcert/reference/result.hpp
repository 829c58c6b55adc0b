// Values and outcomes of the clause functions.
//
// Every clause function returns Result<V>: the value and the element status of RESULT-2.
// On DOMAIN_ERROR every component of the value is a quiet NaN (EDGE-6, EDGE-7, EDGE-9), so a
// poisoned result can never be mistaken for a valid one.
#pragma once

#include <array>

#include "multivector.hpp"
#include "quaternion.hpp"
#include "scalar.hpp"

namespace rotorcert::ref {

/// RESULT-2: per-element status.
enum class Status { ok, domain_error };

inline const char* to_string(Status s) { return s == Status::ok ? "OK" : "DOMAIN_ERROR"; }

template <class V>
struct Result {
  V value{};
  Status status = Status::ok;
};

template <class T> using Vec3 = std::array<T, 3>;
/// 3x3 matrix, column-major: m[c * 3 + r] (LAYOUT-1).
template <class T> using Mat3 = std::array<T, 9>;

/// sigma = real + eps dual (DQ-1). In arrays: [real xyzw, dual xyzw] (LAYOUT-1).
template <class T>
struct DualQuaternion {
  Quaternion<T> real, dual;
};

template <class T>
struct AxisAngle {
  T angle{0};
  Vec3<T> axis{};
};

// ---- poisoned values --------------------------------------------------------------------

template <class T> void poison(T& x) { x = ScalarTraits<T>::nan(); }
template <class T> void poison(Quaternion<T>& q) { poison(q.w); poison(q.x); poison(q.y); poison(q.z); }
template <class T, std::size_t N> void poison(std::array<T, N>& a) { for (auto& x : a) poison(x); }
template <class T> void poison(DualQuaternion<T>& d) { poison(d.real); poison(d.dual); }
template <class T> void poison(AxisAngle<T>& a) { poison(a.angle); poison(a.axis); }
template <class A, class T> void poison(Multivector<A, T>& m) { poison(m.c); }

/// The defined outcome for bad input: DOMAIN_ERROR and all-NaN output.
template <class V>
Result<V> domain_error() {
  Result<V> r;
  poison(r.value);
  r.status = Status::domain_error;
  return r;
}

// ---- input checks ---------------------------------------------------------------------------

template <class T> bool finite(const T& x) { return ScalarTraits<T>::is_finite(x); }
template <class T> bool finite(const Quaternion<T>& q) { return finite(q.w) && finite(q.x) && finite(q.y) && finite(q.z); }
template <class T, std::size_t N> bool finite(const std::array<T, N>& a) {
  for (const auto& x : a)
    if (!finite(x)) return false;
  return true;
}
template <class T> bool finite(const DualQuaternion<T>& d) { return finite(d.real) && finite(d.dual); }

template <class T> bool is_zero(const Quaternion<T>& q) { return q.w == 0 && q.x == 0 && q.y == 0 && q.z == 0; }

}  // namespace rotorcert::ref
