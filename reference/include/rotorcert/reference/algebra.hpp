// Clifford algebras Cl(p,q,r) described by their metric.
//
// Basis vector k is bit k of a blade bitmap. The r degenerate vectors (square 0) come first,
// then the p positive (square +1), then the q negative (square -1). Names: with r = 0 the
// vectors are e1..en; with r >= 1 they are e0..e(n-1), so PGA's ideal vector is e0 = bit 0.
//   Cl3  = Cl(3,0,0): e1 = 1, e2 = 2, e3 = 4                (ALG-1)
//   PGA3 = Cl(3,0,1): e0 = 1, e1 = 2, e2 = 4, e3 = 8         (ALG-7)
#pragma once

#include <array>
#include <string>

#include "blade.hpp"

namespace rotorcert::ref {

template <int P, int Q = 0, int R = 0>
struct Algebra {
  static constexpr int p = P, q = Q, r = R;
  static constexpr int dimension = P + Q + R;
  static constexpr int size = 1 << dimension;  // number of basis blades
  static constexpr Bitmap pseudoscalar = Bitmap(size - 1);

  /// What basis vector k squares to.
  static constexpr int vector_square(int k) { return k < R ? 0 : (k < R + P ? +1 : -1); }

  /// Index printed in the name of basis vector k ("e" + index).
  static constexpr int vector_index(int k) { return R > 0 ? k : k + 1; }

  /// Basis vector k from the printed index, or -1.
  static constexpr int vector_from_index(int index) {
    const int k = R > 0 ? index : index - 1;
    return (k >= 0 && k < dimension) ? k : -1;
  }

  /// Product of the metric factors of the vectors that a and b share.
  static constexpr int metric_factor(Bitmap a, Bitmap b) {
    int f = 1;
    for (int k = 0; k < dimension; ++k)
      if ((a & b) & (Bitmap(1) << k)) f *= vector_square(k);
    return f;
  }

  /// Geometric product of two basis blades: sign * blade(a ^ b), sign in {-1, 0, +1}.
  static constexpr int product_sign(Bitmap a, Bitmap b) {
    return reordering_sign(a, b) * metric_factor(a, b);
  }

  /// Canonical (ascending) name of a basis blade: "1", "e1", "e12", "e023", ...
  static std::string blade_name(Bitmap b) {
    if (b == 0) return "1";
    std::string s = "e";
    for (int k = 0; k < dimension; ++k)
      if (b & (Bitmap(1) << k)) s += std::to_string(vector_index(k));
    return s;
  }
};

using Cl3 = Algebra<3, 0, 0>;
using PGA3 = Algebra<3, 0, 1>;

}  // namespace rotorcert::ref
