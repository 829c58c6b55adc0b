// MOTOR-5 (the blend of motors, DLB under MOTOR-1), the sandwich of a point, the normalisation
// (DQ-4), the product (DQ-2 as MOTOR-3), the motor T(t) R of a rotation and translation (DQ-1),
// SKIN-2 and AXIS-1 for L elements of a batch at once, in SoA lanes that the compiler turns into
// SIMD: the fast paths of motor_pga.cpp's dq_blend_batch, dq_apply_point_batch,
// dq_normalize_batch, dq_compose_batch, dq_from_rotation_translation_batch,
// skin_dual_quaternion_batch and rotate_about_axis_batch for ordinary input, kept apart from the
// scalar math (motor.hpp, motor_pga.cpp) in the manner of ozz-animation's SoA jobs.
//
// Data: the ABI's dual quaternions (element e: k influences of 8 scalars at d + 8 k e, k weights
// at w + k e; a point at p + 3 e) are read through MOTOR-1 into lane arrays m[coefficient][lane],
// coefficients in motor.hpp's order (s, e23, e31, e12, e01, e02, e03, e0123), or (the kernels of
// dq_normalize, dq_compose and dq_from_rotation_translation) read in place in the loop over lanes;
// motors go back through MOTOR-1 (pga::to_dual_quaternion) into out[component][lane].
//
// Every lane computes what the scalar fast path computes for its element (motor_pga.cpp's
// blend_ordinary(), blend(), rigid(), pga::normalized_ordinary(), pga::sandwich(),
// pga::operator*()): the same IEEE operations in the same order, so the same bits; AXIS-1's sin
// and cos are the element function's libm calls, made lane by lane between the vectorised loops. Where a cheap test fails, the lane's `ok` is 0
// and the caller takes the checked path for that element; the lane's other values are then
// meaningless (NaN or inf, no trap: see CMakeLists.txt for the flags). No branch depends on a
// lane's value.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include <rotorcert/runtime/exact_sign.hpp>
#include <rotorcert/runtime/axis_angle_lanes.hpp>
#include <rotorcert/runtime/lane_store.hpp>
#include <rotorcert/runtime/lane_weights.hpp>
#include <rotorcert/runtime/ordinary_range.hpp>

namespace rotorcert::motor_lanes {

using Flag = std::int32_t;  // a lane flag, 1 or 0: bool arrays do not vectorise

/// MOTOR-1 of the ABI dual quaternion at x into lane l of m.
template <class S, std::size_t L>
[[gnu::always_inline]] inline void load_motor(const S* x, std::size_t l, S (&m)[8][L]) {
  m[0][l] = x[3];
  m[1][l] = -x[0];
  m[2][l] = -x[1];
  m[3][l] = -x[2];
  m[4][l] = -x[4];
  m[5][l] = -x[5];
  m[6][l] = -x[6];
  m[7][l] = -x[7];
}

/// pga::normalized_ordinary() of the motor (s, b0, b1, b2, c0, c1, c2, p), into u; returns the
/// lane's test.
template <class S>
[[gnu::always_inline]] inline bool normalized_motor(S s, S b0, S b1, S b2, S c0, S c1, S c2, S p, S (&u)[8]) {
  constexpr S kMax = std::numeric_limits<S>::max();
  constexpr S kLo = runtime::OrdinaryRange<S>::kLo, kHi = runtime::OrdinaryRange<S>::kHi;
  const S n2 = s * s + b0 * b0 + b1 * b1 + b2 * b2;
  const S i2 = c0 * c0 + c1 * c1 + c2 * c2 + p * p;
  const S n = std::sqrt(s * s + (b0 * b0 + b1 * b1 + b2 * b2));
  const S su = s / n, bu0 = b0 / n, bu1 = b1 / n, bu2 = b2 / n;
  const S k = (bu0 * c0 + bu1 * c1 + bu2 * c2) - su * p;
  u[0] = su;
  u[1] = bu0;
  u[2] = bu1;
  u[3] = bu2;
  u[4] = (c0 - k * bu0) / n;
  u[5] = (c1 - k * bu1) / n;
  u[6] = (c2 - k * bu2) / n;
  u[7] = (p + k * su) / n;
  return (n2 >= kLo) & (n2 <= kHi) & ((i2 == 0) | ((i2 >= kLo) & (i2 <= kHi))) & (i2 <= kMax) &
         !(k * k > S(0.9375) * i2);  // runtime::projection_cancels
}

/// normalized_motor() of the motor in lane l of m.
template <class S, std::size_t L>
[[gnu::always_inline]] inline bool normalized_lane(const S (&m)[8][L], std::size_t l, S (&u)[8]) {
  return normalized_motor(m[0][l], m[1][l], m[2][l], m[3][l], m[4][l], m[5][l], m[6][l], m[7][l], u);
}

template <class S, std::size_t L>
struct BlendLanes {
  S out[8][L];  // the normalised weighted sum as a motor, where ok
  Flag ok[L];

