// rapidcheck generators of reference numbers. Values are drawn as exact binary fractions so
// that a shrunk counterexample prints as an exact number and reproduces from its seed.
#pragma once

#include <array>

#include <rapidcheck.h>

#include <rotorcert/reference/multivector.hpp>
#include <rotorcert/reference/quaternion.hpp>

namespace rotorcert::testing {

using ref::Real;

/// A real in [-range, range] with a 2^-20 grid: k * 2^-20 for an integer k.
inline rc::Gen<Real> real_in(int range) {
  return rc::gen::map(rc::gen::inRange<long>(-long(range) << 20, (long(range) << 20) + 1),
                      [](long k) { return Real(k) / Real(1L << 20); });
}

template <class A>
rc::Gen<ref::Multivector<A, Real>> multivector(int range = 4) {
  return rc::gen::map(rc::gen::container<std::array<Real, A::size>>(real_in(range)),
                      [](const std::array<Real, A::size>& c) {
                        ref::Multivector<A, Real> m;
                        m.c = c;
                        return m;
                      });
}

/// A nonzero quaternion (not normalised): the rotation it stands for is that of q/|q|.
inline rc::Gen<ref::Quaternion<Real>> quaternion() {
  return rc::gen::suchThat(
      rc::gen::map(rc::gen::container<std::array<Real, 4>>(real_in(2)),
                   [](const std::array<Real, 4>& a) { return ref::Quaternion<Real>{a[0], a[1], a[2], a[3]}; }),
      [](const ref::Quaternion<Real>& q) { return ref::dot(q, q) > Real(1) / Real(1 << 10); });
}

/// A unit quaternion, normalised in the reference precision.
inline rc::Gen<ref::Quaternion<Real>> unit_quaternion() {
  return rc::gen::map(quaternion(), [](const ref::Quaternion<Real>& q) {
    const Real n = ref::norm(q);
    return ref::Quaternion<Real>{q.w / n, q.x / n, q.y / n, q.z / n};
  });
}

inline rc::Gen<std::array<Real, 3>> vector3(int range = 4) {
  return rc::gen::container<std::array<Real, 3>>(real_in(range));
}

}  // namespace rotorcert::testing
