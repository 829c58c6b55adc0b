// Multivectors of Cl(p,q,r) over a scalar type T, and the products derived from the metric.
//
// Layout: a dense array of 2^n coefficients indexed by blade bitmap (c[0] scalar, c[1] the
// first basis vector, c[3] = e1^e2 of the first two, ...). Dense is wasteful and that is the
// point: every product is the one double loop over basis blades of the textbook, so there is
// no hand-expanded formula in the reference that could hide a sign error.
#pragma once

#include <array>
#include <cctype>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "algebra.hpp"
#include "scalar.hpp"

namespace rotorcert::ref {

template <class A, class T>
struct Multivector {
  using AlgebraType = A;
  using Scalar = T;
  std::array<T, A::size> c{};  // c[bitmap] = coefficient of that basis blade

  Multivector() { c.fill(T(0)); }
  explicit Multivector(const T& scalar) { c.fill(T(0)); c[0] = scalar; }

  static Multivector blade(Bitmap b, const T& coefficient = T(1)) {
    Multivector m;
    m.c[b] = coefficient;
    return m;
  }
  /// Basis vector k (bit k), e.g. vector(0) is e1 in Cl3 and e0 in PGA3.
  static Multivector vector(int k) { return blade(Bitmap(1) << k); }
  static Multivector pseudoscalar() { return blade(A::pseudoscalar); }