  /// The L elements starting at d (influences) and w (weights), k >= 1 influences each.
  void run(std::size_t k, const S* d, const S* w) {
    runtime::LaneWeights<S, L> weights;  // EDGE-9
    weights.scan(k, w);
    S pivot[4][L], sum[8][L], m[8][L];
    for (std::size_t l = 0; l < L; ++l) {
      ok[l] = weights.ok[l];
      const S* x = d + weights.pivot_offset(k, 8, l);
      pivot[0][l] = x[3];
      pivot[1][l] = -x[0];
      pivot[2][l] = -x[1];
      pivot[3][l] = -x[2];
      for (std::size_t c = 0; c < 8; ++c) sum[c][l] = 0;
    }
    for (std::size_t i = 0; i < k; ++i) {
      for (std::size_t l = 0; l < L; ++l) load_motor(d + 8 * k * l + 8 * i, l, m);
      for (std::size_t l = 0; l < L; ++l) {
        S u[8];
        bool good = normalized_lane(m, l, u);
        // The hemisphere sign by the filter of runtime::filtered_dot_sign<S, 4> on the raw rotor
        // parts (s, e23, e31, e12); undecided -> not ok.
        bool negative;
        const bool decided = runtime::filtered_dot4_lane(m[0][l], m[1][l], m[2][l], m[3][l], pivot[0][l], pivot[1][l],
                                                         pivot[2][l], pivot[3][l], negative);
        good = good & decided;
        const S f0 = w[k * l + i] / weights.w_max[l];
        const S f = negative ? -f0 : f0;
        sum[0][l] = sum[0][l] + f * u[0];  // written out: a loop over c here keeps l's loop scalar
        sum[1][l] = sum[1][l] + f * u[1];
        sum[2][l] = sum[2][l] + f * u[2];
        sum[3][l] = sum[3][l] + f * u[3];
        sum[4][l] = sum[4][l] + f * u[4];
        sum[5][l] = sum[5][l] + f * u[5];
        sum[6][l] = sum[6][l] + f * u[6];
        sum[7][l] = sum[7][l] + f * u[7];
        ok[l] = ok[l] & Flag(good);
      }
    }
    for (std::size_t l = 0; l < L; ++l) {
      S u[8];
      ok[l] = ok[l] & Flag(normalized_lane(sum, l, u));
      runtime::store_lane(u, l, out);
    }
  }
};

/// pga::sandwich() of the point (x0, x1, x2, 1) by the motor u, read back as motor_pga.cpp's
/// move_point() does, into lane l of out.
template <class S, std::size_t L>
[[gnu::always_inline]] inline void sandwich_lane(const S (&u)[8], S x0, S x1, S x2, std::size_t l, S (&out)[3][L]) {
  const S s = u[0], b0 = u[1], b1 = u[2], b2 = u[3], c0 = u[4], c1 = u[5], c2 = u[6], e0123 = u[7];
  const S w0 = b1 * x2 - b2 * x1, w1 = b2 * x0 - b0 * x2, w2 = b0 * x1 - b1 * x0;       // b x x
  const S bu0 = b1 * w2 - b2 * w1, bu1 = b2 * w0 - b0 * w2, bu2 = b0 * w1 - b1 * w0;  // b x (b x x)
  const S bc0 = b1 * c2 - b2 * c1, bc1 = b2 * c0 - b0 * c2, bc2 = b0 * c1 - b1 * c0;  // b x c
  const S two_w = S(2) * S(1);
  out[0][l] = x0 - S(2) * s * w0 + S(2) * bu0 - two_w * (e0123 * b0 + s * c0 - bc0);
  out[1][l] = x1 - S(2) * s * w1 + S(2) * bu1 - two_w * (e0123 * b1 + s * c1 - bc1);
  out[2][l] = x2 - S(2) * s * w2 + S(2) * bu2 - two_w * (e0123 * b2 + s * c2 - bc2);
}

template <class S, std::size_t L>
struct ApplyPointLanes {
  S out[3][L];  // the moved point, where ok
  Flag ok[L];

