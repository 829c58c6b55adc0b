// rotorcert reproducer, CQRlib 1.1.4 (Debian libcqrlib-dev 1.1.4-3), clause SLERP-1.
// SLERP-1 (spec/SPEC.md 8.2, tolerance eps16, loose bar 256 eps; METRIC-1 and METRIC-6): slerp(a, b, t)
// = a (a^-1 b')^t with b' = -b when a.b < 0, i.e. a sin((1-t) W)/sin W + b' sin(t W)/sin W.
// CQRHLERP(out, q1, q2, w1, w2) (the hemispherical slerp "for use with quaternions representing
// rotations"; w1 weighs q1) switches to a series when sin(omega) <= 0.05 and keeps only
// sin(x) ~ x - x^3/6 there: the dropped x^5/120 term costs up to ~1e-9, i.e. ~1e6 eps, for every
// pair whose angle after the hemisphere flip is 0.01..0.05 rad -- in particular near-antipodal
// pairs (b ~ -a rotated a little), which the flip brings into that range.
// Source (cqrlib.c, CQRHLERP): 'if (sinomega <= 0.05) { t1=t*(1-t*t*omega*omega/6.); ...'.
// Upstream: CQRlib has no public issue tracker that we found (SourceForge project, no bug list).
// Build: g++ -std=c++20 -O1 SLERP-1.cpp -lCQRlib -lm   Exit: 0 defect shown, 1 not shown.
#include <cqrlib.h>

#include <cmath>
#include <cstdio>

using LD = long double;  // reference arithmetic: 64-bit mantissa (x86) or more, >= 2^11 x finer than double

int main() {
  // The suite's worst input (near-antipodal family): a.b ~ -0.9998, the angle after the flip is ~0.04 rad.
  CQRQuaternion a, b, out{};  // {w, x, y, z}
  a.x = 0x1.93a1b5552cc8cp-2, a.y = -0x1.e9c64fac6d706p-4, a.z = -0x1.3165c525ae8c1p-1, a.w = 0x1.60b3acc007a27p-1;
  b.x = -0x1.985a21eb9afaep-2, b.y = 0x1.3bbe9d9a9ba58p-3, b.z = 0x1.3bfa1ac7ae0c9p-1, b.w = -0x1.5234eb5b1999fp-1;
  const double t = 0x1.058565f181e26p-3;
  // (An ordinary pair, e.g. b = {w, x, y, z} = {0.6, 0.8, 0, 0} against a, takes the sin branch: exit 1.)
  const int rc = CQRHLERP(&out, &a, &b, 1.0 - t, t);  // slerp(a, b, t): weight 1 - t on a, t on b

  // Reference in long double: normalise (rotations q/|q|), flip b when a.b < 0, W = 2 atan2(|a-b'|, |a+b'|).
  const LD A[4] = {a.w, a.x, a.y, a.z}, B0[4] = {b.w, b.x, b.y, b.z}, G[4] = {out.w, out.x, out.y, out.z};
  LD na = 0, nb = 0, dot = 0, dm = 0, dp = 0, Ah[4], Bh[4], R[4];
  for (int i = 0; i < 4; ++i) na += A[i] * A[i], nb += B0[i] * B0[i], dot += A[i] * B0[i];
  const LD sgn = dot < 0 ? -1.0L : 1.0L;
  for (int i = 0; i < 4; ++i) {
    Ah[i] = A[i] / std::sqrt(na), Bh[i] = sgn * B0[i] / std::sqrt(nb);
    dm += (Ah[i] - Bh[i]) * (Ah[i] - Bh[i]), dp += (Ah[i] + Bh[i]) * (Ah[i] + Bh[i]);
  }
  const LD W = 2 * std::atan2(std::sqrt(dm), std::sqrt(dp)), s = std::sin(W);
  const LD ca = std::sin((1 - (LD)t) * W) / s, cb = std::sin((LD)t * W) / s;
  for (int i = 0; i < 4; ++i) R[i] = ca * Ah[i] + cb * Bh[i];
  // METRIC-1: 4 atan2(min(|g-r|, |g+r|), max(...)) of the normalised output; METRIC-6: | |g| - 1 |.
  LD ng = 0, nr = 0, em = 0, ep = 0;
  for (int i = 0; i < 4; ++i) ng += G[i] * G[i], nr += R[i] * R[i];
  for (int i = 0; i < 4; ++i) {
    const LD g = G[i] / std::sqrt(ng), r = R[i] / std::sqrt(nr);
    em += (g - r) * (g - r), ep += (g + r) * (g + r);
  }
  em = std::sqrt(em), ep = std::sqrt(ep);
  const double d = (double)(4 * std::atan2(std::fmin(em, ep), std::fmax(em, ep)));
  const double norm_defect = (double)std::fabs(std::sqrt(ng) - 1);
  const double eps = 0x1p-52, err = std::fmax(d, norm_defect) / eps;

  std::printf("rotorcert reproducer: CQRlib 1.1.4 SLERP-1: CQRHLERP's small-angle series (sin omega <= 0.05, "
              "taken after the hemisphere flip of a near-antipodal pair) drops the x^5 term of sin: %.3g eps\n", err);
  std::printf("call:    CQRHLERP(&out, &a, &b, 1 - t, t)   (slerp(a, b, t); w1 = 1 - t weighs a)\n");
  std::printf("input:   a {w, x, y, z} = {%a, %a, %a, %a}\n", a.w, a.x, a.y, a.z);
  std::printf("         b {w, x, y, z} = {%a, %a, %a, %a}\n         t = %a   (a.b = %.6Lf, angle after the flip "
              "W = %.6Lf rad, sin W = %.4Lf)\n", b.w, b.x, b.y, b.z, t, dot, W, s);
  std::printf("library: rc = %d, out {w, x, y, z} = {%a, %a, %a, %a}\n", rc, out.w, out.x, out.y, out.z);
  std::printf("correct: {%a, %a, %a, %a}   [a sin((1-t)W)/sin W + b' sin(tW)/sin W, b' = -b, long double]\n",
              (double)R[0], (double)R[1], (double)R[2], (double)R[3]);
  std::printf("error:   %.3g rad (METRIC-1), norm defect %.3g (METRIC-6): %.3g eps (eps = 2^-52; loose bar 256 eps)\n",
              d, norm_defect, err);
  if (rc == CQR_SUCCESS && err <= 256) {
    std::printf("DEFECT NOT SHOWN\n");
    return 1;
  }
  std::printf("DEFECT SHOWN\n");
  return 0;
}
