// MAT-2 / MAT-3 on ref::Bounded: the reference's own K, and its top eigenvector with a proven
// bound (the fast oracle's from_matrix, fuzz/README.md "The fast oracle").
//
// The reference finds the eigenvector by Jacobi sweeps that stop at the type's epsilon, which a
// running error bound cannot follow. Here the sweeps run unverified in long double on K's
// midpoints, and the vector x they give is then verified in Bounded arithmetic against K's
// intervals (which hold the exact K):
//   - rho = x^T K x / x^T x is the Rayleigh quotient, so the largest eigenvalue lambda_1 >= rho;
//   - r = K x^ - rho x^ (x^ = x / |x|) is the residual;
//   - the other three eigenvalues have the sum tr K - lambda_1 and the sum of squares
//     |K|_F^2 - lambda_1^2, so the second largest is at most
//         lambda_2 <= s/3 + sqrt(2/3 (Q - s^2/3)),  s = tr K - L,  Q = |K|_F^2 - L^2,
//     for any L <= lambda_1 with L >= tr K / 4 (the bound falls as L rises there);
//   - with the gap delta = rho - lambda_2 > 0, lambda_1 is simple and the angle theta between x^
//     and its eigenvector q_1 obeys sin theta <= |r| / delta (Davis and Kahan: the part of r
//     orthogonal to q_1 is sin theta (K - rho) y with y orthogonal to q_1);
//   - |x^ - q_1| = 2 sin(theta / 2) <= sqrt(2) sin theta (q_1 signed to face x^, theta <= pi/2).
// Each component of x^ widened by that distance holds q_1's; the answer's normalisation and sign
// are the reference's (detail::from_matrix_answer). Where the gap is not positive (a matrix whose
// nearest rotation is not unique or is nearly so) the evaluation is undecided and MPFR answers.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "bounded.hpp"
#include "rotation_ops.hpp"

namespace rotorcert::ref::clause {
namespace detail {

using K4 = std::array<std::array<Bounded, 4>, 4>;

/// The eigenvector of the largest eigenvalue of the symmetric K (intervals holding the exact K),
/// from an approximation x (components in K's order), with bounds that hold it; nullopt where the
/// bounds cannot prove x near it (x near another eigenvector, a gap that is not positive).
inline std::optional<std::array<Bounded, 4>> verified_top_eigenvector(const K4& k, const std::array<Bounded::F, 4>& approx) {
  using F = Bounded::F;
  constexpr F u = Bounded::kU;
  std::array<Bounded, 4> x;  // exact long double values
  for (int i = 0; i < 4; ++i) x[i] = Bounded(approx[i], 0);
  Bounded xx(0), xkx(0), trace(0), frobenius(0);
  std::array<Bounded, 4> kx;
  for (int i = 0; i < 4; ++i) {
    xx += x[i] * x[i];
    Bounded s(0);
    for (int j = 0; j < 4; ++j) {
      s += k[i][j] * x[j];
      frobenius += k[i][j] * k[i][j];
    }
    kx[i] = s;
    xkx += x[i] * kx[i];
    trace += k[i][i];
  }
  const Bounded rho = xkx / xx;
  Bounded rr(0);
  for (int i = 0; i < 4; ++i) {
    const Bounded ri = kx[i] - rho * x[i];
    rr += ri * ri;
  }
  const Bounded residual = sqrt(rr) / sqrt(xx);  // |K x^ - rho x^| (roots of sums of squares: >= 0)
  // The ends of an interval, each moved outward past the rounding of its own computation.
  const auto upper = [](const Bounded& b) {
    const F hi = b.value() + b.bound() * (1 + 4 * u);
    return hi + std::fabs(hi) * 4 * u;
  };
  const auto lower = [](const Bounded& b) {
    const F lo = b.value() - b.bound() * (1 + 4 * u);
    return lo - std::fabs(lo) * 4 * u;
  };
  // L: a lower bound of lambda_1 (rho's lower end), as an exact value.
  const Bounded L(lower(rho), 0);
  if (!(xx.value() > 0) || !(L.value() > upper(trace) / 4)) return std::nullopt;
  const Bounded s = trace - L, q = frobenius - L * L;
  const F spread = std::max(F(0), upper(q - s * s / Bounded(3)));  // >= 0 at the exact lambda_1, so at L
  const F lambda2 = upper(s / Bounded(3)) + std::sqrt(F(2) / 3 * spread) * (1 + 8 * u);
  const F gap = lower(rho) - lambda2;
  if (!(gap > 0) || !std::isfinite(upper(residual))) return std::nullopt;
  const F distance = std::sqrt(F(2)) * (1 + 8 * u) * upper(residual) / gap * (1 + 8 * u);
  const Bounded norm = sqrt(xx);
  std::array<Bounded, 4> q1;
  for (int i = 0; i < 4; ++i) {
    const Bounded xi = x[i] / norm;
    q1[i] = Bounded(xi.value(), xi.bound() + distance * (1 + 4 * u) + Bounded::kTiny);
  }
  return q1;
}

}  // namespace detail

/// MAT_2_from_matrix on Bounded (see the file comment): undecided where the verification fails.
inline Result<Quaternion<Bounded>> MAT_2_from_matrix_verified(const Mat3<Bounded>& matrix) {
  using F = Bounded::F;
  const auto k = detail::from_matrix_k(matrix);
  if (!k) return domain_error<Quaternion<Bounded>>();
  // The unverified step: Jacobi on K's midpoints, in long double.
  std::array<std::array<F, 4>, 4> mid;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) mid[i][j] = (*k)[i][j].value();
  const auto q1 = detail::verified_top_eigenvector(*k, detail::top_eigenvector(detail::jacobi_eigen(mid)));
  if (!q1) {
    Bounded::undecide();
    return domain_error<Quaternion<Bounded>>();
  }
  // Eigenvector components are in the order x, y, z, w.
  const auto& v = *q1;
  return {detail::from_matrix_answer(Quaternion<Bounded>{v[3], v[0], v[1], v[2]}), Status::ok};
}

}  // namespace rotorcert::ref::clause