  /// The L elements starting at d (dual quaternions) and p (points).
  void run(const S* d, const S* p) {
    S m[8][L], v[3][L];
    for (std::size_t l = 0; l < L; ++l) {
      load_motor(d + 8 * l, l, m);
      for (std::size_t c = 0; c < 3; ++c) v[c][l] = p[3 * l + c];
    }
    for (std::size_t l = 0; l < L; ++l) {
      S u[8];
      const bool finite_point = runtime::finite3_lane(v[0][l], v[1][l], v[2][l]);
      ok[l] = Flag(normalized_lane(m, l, u)) & Flag(finite_point);
      sandwich_lane(u, v[0][l], v[1][l], v[2][l], l, out);
    }
  }
};

/// pga::operator*() (MOTOR-3, the geometric product of two even elements) of the motors a and b,
/// term by term in its order, into r.
template <class S>
[[gnu::always_inline]] inline void product_lane(const S (&a)[8], const S (&b)[8], S (&r)[8]) {
  const S as = a[0], ab0 = a[1], ab1 = a[2], ab2 = a[3], ac0 = a[4], ac1 = a[5], ac2 = a[6], ap = a[7];
  const S bs = b[0], bb0 = b[1], bb1 = b[2], bb2 = b[3], bc0 = b[4], bc1 = b[5], bc2 = b[6], bp = b[7];
  const S x0 = ab1 * bb2 - ab2 * bb1, x1 = ab2 * bb0 - ab0 * bb2, x2 = ab0 * bb1 - ab1 * bb0;  // ba x bb
  const S y0 = ab1 * bc2 - ab2 * bc1, y1 = ab2 * bc0 - ab0 * bc2, y2 = ab0 * bc1 - ab1 * bc0;  // ba x cb
  const S z0 = ac1 * bb2 - ac2 * bb1, z1 = ac2 * bb0 - ac0 * bb2, z2 = ac0 * bb1 - ac1 * bb0;  // ca x bb
  r[0] = as * bs - (ab0 * bb0 + ab1 * bb1 + ab2 * bb2);
  r[1] = as * bb0 + bs * ab0 - x0;
  r[2] = as * bb1 + bs * ab1 - x1;
  r[3] = as * bb2 + bs * ab2 - x2;
  r[4] = as * bc0 + bs * ac0 - bp * ab0 - ap * bb0 - y0 - z0;
  r[5] = as * bc1 + bs * ac1 - bp * ab1 - ap * bb1 - y1 - z1;
  r[6] = as * bc2 + bs * ac2 - bp * ab2 - ap * bb2 - y2 - z2;
  r[7] = as * bp + ap * bs + (ab0 * bc0 + ab1 * bc1 + ab2 * bc2) + (ac0 * bb0 + ac1 * bb1 + ac2 * bb2);
}

/// pga::to_dual_quaternion() (MOTOR-1 backwards) of the motor u into lane l of out.
template <class S, std::size_t L>
[[gnu::always_inline]] inline void store_dual_quaternion(const S (&u)[8], std::size_t l, S (&out)[8][L]) {
  out[0][l] = -u[1];
  out[1][l] = -u[2];
  out[2][l] = -u[3];
  out[3][l] = u[0];
  out[4][l] = -u[4];
  out[5][l] = -u[5];
  out[6][l] = -u[6];
  out[7][l] = -u[7];
}

/// normalized_motor() of the ABI dual quaternion at x, read through MOTOR-1 in place: the kernels
/// below call it on x = d + 8 l in their loop over lanes l, whose reads the vectoriser turns into
/// vector loads and shuffles (at n = 4096 up to 23% faster than copying into lane arrays first with
/// load_motor; 10% slower only for binary32 dq_normalize).
template <class S>
[[gnu::always_inline]] inline bool normalized_dual_quaternion_lane(const S* x, S (&u)[8]) {
  return normalized_motor(x[3], -x[0], -x[1], -x[2], -x[4], -x[5], -x[6], -x[7], u);
}

/// DQ-4 for L elements of a dq_normalize batch: motor_pga.cpp's MotorPga::dq_normalize() where
/// pga::normalized() takes normalized_ordinary() (the checks it passes then are implied by the
/// test). out holds ABI dual quaternions.
template <class S, std::size_t L>
struct DqNormalizeLanes {
  S out[8][L];  // the unit motor as a dual quaternion, where ok
  Flag ok[L];

