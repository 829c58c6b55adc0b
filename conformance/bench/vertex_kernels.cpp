// The frame benchmarks' vertex loops (vertex_kernels.hpp). foreach_target.h compiles the middle
// part once per Highway target; the HWY_ONCE part dispatches to the best one the CPU supports.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "bench/vertex_kernels.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "bench/vertex_kernels.hpp"

HWY_BEFORE_NAMESPACE();
namespace rotorcert::bench::vertices::HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

/// Entry c of influence k of a vector of vertices: palette[offset[k][v] + c] per lane.
template <class D, class VI>
HWY_INLINE hn::Vec<D> entry(D d, const hn::TFromD<D>* palette, VI offset, std::size_t c) {
  return hn::GatherIndex(d, palette + c, offset);
}

template <class S>
HWY_INLINE void SkinLbs(const Streams<S>& s, const S* HWY_RESTRICT palette) {
  const hn::ScalableTag<S> d;
  const hn::RebindToSigned<decltype(d)> di;
  using V = hn::Vec<decltype(d)>;
  const std::size_t N = hn::Lanes(d);
  for (std::size_t i = 0; i < s.count; i += N) {
    const auto o0 = hn::LoadU(di, s.offset[0] + i), o1 = hn::LoadU(di, s.offset[1] + i);
    const auto o2 = hn::LoadU(di, s.offset[2] + i), o3 = hn::LoadU(di, s.offset[3] + i);
    const V w0 = hn::LoadU(d, s.weight[0] + i), w1 = hn::LoadU(d, s.weight[1] + i);
    const V w2 = hn::LoadU(d, s.weight[2] + i), w3 = hn::LoadU(d, s.weight[3] + i);
    // SkinJob's sum, in its order: ((w0 M0 + w1 M1) + w2 M2) + w3 M3.
    V m[12];
    for (std::size_t e = 0; e < 12; ++e) {
      m[e] = hn::MulAdd(w3, entry(d, palette, o3, e),
                        hn::MulAdd(w2, entry(d, palette, o2, e),
                                   hn::MulAdd(w1, entry(d, palette, o1, e), hn::Mul(w0, entry(d, palette, o0, e)))));
    }
    const V p0 = hn::LoadU(d, s.position[0] + i), p1 = hn::LoadU(d, s.position[1] + i);
    const V p2 = hn::LoadU(d, s.position[2] + i);
    const V n0 = hn::LoadU(d, s.normal[0] + i), n1 = hn::LoadU(d, s.normal[1] + i), n2 = hn::LoadU(d, s.normal[2] + i);
    for (std::size_t r = 0; r < 3; ++r) {
      const V p = hn::MulAdd(m[6 + r], p2, hn::MulAdd(m[3 + r], p1, hn::MulAdd(m[r], p0, m[9 + r])));
      const V n = hn::MulAdd(m[6 + r], n2, hn::MulAdd(m[3 + r], n1, hn::Mul(m[r], n0)));
      hn::StoreU(p, d, s.position_out[r] + i);
      hn::StoreU(n, d, s.normal_out[r] + i);
    }
  }
}

