// Recurses without bound when slerp is asked to extrapolate beyond t = 1 (a subdivision that never
// reaches its base case): the stack overflows, the child dies of SIGSEGV on the guard page.
#include "faulty.hpp"

namespace {
// Each frame keeps a buffer alive across the call, so the recursion cannot become a loop.
double subdivide(double t, int depth) {
  volatile double frame[32];
  frame[depth % 32] = t;
  if (t <= 1) return frame[depth % 32];
  return subdivide(t, depth + 1) + frame[(depth + 1) % 32];
}

struct Impl : faulty::Correct {
  static constexpr const char* name = "faulty_recursion";
  static constexpr const char* description = "correct, but overflows its stack on slerp with t > 1";
  static mutant::Status slerp(const mutant::Q<double>& a, const mutant::Q<double>& b, const double& t,
                              mutant::Q<double>& out) {
    if (t > 1 && subdivide(t, 0) != t) return mutant::Status::domain_error;  // never returns
    return Correct::slerp(a, b, t, out);
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(faulty_recursion, Impl)
