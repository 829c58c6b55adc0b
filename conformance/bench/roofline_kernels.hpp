// The roofline's kernels, on Google Highway with dynamic dispatch (the best target of this CPU):
// peak FMA throughput and STREAM-like memory bandwidth. roofline.cpp times them.
#pragma once

#include <cstddef>

namespace rotorcert::bench::roofline {

/// Independent FMA accumulator chains: enough to cover FMA latency x throughput on current x86
/// (4 cycles x 2 ports = 8) with room to spare, few enough for 16 vector registers (AVX2).
inline constexpr std::size_t kFmaChains = 12;

struct FmaRun {
  double checksum = 0;  // sum of the accumulators, so the chains are not dead code
  double flops = 0;     // rounds x kFmaChains x lanes x 2
};

/// `rounds` of one FMA acc = acc * m + a per chain (m and a come from the caller, so nothing
/// can be folded at compile time).
FmaRun fma_f32(std::size_t rounds, float m, float a);
FmaRun fma_f64(std::size_t rounds, double m, double a);

/// Sum of p[0 .. n): reads n doubles.
double read_sum(const double* p, std::size_t n);

/// a[i] = b[i] + s c[i] (STREAM triad): reads 2n doubles, writes n.
void triad(double* a, const double* b, const double* c, double s, std::size_t n);

/// The Highway target dynamic dispatch chose, e.g. "AVX3".
const char* target_name();

/// Lanes of a float vector of that target.
std::size_t lanes_f32();

}  // namespace rotorcert::bench::roofline
