// Generic exp, square root and log of a multivector by series (EXPSERIES-1).
//
// These know nothing of rotors or motors; they are the slow, obviously-correct fallback that
// the closed forms of cl3.hpp and pga.hpp are tested against.
#pragma once

#include <optional>
#include <stdexcept>

#include "multivector.hpp"

namespace rotorcert::ref {

/// exp(x) = sum x^k / k!, after scaling x by 2^-s so that |x|_1 <= 1/2, then squaring s times.
/// The 1-norm is submultiplicative, so the truncation error is below the last term's norm.
template <class A, class T>
Multivector<A, T> exp_series(const Multivector<A, T>& x) {
  using MV = Multivector<A, T>;
  const T eps = ScalarTraits<T>::epsilon();
  int squarings = 0;
  T scale(1);
  while (norm1(x) * scale > T(0.5)) {
    scale /= T(2);
    ++squarings;
  }
  const MV y = x * scale;
  MV sum(T(1)), term(T(1));
  for (int k = 1; k < 10000; ++k) {
    term = gp(term, y) / T(k);
    sum = sum + term;
    if (norm1(term) <= eps * norm1(sum) / T(16)) break;
  }
  for (int i = 0; i < squarings; ++i) sum = gp(sum, sum);
  return sum;
}

/// Principal square root by the Denman-Beavers iteration Y <- (Y + Z^-1)/2, Z <- (Z + Y^-1)/2,
/// which converges to sqrt(x) when no eigenvalue of left multiplication by x is real and <= 0.
template <class A, class T>
std::optional<Multivector<A, T>> sqrt_series(const Multivector<A, T>& x) {
  using MV = Multivector<A, T>;
  const T eps = ScalarTraits<T>::epsilon();
  MV y = x, z(T(1));
  for (int it = 0; it < 200; ++it) {
    const auto yi = inverse(y);
    const auto zi = inverse(z);
    if (!yi || !zi) return std::nullopt;
    const MV y_next = (y + *zi) / T(2);
    const MV z_next = (z + *yi) / T(2);
    const bool converged = norm1(y_next - y) <= eps * norm1(y_next) * T(64);
    y = y_next;
    z = z_next;
    if (converged) return y;
  }
  return std::nullopt;
}

/// Principal log by inverse scaling and squaring: take square roots until |x - 1|_1 <= 1/4,
/// sum log(1 + u) = u - u^2/2 + u^3/3 - ..., multiply by 2^k. nullopt where no principal log
/// exists (e.g. the rotor -1, whose square root is not unique).
template <class A, class T>
std::optional<Multivector<A, T>> log_series(const Multivector<A, T>& x) {
  using MV = Multivector<A, T>;
  const T eps = ScalarTraits<T>::epsilon();
  MV r = x;
  int roots = 0;
  while (norm1(r - MV(T(1))) > T(0.25)) {
    if (++roots > 200) return std::nullopt;
    const auto s = sqrt_series(r);
    if (!s) return std::nullopt;
    r = *s;
  }
  const MV u = r - MV(T(1));
  MV sum, power(T(1));
  for (int k = 1; k < 100000; ++k) {
    power = gp(power, u);
    const MV term = power / T(k);
    sum = (k % 2 == 1) ? sum + term : sum - term;
    if (norm1(term) <= eps * (norm1(sum) + eps) / T(16)) break;
  }
  T scale(1);
  for (int i = 0; i < roots; ++i) scale *= T(2);
  return sum * scale;
}

}  // namespace rotorcert::ref