template <class S>
HWY_INLINE void SkinDqs(const Streams<S>& s, const S* HWY_RESTRICT palette) {
  const hn::ScalableTag<S> d;
  const hn::RebindToSigned<decltype(d)> di;
  using V = hn::Vec<decltype(d)>;
  using VI = hn::Vec<decltype(di)>;
  const std::size_t N = hn::Lanes(d);
  const V zero = hn::Zero(d);
  for (std::size_t i = 0; i < s.count; i += N) {
    const VI o[4] = {hn::LoadU(di, s.offset[0] + i), hn::LoadU(di, s.offset[1] + i), hn::LoadU(di, s.offset[2] + i),
                     hn::LoadU(di, s.offset[3] + i)};
    V w[4] = {hn::LoadU(d, s.weight[0] + i), hn::LoadU(d, s.weight[1] + i), hn::LoadU(d, s.weight[2] + i),
              hn::LoadU(d, s.weight[3] + i)};
    V real[4][4];  // real[k][c]: component c of influence k's real part
    for (std::size_t k = 0; k < 4; ++k)
      for (std::size_t c = 0; c < 4; ++c) real[k][c] = entry(d, palette, o[k], c);
    // The pivot: the first influence of weight > 0 (DQ-6), else the last.
    V pivot[4];
    const auto take0 = hn::Gt(w[0], zero), take1 = hn::Gt(w[1], zero), take2 = hn::Gt(w[2], zero);
    for (std::size_t c = 0; c < 4; ++c)
      pivot[c] = hn::IfThenElse(take0, real[0][c], hn::IfThenElse(take1, real[1][c], hn::IfThenElse(take2, real[2][c], real[3][c])));
    for (std::size_t k = 0; k < 4; ++k) {
      const V dot = hn::MulAdd(real[k][3], pivot[3],
                               hn::MulAdd(real[k][2], pivot[2], hn::MulAdd(real[k][1], pivot[1], hn::Mul(real[k][0], pivot[0]))));
      w[k] = hn::IfThenElse(hn::Lt(dot, zero), hn::Neg(w[k]), w[k]);
    }
    V b[8];
    for (std::size_t c = 0; c < 4; ++c)
      b[c] = hn::MulAdd(w[3], real[3][c], hn::MulAdd(w[2], real[2][c], hn::MulAdd(w[1], real[1][c], hn::Mul(w[0], real[0][c]))));
    for (std::size_t c = 4; c < 8; ++c)
      b[c] = hn::MulAdd(w[3], entry(d, palette, o[3], c),
                        hn::MulAdd(w[2], entry(d, palette, o[2], c),
                                   hn::MulAdd(w[1], entry(d, palette, o[1], c), hn::Mul(w[0], entry(d, palette, o[0], c)))));
    const V x = b[0], y = b[1], z = b[2], ww = b[3], dx = b[4], dy = b[5], dz = b[6], dw = b[7];
    // sc = 2 / |b_r|^2: the rotation matrix of the unnormalised b_r (MAT-1 scaled by 1 / |b_r|^2)
    // and t = 2 vec(b_d b_r*) / |b_r|^2 need no square root.
    const V sc = hn::Div(hn::Set(d, S(2)), hn::MulAdd(ww, ww, hn::MulAdd(z, z, hn::MulAdd(y, y, hn::Mul(x, x)))));
    const V xs = hn::Mul(x, sc), ys = hn::Mul(y, sc), zs = hn::Mul(z, sc);
    const V wx = hn::Mul(ww, xs), wy = hn::Mul(ww, ys), wz = hn::Mul(ww, zs);
    const V xx = hn::Mul(x, xs), xy = hn::Mul(x, ys), xz = hn::Mul(x, zs);
    const V yy = hn::Mul(y, ys), yz = hn::Mul(y, zs), zz = hn::Mul(z, zs);
    const V one = hn::Set(d, S(1));
    const V m00 = hn::Sub(one, hn::Add(yy, zz)), m01 = hn::Sub(xy, wz), m02 = hn::Add(xz, wy);
    const V m10 = hn::Add(xy, wz), m11 = hn::Sub(one, hn::Add(xx, zz)), m12 = hn::Sub(yz, wx);
    const V m20 = hn::Sub(xz, wy), m21 = hn::Add(yz, wx), m22 = hn::Sub(one, hn::Add(xx, yy));
    // t = sc (w d - dw v + v x d), v = (x, y, z), d = (dx, dy, dz).
    const V tx = hn::Mul(sc, hn::Add(hn::NegMulAdd(dw, x, hn::Mul(ww, dx)), hn::MulSub(y, dz, hn::Mul(z, dy))));
    const V ty = hn::Mul(sc, hn::Add(hn::NegMulAdd(dw, y, hn::Mul(ww, dy)), hn::MulSub(z, dx, hn::Mul(x, dz))));
    const V tz = hn::Mul(sc, hn::Add(hn::NegMulAdd(dw, z, hn::Mul(ww, dz)), hn::MulSub(x, dy, hn::Mul(y, dx))));
    const V p0 = hn::LoadU(d, s.position[0] + i), p1 = hn::LoadU(d, s.position[1] + i);
    const V p2 = hn::LoadU(d, s.position[2] + i);
    const V n0 = hn::LoadU(d, s.normal[0] + i), n1 = hn::LoadU(d, s.normal[1] + i), n2 = hn::LoadU(d, s.normal[2] + i);
    hn::StoreU(hn::MulAdd(m02, p2, hn::MulAdd(m01, p1, hn::MulAdd(m00, p0, tx))), d, s.position_out[0] + i);
    hn::StoreU(hn::MulAdd(m12, p2, hn::MulAdd(m11, p1, hn::MulAdd(m10, p0, ty))), d, s.position_out[1] + i);
    hn::StoreU(hn::MulAdd(m22, p2, hn::MulAdd(m21, p1, hn::MulAdd(m20, p0, tz))), d, s.position_out[2] + i);
    hn::StoreU(hn::MulAdd(m02, n2, hn::MulAdd(m01, n1, hn::Mul(m00, n0))), d, s.normal_out[0] + i);
    hn::StoreU(hn::MulAdd(m12, n2, hn::MulAdd(m11, n1, hn::Mul(m10, n0))), d, s.normal_out[1] + i);
    hn::StoreU(hn::MulAdd(m22, n2, hn::MulAdd(m21, n1, hn::Mul(m20, n0))), d, s.normal_out[2] + i);
  }
}

HWY_NOINLINE void SkinLbsF32(const Streams<float>& s, const float* palette) { SkinLbs(s, palette); }
HWY_NOINLINE void SkinLbsF64(const Streams<double>& s, const double* palette) { SkinLbs(s, palette); }
HWY_NOINLINE void SkinDqsF32(const Streams<float>& s, const float* palette) { SkinDqs(s, palette); }
HWY_NOINLINE void SkinDqsF64(const Streams<double>& s, const double* palette) { SkinDqs(s, palette); }

}  // namespace rotorcert::bench::vertices::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace rotorcert::bench::vertices {

HWY_EXPORT(SkinLbsF32);
HWY_EXPORT(SkinLbsF64);
HWY_EXPORT(SkinDqsF32);
HWY_EXPORT(SkinDqsF64);

void skin_lbs(const Streams<float>& v, const float* palette) { HWY_DYNAMIC_DISPATCH(SkinLbsF32)(v, palette); }
void skin_lbs(const Streams<double>& v, const double* palette) { HWY_DYNAMIC_DISPATCH(SkinLbsF64)(v, palette); }
void skin_dqs(const Streams<float>& v, const float* palette) { HWY_DYNAMIC_DISPATCH(SkinDqsF32)(v, palette); }
void skin_dqs(const Streams<double>& v, const double* palette) { HWY_DYNAMIC_DISPATCH(SkinDqsF64)(v, palette); }

}  // namespace rotorcert::bench::vertices
#endif  // HWY_ONCE
