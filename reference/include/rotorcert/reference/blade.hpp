// Basis blades as bitmaps (Dorst, Fontijne & Mann, GA for Computer Science, ch. 19).
//
// A basis blade e_{i1} ^ e_{i2} ^ ... with i1 < i2 < ... is the bitmap with bits i1, i2, ... set.
// Which basis vector a bit stands for, and what it squares to, is the algebra's business
// (algebra.hpp); here only the combinatorics that every metric shares.
#pragma once

#include <bit>
#include <cstdint>

namespace rotorcert::ref {

using Bitmap = std::uint32_t;

/// Grade of a basis blade: the number of basis vectors in it.
constexpr int grade_of(Bitmap blade) { return std::popcount(blade); }

/// Sign (+1 or -1) of the permutation that sorts the concatenation a b of two basis blades
/// into ascending order, before equal vectors are contracted. For each vector of a, count the
/// vectors of b with a lower index that it must pass.
constexpr int reordering_sign(Bitmap a, Bitmap b) {
  a >>= 1;
  int swaps = 0;
  while (a != 0) {
    swaps += std::popcount(a & b);
    a >>= 1;
  }
  return (swaps & 1) ? -1 : +1;
}

/// Sign of the reverse of a grade-k blade: (-1)^(k(k-1)/2).
constexpr int reverse_sign(int k) { return ((k * (k - 1) / 2) & 1) ? -1 : +1; }

/// Sign of the grade involution of a grade-k blade: (-1)^k.
constexpr int involution_sign(int k) { return (k & 1) ? -1 : +1; }

}  // namespace rotorcert::ref
