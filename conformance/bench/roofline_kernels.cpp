// Roofline kernels (roofline_kernels.hpp). foreach_target.h compiles the middle part once per
// Highway target; the HWY_ONCE part dispatches to the best one the CPU supports.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "bench/roofline_kernels.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "bench/roofline_kernels.hpp"

HWY_BEFORE_NAMESPACE();
namespace rotorcert::bench::roofline::HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

template <class D, class T>
HWY_INLINE FmaRun FmaChains(D d, std::size_t rounds, T mul, T add) {
  static_assert(kFmaChains == 12, "the chains below are written out");
  const auto m = hn::Set(d, mul), a = hn::Set(d, add);
  // Distinct starting values; each chain converges to a / (1 - m): no overflow, no subnormals.
  auto c0 = hn::Set(d, T(0.01)), c1 = hn::Set(d, T(0.02)), c2 = hn::Set(d, T(0.03)), c3 = hn::Set(d, T(0.04));
  auto c4 = hn::Set(d, T(0.05)), c5 = hn::Set(d, T(0.06)), c6 = hn::Set(d, T(0.07)), c7 = hn::Set(d, T(0.08));
  auto c8 = hn::Set(d, T(0.09)), c9 = hn::Set(d, T(0.10)), c10 = hn::Set(d, T(0.11)), c11 = hn::Set(d, T(0.12));
  for (std::size_t r = 0; r < rounds; ++r) {
    c0 = hn::MulAdd(c0, m, a), c1 = hn::MulAdd(c1, m, a), c2 = hn::MulAdd(c2, m, a), c3 = hn::MulAdd(c3, m, a);
    c4 = hn::MulAdd(c4, m, a), c5 = hn::MulAdd(c5, m, a), c6 = hn::MulAdd(c6, m, a), c7 = hn::MulAdd(c7, m, a);
    c8 = hn::MulAdd(c8, m, a), c9 = hn::MulAdd(c9, m, a), c10 = hn::MulAdd(c10, m, a), c11 = hn::MulAdd(c11, m, a);
  }
  const auto sum = hn::Add(hn::Add(hn::Add(hn::Add(c0, c1), hn::Add(c2, c3)), hn::Add(hn::Add(c4, c5), hn::Add(c6, c7))),
                           hn::Add(hn::Add(c8, c9), hn::Add(c10, c11)));
  FmaRun run;
  run.checksum = static_cast<double>(hn::GetLane(hn::SumOfLanes(d, sum)));
  run.flops = static_cast<double>(rounds) * kFmaChains * static_cast<double>(hn::Lanes(d)) * 2;
  return run;
}

HWY_NOINLINE FmaRun FmaF32(std::size_t rounds, float m, float a) {
  return FmaChains(hn::ScalableTag<float>(), rounds, m, a);
}
HWY_NOINLINE FmaRun FmaF64(std::size_t rounds, double m, double a) {
  return FmaChains(hn::ScalableTag<double>(), rounds, m, a);
}

HWY_NOINLINE double ReadSum(const double* HWY_RESTRICT p, std::size_t n) {
  const hn::ScalableTag<double> d;
  const std::size_t N = hn::Lanes(d);
  // Four accumulators hide the add latency, so the loads set the pace.
  auto s0 = hn::Zero(d), s1 = hn::Zero(d), s2 = hn::Zero(d), s3 = hn::Zero(d);
  std::size_t i = 0;
  for (; i + 4 * N <= n; i += 4 * N) {
    s0 = hn::Add(s0, hn::LoadU(d, p + i));
    s1 = hn::Add(s1, hn::LoadU(d, p + i + N));
    s2 = hn::Add(s2, hn::LoadU(d, p + i + 2 * N));
    s3 = hn::Add(s3, hn::LoadU(d, p + i + 3 * N));
  }
  double tail = 0;
  for (; i < n; ++i) tail += p[i];
  return hn::GetLane(hn::SumOfLanes(d, hn::Add(hn::Add(s0, s1), hn::Add(s2, s3)))) + tail;
}

HWY_NOINLINE void Triad(double* HWY_RESTRICT a, const double* HWY_RESTRICT b, const double* HWY_RESTRICT c, double s,
                        std::size_t n) {
  const hn::ScalableTag<double> d;
  const std::size_t N = hn::Lanes(d);
  const auto vs = hn::Set(d, s);
  std::size_t i = 0;
  for (; i + N <= n; i += N) hn::StoreU(hn::MulAdd(vs, hn::LoadU(d, c + i), hn::LoadU(d, b + i)), d, a + i);
  for (; i < n; ++i) a[i] = b[i] + s * c[i];
}

HWY_NOINLINE const char* TargetName() { return hwy::TargetName(HWY_TARGET); }
HWY_NOINLINE std::size_t LanesF32() { return hn::Lanes(hn::ScalableTag<float>()); }

}  // namespace rotorcert::bench::roofline::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace rotorcert::bench::roofline {

HWY_EXPORT(FmaF32);
HWY_EXPORT(FmaF64);
HWY_EXPORT(ReadSum);
HWY_EXPORT(Triad);
HWY_EXPORT(TargetName);
HWY_EXPORT(LanesF32);

FmaRun fma_f32(std::size_t rounds, float m, float a) { return HWY_DYNAMIC_DISPATCH(FmaF32)(rounds, m, a); }
FmaRun fma_f64(std::size_t rounds, double m, double a) { return HWY_DYNAMIC_DISPATCH(FmaF64)(rounds, m, a); }
double read_sum(const double* p, std::size_t n) { return HWY_DYNAMIC_DISPATCH(ReadSum)(p, n); }
void triad(double* a, const double* b, const double* c, double s, std::size_t n) {
  HWY_DYNAMIC_DISPATCH(Triad)(a, b, c, s, n);
}
const char* target_name() { return HWY_DYNAMIC_DISPATCH(TargetName)(); }
std::size_t lanes_f32() { return HWY_DYNAMIC_DISPATCH(LanesF32)(); }

}  // namespace rotorcert::bench::roofline
#endif  // HWY_ONCE
