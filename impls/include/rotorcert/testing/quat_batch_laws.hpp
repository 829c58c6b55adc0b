// A law of the quaternion batches that run ordinary elements in SIMD lanes (rotor_m2's
// rotor/rotor_lanes.hpp, dq's QuatLanes): the batch gives each element's bits and status as the
// element function gives them alone. Written once for any table; the tests name the clauses.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>

#include <rotorcert/impl.hpp>

namespace rotorcert::testing::quat_batch_laws {

/// NORM-1, COMPOSE-1, APPLY-1 and, where the table has them, INV-1, APPLY-2, APPLY-3, MAT-1, MAT-2, AXANG-1, AXANG-2, LOG-1, EXP-1, NLERP-1, SLERP-2, QLB-1, SKIN-1 and (ops3)
/// AXANG-3, AXANG-4, EDGE-3, EDGE-5..8: a batch that runs its ordinary elements in SIMD lanes
/// (rotor_m2, dq) must give, bit for bit and status for status, what the element function
/// gives for each element alone (a one-element call takes the element function). 61
/// elements: 3 blocks of 16, 3 of 4 and one alone; among ordinary quaternions of sizes 1/4 .. 4
/// (EDGE-5) sit ones scaled by 2^+-E beyond the ordinary range, zeros, subnormals, NaN and
/// infinities (EDGE-6..8), and for nlerp t in [-1/2, 3/2] beside NaN and 1e30, pairs with b = -a
/// (the flip) and pairs with a.b = 0 exactly (EDGE-3's tie, which the lanes' filter cannot
/// decide), so lanes of one block take different paths. Any difference between
/// the lanes' arithmetic and the element function's shows as a bit.
template <class S>
void batch_gives_the_element_bits(const impl::Ops<S>& ops, const impl::Ops3<S>* ops3 = nullptr) {
  constexpr int E = std::is_same_v<S, float> ? 40 : 300;
  constexpr std::size_t kCases = 61;
  std::mt19937_64 gen(61);
  std::uniform_real_distribution<double> unit(-1, 1), size(0.25, 4);
  std::vector<S> a(4 * kCases), b(4 * kCases), v(3 * kCases), t(kCases);
  for (std::size_t i = 0; i < kCases; ++i) {
    for (std::size_t c = 0; c < 4; ++c) a[4 * i + c] = S(unit(gen) * size(gen)), b[4 * i + c] = S(unit(gen) * size(gen));
    for (std::size_t c = 0; c < 3; ++c) v[3 * i + c] = S(unit(gen) * 10);
    t[i] = S(unit(gen) + 0.5);
    switch (i % 11) {  // the specials, spread over blocks and lanes
      case 2: for (std::size_t c = 0; c < 4; ++c) a[4 * i + c] = std::ldexp(a[4 * i + c], E); break;
      case 3: t[i] = std::numeric_limits<S>::quiet_NaN(); break;
      case 4: t[i] = S(1e30); break;
      case 5: for (std::size_t c = 0; c < 4; ++c) b[4 * i + c] = std::ldexp(b[4 * i + c], -E); break;
      case 6: for (std::size_t c = 0; c < 4; ++c) b[4 * i + c] = -a[4 * i + c]; break;
      case 7: a[4 * i] = a[4 * i + 1] = a[4 * i + 2] = a[4 * i + 3] = S(i % 2 ? -0.0 : 0.0); break;
      case 8: a[4 * i + 1] = std::numeric_limits<S>::denorm_min(), a[4 * i] = a[4 * i + 2] = a[4 * i + 3] = 0; break;
      case 9: v[3 * i + 2] = std::numeric_limits<S>::infinity(); b[4 * i + 3] = std::numeric_limits<S>::quiet_NaN(); break;
      case 0: a[4 * i] = a[4 * i + 1] = a[4 * i + 2] = 0; break;  // no vector part: to_axis's +z
      case 10: b[4 * i] = -a[4 * i + 1], b[4 * i + 1] = a[4 * i], b[4 * i + 2] = -a[4 * i + 3], b[4 * i + 3] = a[4 * i + 2]; break;
      default: break;
    }
  }
  // One op: the batch of all cases against one-element calls from element i, `width` output
  // scalars per element, bit for bit and status for status.
  const auto check = [&](const char* name, std::size_t width, auto call) {
    std::vector<S> batch(width * kCases), one(width);
    std::vector<std::uint8_t> st(kCases);
    std::uint8_t st1;
    ASSERT_EQ(call(kCases, std::size_t{0}, batch.data(), st.data()), 0) << name;
    for (std::size_t i = 0; i < kCases; ++i) {
      call(1, i, one.data(), &st1);
      EXPECT_EQ(st[i], st1) << name << " " << i;
      EXPECT_EQ(0, std::memcmp(&batch[width * i], one.data(), width * sizeof(S))) << name << " element " << i;
    }
  };
  using Status = std::uint8_t*;
  check("normalize", 4, [&](std::size_t n, std::size_t i, S* o, Status s) { return ops.normalize(n, &a[4 * i], o, s); });
  check("compose", 4,
        [&](std::size_t n, std::size_t i, S* o, Status s) { return ops.compose(n, &a[4 * i], &b[4 * i], o, s); });
  if (ops.inverse != nullptr)
    check("inverse", 4, [&](std::size_t n, std::size_t i, S* o, Status s) { return ops.inverse(n, &a[4 * i], o, s); });
  check("apply_vector", 3,
        [&](std::size_t n, std::size_t i, S* o, Status s) { return ops.apply_vector(n, &a[4 * i], &v[3 * i], o, s); });
  if (ops.apply_bivector != nullptr)
    check("apply_bivector", 3, [&](std::size_t n, std::size_t i, S* o, Status s) {
      return ops.apply_bivector(n, &a[4 * i], &v[3 * i], o, s);
    });
  if (ops.apply_trivector != nullptr)  // the vectors' x as the trivector's coefficient (Inf among them)
    check("apply_trivector", 1, [&](std::size_t n, std::size_t i, S* o, Status s) {
      std::vector<S> coefficient(n);
      for (std::size_t e = 0; e < n; ++e) coefficient[e] = v[3 * (i + e) + 2];
      return ops.apply_trivector(n, &a[4 * i], coefficient.data(), o, s);
    });
  if (ops.to_matrix != nullptr)
    check("to_matrix", 9, [&](std::size_t n, std::size_t i, S* o, Status s) { return ops.to_matrix(n, &a[4 * i], o, s); });
  if (ops3 != nullptr && ops3->to_axis != nullptr)
    check("to_axis", 3, [&](std::size_t n, std::size_t i, S* o, Status s) { return ops3->to_axis(n, &a[4 * i], o, s); });
  if (ops.nlerp != nullptr)
    check("nlerp", 4, [&](std::size_t n, std::size_t i, S* o, Status s) {
      return ops.nlerp(n, &a[4 * i], &b[4 * i], &t[i], o, s);
    });
  // LOG-1, AXANG-1 and AXANG-3 on the quaternions above, on near-identities (w = 2^10 |v|: log's series)
  // and on rotations so near the identity that the rotor's |B|^2 underflows; EXP-1 on the vectors above and on tiny ones (|v|^2 < eps: exp's
  // series) in every fifth; AXANG-2 on the vectors as axes with angles 7 t (NaN and 7e30
  // among them) and a zero axis in every seventh.
  {
    std::vector<S> qs(a), vs(v), angles(kCases), axes(v);
    for (std::size_t i = 0; i < kCases; ++i) {
      if (i % 5 == 4) qs[4 * i + 3] = std::ldexp(std::abs(qs[4 * i]) + std::abs(qs[4 * i + 1]) + std::abs(qs[4 * i + 2]), 10);
      if (i % 5 == 2) {  // |q|^2 ordinary, the rotor's |B|^2 underflows: norm3 must scale
        for (std::size_t c = 0; c < 3; ++c) qs[4 * i + c] = std::ldexp(qs[4 * i + c], std::is_same_v<S, float> ? -43 : -281);
        qs[4 * i + 3] = std::ldexp(qs[4 * i + 3], std::is_same_v<S, float> ? 32 : 256);
      }
      if (i % 5 == 3)
        for (std::size_t c = 0; c < 3; ++c) vs[3 * i + c] = std::ldexp(vs[3 * i + c], -40);
      angles[i] = S(7) * t[i];
      if (i % 7 == 5) axes[3 * i] = axes[3 * i + 1] = axes[3 * i + 2] = 0;
    }
    if (ops.log != nullptr)
      check("log", 3, [&](std::size_t n, std::size_t i, S* o, Status s) { return ops.log(n, &qs[4 * i], o, s); });
    if (ops.to_axis_angle != nullptr)  // angle and axis side by side in one output of 4 scalars
      check("to_axis_angle", 4, [&](std::size_t n, std::size_t i, S* o, Status s) {
        std::vector<S> angle(n), axis(3 * n);
        const int r = ops.to_axis_angle(n, &qs[4 * i], angle.data(), axis.data(), s);
        for (std::size_t e = 0; e < n; ++e) {
          o[4 * e] = angle[e];
          for (std::size_t c = 0; c < 3; ++c) o[4 * e + 1 + c] = axis[3 * e + c];
        }
        return r;
      });
    if (ops3 != nullptr && ops3->to_angle != nullptr)
      check("to_angle", 1, [&](std::size_t n, std::size_t i, S* o, Status s) { return ops3->to_angle(n, &qs[4 * i], o, s); });
    if (ops.exp != nullptr)
      check("exp", 4, [&](std::size_t n, std::size_t i, S* o, Status s) { return ops.exp(n, &vs[3 * i], o, s); });
    if (ops.from_axis_angle != nullptr)
      check("from_axis_angle", 4, [&](std::size_t n, std::size_t i, S* o, Status s) {
        return ops.from_axis_angle(n, &angles[i], &axes[3 * i], o, s);
      });
  }
  // SLERP-2 on the pairs above, and on pairs b = a (1 + 1e-3 d) close enough for log's series
  // (and with t = 1e-6 for exp's too) in every third element.
  if (ops.slerp != nullptr) {
    std::vector<S> bs(b), ts(t);
    for (std::size_t i = 1; i < kCases; i += 3) {
      for (std::size_t c = 0; c < 4; ++c) bs[4 * i + c] = a[4 * i + c] * S(1 + 1e-3 * unit(gen));
      if (i % 2 == 0) ts[i] = S(1e-6);
    }
    check("slerp", 4, [&](std::size_t n, std::size_t i, S* o, Status s) {
      return ops.slerp(n, &a[4 * i], &bs[4 * i], &ts[i], o, s);
    });
  }
  // MAT-2 and MAT-3: the rotation matrices of the quaternions a (those that are rotations) rounded
  // to the format, so that most take MAT-3's fast path, and among them, spread over lanes: a
  // reflection (-M), 3/2 M (outside the fast path's bounds), M with one entry off by 2^-10 (not
  // orthonormal), a half turn about (1, -1, 0) (w = 0: MAT-2's sign rule on x), NaN and Inf, and
  // the identity.
  if (ops.from_matrix != nullptr) {
    std::vector<S> m(9 * kCases);
    for (std::size_t i = 0; i < kCases; ++i) {
      double q[4];
      for (std::size_t c = 0; c < 4; ++c) q[c] = double(a[4 * i + c]);
      double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
      if (!(n > 1e-30 && n < 1e30)) q[0] = q[1] = q[2] = 0, q[3] = n = 1;  // not a rotation: the identity
      const double x = q[0] / n, y = q[1] / n, z = q[2] / n, w = q[3] / n;
      const double r[9] = {1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y),
                           2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x),
                           2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)};
      S* e = &m[9 * i];
      for (std::size_t c = 0; c < 9; ++c) e[c] = S(r[c]);
      switch (i % 13) {
        case 1: for (std::size_t c = 0; c < 9; ++c) e[c] = -e[c]; break;
        case 3: for (std::size_t c = 0; c < 9; ++c) e[c] = S(1.5) * e[c]; break;
        case 5: e[4] = e[4] + S(1.0 / 1024); break;
        case 7: { const S h[9] = {0, -1, 0, -1, 0, 0, 0, 0, -1}; for (std::size_t c = 0; c < 9; ++c) e[c] = h[c]; } break;
        case 9: e[2] = std::numeric_limits<S>::quiet_NaN(); break;
        case 10: e[6] = std::numeric_limits<S>::infinity(); break;
        case 11: { const S id[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}; for (std::size_t c = 0; c < 9; ++c) e[c] = id[c]; } break;
        default: break;
      }
    }
    check("from_matrix", 4, [&](std::size_t n, std::size_t i, S* o, Status s) { return ops.from_matrix(n, &m[9 * i], o, s); });
  }
  // QLB-1 with k = 1, 4 and 8 influences per element (EDGE-9's rules on the weights): ordinary
  // influences, and in every other element one special, so that lanes of one block take
  // different paths: an influence that is -q_0 (the flip) or orthogonal to q_0 exactly (EDGE-3's
  // tie against the pivot), scaled by 2^E, zero, subnormal or NaN; a first weight 0 (the pivot
  // moves), all weights 0, a weight -0, -1/2, NaN, +Inf or 1e30.
  if (ops.blend_qlb != nullptr)
    for (const std::size_t k : {std::size_t{1}, std::size_t{4}, std::size_t{8}}) {
      std::vector<S> qs(4 * k * kCases), ws(k * kCases);
      for (std::size_t i = 0; i < kCases; ++i) {
        S* q = &qs[4 * k * i];
        S* w = &ws[k * i];
        for (std::size_t j = 0; j < k; ++j) {
          for (std::size_t c = 0; c < 4; ++c) q[4 * j + c] = S(unit(gen) * size(gen));
          w[j] = S(std::abs(unit(gen)));
        }
        const std::size_t last = k - 1;
        switch (i % 26) {
          case 1: for (std::size_t c = 0; c < 4; ++c) q[4 * last + c] = -q[c]; break;
          case 2: if (k > 1) q[4 * last] = -q[1], q[4 * last + 1] = q[0], q[4 * last + 2] = -q[3], q[4 * last + 3] = q[2]; break;
          case 3: for (std::size_t c = 0; c < 4; ++c) q[4 * last + c] = std::ldexp(q[4 * last + c], E); break;
          case 4: for (std::size_t c = 0; c < 4; ++c) q[4 * last + c] = 0; break;
          case 5: q[4 * last] = std::numeric_limits<S>::denorm_min(), q[4 * last + 1] = q[4 * last + 2] = q[4 * last + 3] = 0; break;
          case 6: q[4 * last + 2] = std::numeric_limits<S>::quiet_NaN(); break;
          case 7: w[0] = 0; break;
          case 8: for (std::size_t j = 0; j < k; ++j) w[j] = 0; break;
          case 9: w[last] = S(-0.0); break;
          case 10: w[last] = S(-0.5); break;
          case 11: w[last] = std::numeric_limits<S>::quiet_NaN(); break;
          case 12: w[last] = std::numeric_limits<S>::infinity(); break;
          case 13: w[last] = S(1e30); break;
          default: break;
        }
      }
      check(k == 1 ? "blend_qlb k=1" : k == 4 ? "blend_qlb k=4" : "blend_qlb k=8", 4,
            [&](std::size_t n, std::size_t i, S* o, Status s) { return ops.blend_qlb(n, k, &qs[4 * k * i], &ws[k * i], o, s); });
      // SKIN-1 on the same influences and weights, with translations in [-10, 10] (one Inf in
      // every 17th element) and the vectors v as vertices (their Inf among them).
      if (ops.skin_linear != nullptr) {
        std::vector<S> ts(3 * k * kCases);
        for (std::size_t j = 0; j < ts.size(); ++j) ts[j] = S(10 * unit(gen));
        for (std::size_t i = 5; i < kCases; i += 17) ts[3 * k * i + 1] = std::numeric_limits<S>::infinity();
        check(k == 1 ? "skin_linear k=1" : k == 4 ? "skin_linear k=4" : "skin_linear k=8", 3,
              [&](std::size_t n, std::size_t i, S* o, Status s) {
                return ops.skin_linear(n, k, &qs[4 * k * i], &ts[3 * k * i], &ws[k * i], &v[3 * i], o, s);
              });
      }
    }
}

}  // namespace rotorcert::testing::quat_batch_laws