  T& operator[](Bitmap b) { return c[b]; }
  const T& operator[](Bitmap b) const { return c[b]; }
  T scalar() const { return c[0]; }
};

// ---- linear structure ------------------------------------------------------------------

template <class A, class T>
Multivector<A, T> operator+(const Multivector<A, T>& a, const Multivector<A, T>& b) {
  Multivector<A, T> r;
  for (int i = 0; i < A::size; ++i) r.c[i] = a.c[i] + b.c[i];
  return r;
}
template <class A, class T>
Multivector<A, T> operator-(const Multivector<A, T>& a, const Multivector<A, T>& b) {
  Multivector<A, T> r;
  for (int i = 0; i < A::size; ++i) r.c[i] = a.c[i] - b.c[i];
  return r;
}
template <class A, class T>
Multivector<A, T> operator-(const Multivector<A, T>& a) {
  Multivector<A, T> r;
  for (int i = 0; i < A::size; ++i) r.c[i] = -a.c[i];
  return r;
}
template <class A, class T>
Multivector<A, T> operator*(const T& s, const Multivector<A, T>& a) {
  Multivector<A, T> r;
  for (int i = 0; i < A::size; ++i) r.c[i] = s * a.c[i];
  return r;
}
template <class A, class T>
Multivector<A, T> operator*(const Multivector<A, T>& a, const T& s) { return s * a; }
template <class A, class T>
Multivector<A, T> operator/(const Multivector<A, T>& a, const T& s) {
  Multivector<A, T> r;
  for (int i = 0; i < A::size; ++i) r.c[i] = a.c[i] / s;
  return r;
}

// ---- products (ALG-2, ALG-3) ---------------------------------------------------------------

/// Bilinear extension of a product of basis blades. `keep(a, b)` selects which blade pairs
/// contribute; the value of each contribution is the geometric product of the two blades.
/// Absent blades (coefficient 0) contribute nothing, not 0 times an infinite coefficient.
template <class A, class T, class Keep>
Multivector<A, T> blade_product(const Multivector<A, T>& x, const Multivector<A, T>& y, Keep keep) {
  Multivector<A, T> r;
  for (Bitmap a = 0; a < Bitmap(A::size); ++a) {
    if (is_absent(x.c[a])) continue;
    for (Bitmap b = 0; b < Bitmap(A::size); ++b) {
      if (is_absent(y.c[b]) || !keep(a, b)) continue;
      const int sign = A::product_sign(a, b);
      if (sign == 0) continue;
      if (sign > 0) r.c[a ^ b] += x.c[a] * y.c[b];
      else r.c[a ^ b] -= x.c[a] * y.c[b];
    }
  }
  return r;
}

/// Geometric product (ALG-2).
template <class A, class T>
Multivector<A, T> gp(const Multivector<A, T>& x, const Multivector<A, T>& y) {
  return blade_product(x, y, [](Bitmap, Bitmap) { return true; });
}
template <class A, class T>
Multivector<A, T> operator*(const Multivector<A, T>& x, const Multivector<A, T>& y) { return gp(x, y); }

/// Outer product (ALG-3): blades that share no vector.
template <class A, class T>
Multivector<A, T> op(const Multivector<A, T>& x, const Multivector<A, T>& y) {
  return blade_product(x, y, [](Bitmap a, Bitmap b) { return (a & b) == 0; });
}

/// Left contraction (ALG-3): the grade(b) - grade(a) part of a b, zero unless a is inside b.
template <class A, class T>
Multivector<A, T> lc(const Multivector<A, T>& x, const Multivector<A, T>& y) {
  return blade_product(x, y, [](Bitmap a, Bitmap b) { return (a & ~b) == 0; });
}

/// Scalar product (ALG-3): the grade-0 part of the geometric product.
template <class A, class T>
T scp(const Multivector<A, T>& x, const Multivector<A, T>& y) {
  return blade_product(x, y, [](Bitmap a, Bitmap b) { return a == b; }).c[0];
}

// ---- involutions and grades (ALG-4) -------------------------------------------------------

template <class A, class T, class SignOfGrade>
Multivector<A, T> graded_sign(const Multivector<A, T>& x, SignOfGrade sign_of_grade) {
  Multivector<A, T> r;
  for (Bitmap b = 0; b < Bitmap(A::size); ++b)
    r.c[b] = sign_of_grade(grade_of(b)) > 0 ? x.c[b] : -x.c[b];
  return r;
}

template <class A, class T>
Multivector<A, T> reverse(const Multivector<A, T>& x) { return graded_sign(x, reverse_sign); }

template <class A, class T>
Multivector<A, T> involute(const Multivector<A, T>& x) { return graded_sign(x, involution_sign); }

template <class A, class T>
Multivector<A, T> conjugate(const Multivector<A, T>& x) {
  return graded_sign(x, [](int k) { return reverse_sign(k) * involution_sign(k); });
}

/// Grade-k part <x>_k.
template <class A, class T>
Multivector<A, T> grade(const Multivector<A, T>& x, int k) {
  Multivector<A, T> r;
  for (Bitmap b = 0; b < Bitmap(A::size); ++b)
    if (grade_of(b) == k) r.c[b] = x.c[b];
  return r;
}

/// The even part: grades 0, 2, 4, ...
template <class A, class T>
Multivector<A, T> even(const Multivector<A, T>& x) {
  Multivector<A, T> r;
  for (Bitmap b = 0; b < Bitmap(A::size); ++b)
    if (grade_of(b) % 2 == 0) r.c[b] = x.c[b];
  return r;
}

// ---- norms ----------------------------------------------------------------------------

/// Sum of |coefficients|. Submultiplicative for every metric with squares in {-1,0,1}
/// (|x y|_1 <= |x|_1 |y|_1), which is what the series below need for their error bounds.
template <class A, class T>
T norm1(const Multivector<A, T>& x) {
  using std::abs;
  T s(0);
  for (const T& v : x.c) s += abs(v);
  return s;
}

/// Euclidean norm of the coefficient vector (not a metric norm: PGA's e0 counts too).
template <class A, class T>
T coefficient_norm(const Multivector<A, T>& x) {
  using std::sqrt;
  T s(0);
  for (const T& v : x.c) s += v * v;
  return sqrt(s);
}

template <class A, class T>
bool all_finite(const Multivector<A, T>& x) {
  for (const T& v : x.c)
    if (!ScalarTraits<T>::is_finite(v)) return false;
  return true;
}

// ---- inverse, by the left-multiplication matrix ----------------------------------------

/// General inverse: solves x y = 1 for y by Gaussian elimination on the 2^n x 2^n matrix of
/// left multiplication by x. Slow and generic; nullopt when x is not invertible.
/// (For versors ~x / (x ~x) is the inverse; tests check the two agree.)
template <class A, class T>
std::optional<Multivector<A, T>> inverse(const Multivector<A, T>& x) {
  using std::abs;
  constexpr int n = A::size;
  std::array<std::array<T, n + 1>, n> m;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j <= n; ++j) m[i][j] = T(0);
  // Column b of the matrix is x * blade(b).
  for (Bitmap b = 0; b < Bitmap(n); ++b) {
    const Multivector<A, T> column = gp(x, Multivector<A, T>::blade(b));
    for (int i = 0; i < n; ++i) m[i][b] = column.c[i];
  }
  m[0][n] = T(1);
  for (int col = 0; col < n; ++col) {
    int pivot = col;
    for (int i = col + 1; i < n; ++i)
      if (abs(m[i][col]) > abs(m[pivot][col])) pivot = i;
    if (m[pivot][col] == 0) return std::nullopt;
    std::swap(m[pivot], m[col]);
    for (int i = 0; i < n; ++i) {
      if (i == col || m[i][col] == 0) continue;
      const T f = m[i][col] / m[col][col];
      for (int j = col; j <= n; ++j) m[i][j] -= f * m[col][j];
    }
  }
  Multivector<A, T> y;
  for (int i = 0; i < n; ++i) y.c[i] = m[i][n] / m[i][i];
  return y;
}

// ---- names ------------------------------------------------------------------------------

/// Parses a blade name made of basis vector indices, in any order: "1", "e2", "e31", "e032".
/// Returns the signed basis blade: e31 = e3 e1 = -e13, e032 = -e023. Repeated indices are
/// contracted with the metric (e11 = 1 in Cl3, e00 = 0 in PGA).
template <class A, class T>
Multivector<A, T> blade_from_name(const std::string& name) {
  using MV = Multivector<A, T>;
  if (name == "1") return MV(T(1));
  if (name.size() < 2 || name[0] != 'e')
    throw std::invalid_argument("not a blade name: '" + name + "'");
  MV r(T(1));
  for (std::size_t i = 1; i < name.size(); ++i) {
    if (!std::isdigit(static_cast<unsigned char>(name[i])))
      throw std::invalid_argument("not a blade name: '" + name + "'");
    const int k = A::vector_from_index(name[i] - '0');
    if (k < 0) throw std::invalid_argument("no basis vector e" + std::string(1, name[i]) + " in this algebra");
    r = gp(r, MV::vector(k));
  }
  return r;
}

}  // namespace rotorcert::ref