  void run(const S* d, const S* /*unused*/) {
    for (std::size_t l = 0; l < L; ++l) {
      S u[8];
      ok[l] = Flag(normalized_dual_quaternion_lane(d + 8 * l, u));
      store_dual_quaternion(u, l, out);
    }
  }
};

/// DQ-2 (MOTOR-3) for L elements of a dq_compose batch: motor_pga.cpp's MotorPga::dq_compose(), the
/// geometric product of both inputs' unit motors, where both normalise by normalized_ordinary().
template <class S, std::size_t L>
struct DqComposeLanes {
  S out[8][L];  // the product as a dual quaternion, where ok
  Flag ok[L];

  void run(const S* a, const S* b) {
    for (std::size_t l = 0; l < L; ++l) {
      S ua[8], ub[8], r[8];
      const bool good_a = normalized_dual_quaternion_lane(a + 8 * l, ua);
      const bool good_b = normalized_dual_quaternion_lane(b + 8 * l, ub);
      ok[l] = Flag(good_a & good_b);
      product_lane(ua, ub, r);
      store_dual_quaternion(r, l, out);
    }
  }
};

/// DQ-1 for L elements of a dq_from_rotation_translation batch: motor_pga.cpp's
/// MotorPga::dq_from_rotation_translation(), the product T(t) R of pga::translator(t) and
/// unit_rotor(q) where |q|^2 is ordinary (unit_rotor() then divides by its sqrt unscaled) and t is
/// finite. The product runs in full, its zero and unit coefficients included: the compiler drops
/// only the terms whose removal IEEE arithmetic allows (x * 1, x - +0), so the signs of zeros stay
/// those of the element path. Data: element e's quaternion at q + 4 e, its translation at t + 3 e
/// (the ABI arrays, read in place).
template <class S, std::size_t L>
struct FromRotationTranslationLanes {
  S out[8][L];  // T(t) R as a dual quaternion, where ok
  Flag ok[L];

