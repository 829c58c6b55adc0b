// MAT-3's two quantities of an input matrix M (3x3, column-major m[c*3 + r]), written once for
// the engine, the fuzz oracle and the tests: where the format cannot decide the sign of det M
// (its domain), and delta = ||M^T M - I||_F (its bar, class inherited-mat).
#pragma once

#include <cmath>

#include "result.hpp"

namespace rotorcert::ref::clause {

/// MAT-3's band: |det M| <= 8u per(|M|) (per the permanent of the entries' magnitudes, u the
/// format's unit roundoff), Shewchuk's bound on a floating-point 3x3 determinant. There the
/// format cannot decide det's sign and either outcome conforms.
template <class T>
bool MAT_3_numerically_singular(const Mat3<T>& m, const T& u) {
  using std::abs;
  constexpr int kPermutations[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  T det(0), per(0);
  for (int p = 0; p < 6; ++p) {
    // Entry (row, column) is m[column * 3 + row].
    const T term = m[kPermutations[p][0] * 3 + 0] * m[kPermutations[p][1] * 3 + 1] * m[kPermutations[p][2] * 3 + 2];
    det += p < 3 ? term : -term;
    per += abs(term);
  }
  return abs(det) <= T(8) * u * per;
}

/// delta = ||M^T M - I||_F, the orthogonality defect inherited-mat's bars grow with.
template <class T>
T MAT_3_orthogonality_defect(const Mat3<T>& m) {
  using std::sqrt;
  T delta(0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      T s(0);
      for (int r = 0; r < 3; ++r) s += m[i * 3 + r] * m[j * 3 + r];
      const T d = s - T(i == j ? 1 : 0);
      delta += d * d;
    }
  return sqrt(delta);
}

}  // namespace rotorcert::ref::clause