  void run(const S* q, const S* t) {
    for (std::size_t l = 0; l < L; ++l) {
      const S qx = q[4 * l], qy = q[4 * l + 1], qz = q[4 * l + 2], qw = q[4 * l + 3];
      const S tx = t[3 * l], ty = t[3 * l + 1], tz = t[3 * l + 2];
      const S n2 = qx * qx + qy * qy + qz * qz + qw * qw;
      const bool ordinary_q = runtime::is_ordinary_square_lane(n2);
      const bool finite_t = runtime::finite3_lane(tx, ty, tz);
      ok[l] = Flag(ordinary_q & finite_t);
      const S n = std::sqrt(n2);
      // pga::rotor(q / n) (Q2R-1) and pga::translator(t) = 1 - 1/2 (t0 e01 + t1 e02 + t2 e03).
      const S rotor[8] = {qw / n, -(qx / n), -(qy / n), -(qz / n), S(0), S(0), S(0), S(0)};
      const S translator[8] = {S(1), S(0), S(0), S(0), -tx / S(2), -ty / S(2), -tz / S(2), S(0)};
      S r[8];
      product_lane(translator, rotor, r);
      store_dual_quaternion(r, l, out);
    }
  }
};

/// motor_pga.cpp's rigid(q, t) = pga::translator(t) * unit_rotor(q) (DQ-1 as T(t) R) into r, for
/// a quaternion whose n2 = |q|^2 is ordinary: FromRotationTranslationLanes' operations, the
/// product in full.
template <class S>
[[gnu::always_inline]] inline void rigid_lane(S qx, S qy, S qz, S qw, S n2, S tx, S ty, S tz, S (&r)[8]) {
  const S n = std::sqrt(n2);
  const S rotor[8] = {qw / n, -(qx / n), -(qy / n), -(qz / n), S(0), S(0), S(0), S(0)};
  const S translator[8] = {S(1), S(0), S(0), S(0), -tx / S(2), -ty / S(2), -tz / S(2), S(0)};
  product_lane(translator, rotor, r);
}

/// SKIN-2 for L elements of a skin_dual_quaternion batch: motor_pga.cpp's
/// MotorPga::skin_dual_quaternion() (the motors T(t_i) R_i blended by blend() against the pivot,
/// MOTOR-5, then the sandwich of the vertex) where the weights pass EDGE-9's tests
/// (runtime::LaneWeights), the vertex and every translation are finite, every |q_i|^2 is ordinary,
/// the filter decides every hemisphere sign (EDGE-3) and the sum normalises by
/// pga::normalized_ordinary(). Data: element e's k rotations at q + 4 k e, translations at
/// t + 3 k e, weights at w + k e, vertex at v + 3 e (the ABI arrays).
template <class S, std::size_t L>
struct SkinDualQuaternionLanes {
  S out[3][L];  // the skinned vertex, where ok
  Flag ok[L];

  void run(std::size_t k, const S* q, const S* t, const S* w, const S* v) {
    runtime::LaneWeights<S, L> weights;  // EDGE-9
    weights.scan(k, w);
    S pivot[4][L], sum[8][L], p[3][L];
    for (std::size_t l = 0; l < L; ++l) {
      // pga::rotor() of the pivot's quaternion as given: (s, e23, e31, e12) = (w, -x, -y, -z).
      const S* x = q + weights.pivot_offset(k, 4, l);
      pivot[0][l] = x[3];
      pivot[1][l] = -x[0];
      pivot[2][l] = -x[1];
      pivot[3][l] = -x[2];
      for (std::size_t c = 0; c < 3; ++c) p[c][l] = v[3 * l + c];
      for (std::size_t c = 0; c < 8; ++c) sum[c][l] = 0;
    }
    for (std::size_t l = 0; l < L; ++l) ok[l] = weights.ok[l] & Flag(runtime::finite3_lane(p[0][l], p[1][l], p[2][l]));
    S x[4][L], tr[3][L];
    for (std::size_t i = 0; i < k; ++i) {
      for (std::size_t l = 0; l < L; ++l) {
        for (std::size_t c = 0; c < 4; ++c) x[c][l] = q[4 * k * l + 4 * i + c];
        for (std::size_t c = 0; c < 3; ++c) tr[c][l] = t[3 * k * l + 3 * i + c];
      }
      for (std::size_t l = 0; l < L; ++l) {
        const S qx = x[0][l], qy = x[1][l], qz = x[2][l], qw = x[3][l];
        const S n2 = qx * qx + qy * qy + qz * qz + qw * qw;  // unit_rotor()'s
        const bool ordinary = runtime::is_ordinary_square_lane(n2);
        const bool finite_t = runtime::finite3_lane(tr[0][l], tr[1][l], tr[2][l]);
        S m[8];
        rigid_lane(qx, qy, qz, qw, n2, tr[0][l], tr[1][l], tr[2][l], m);
        // blend()'s hemisphere_dot(raw(i), raw(p)) on the rotors (w, -x, -y, -z) by the filter of
        // runtime::filtered_dot_sign<S, 4>; undecided -> not ok.
        bool negative;
        const bool decided =
            runtime::filtered_dot4_lane(qw, -qx, -qy, -qz, pivot[0][l], pivot[1][l], pivot[2][l], pivot[3][l], negative);
        const S f0 = w[k * l + i] / weights.w_max[l];
        const S f = negative ? -f0 : f0;
        sum[0][l] = sum[0][l] + f * m[0];  // written out: a loop over c here keeps l's loop scalar
        sum[1][l] = sum[1][l] + f * m[1];
        sum[2][l] = sum[2][l] + f * m[2];
        sum[3][l] = sum[3][l] + f * m[3];
        sum[4][l] = sum[4][l] + f * m[4];
        sum[5][l] = sum[5][l] + f * m[5];
        sum[6][l] = sum[6][l] + f * m[6];
        sum[7][l] = sum[7][l] + f * m[7];
        ok[l] = ok[l] & Flag(ordinary & finite_t & decided);
      }
    }
    for (std::size_t l = 0; l < L; ++l) {
      S u[8];
      ok[l] = ok[l] & Flag(normalized_lane(sum, l, u));
      sandwich_lane(u, p[0][l], p[1][l], p[2][l], l, out);
    }
  }
};

/// AXIS-1 for L elements of a rotate_about_axis batch: motor_pga.cpp's MotorPga::rotate_about_axis()
/// (the sandwich of the point by T_c R ~T_c, R = cos h + sin h (the rotor of u/|u|), h = angle / 2)
/// where the centre, angle and point are finite and |u|^2 is ordinary (unit_rotor() then divides
/// by its sqrt unscaled; u is finite and nonzero). Every product runs in full, zero coefficients
/// included, so that the signs of zeros are the element path's. Data: element e's centre at
/// c + 3 e, axis at u + 3 e, angle at angle + e, point at p + 3 e (the ABI arrays).
template <class S, std::size_t L>
struct RotateAboutAxisLanes {
  S out[3][L];  // the moved point, where ok
  Flag ok[L];

  void run(const S* c, const S* u, const S* angle, const S* p) {
    runtime::AxisAngleLanes<S, L> in;
    in.load(c, u, angle, p);
    for (std::size_t l = 0; l < L; ++l) {
      ok[l] = in.ok[l];
      // pga::rotor(): (e23, e31, e12) = -(x, y, z)/|u| (an exact negation), scaled by sin h.
      const S sn = in.sin_half[l];
      const S r[8] = {in.cos_half[l], sn * -in.axis[0][l], sn * -in.axis[1][l], sn * -in.axis[2][l],
                      S(0),           S(0),                S(0),                S(0)};
      const S cx = in.centre[0][l], cy = in.centre[1][l], cz = in.centre[2][l];
      // pga::translator(c) and its pga::reverse().
      const S tc[8] = {S(1), S(0), S(0), S(0), -cx / S(2), -cy / S(2), -cz / S(2), S(0)};
      const S tc_reverse[8] = {tc[0], -tc[1], -tc[2], -tc[3], -tc[4], -tc[5], -tc[6], tc[7]};
      S tr[8], m[8];
      product_lane(tc, r, tr);
      product_lane(tr, tc_reverse, m);
      sandwich_lane(m, in.point[0][l], in.point[1][l], in.point[2][l], l, out);
    }
  }
};

}  // namespace rotorcert::motor_lanes
