// Loops forever when slerp is asked for t < 0 (a root finder that never converges).

#include "faulty.hpp"

namespace {
// Never set. Volatile, not a std::atomic: clang 14 folds the load of an internal atomic that
// nothing stores to, and then removes the loop as one without side effects (a hang that returns).
volatile bool converged = false;
struct Impl : faulty::Correct {
  static constexpr const char* name = "faulty_hang";
  static constexpr const char* description = "correct, but never returns from slerp with t < 0";
  static mutant::Status slerp(const mutant::Q<double>& a, const mutant::Q<double>& b, const double& t,
                              mutant::Q<double>& out) {
    while (t < 0 && !converged) {
    }
    return Correct::slerp(a, b, t, out);
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(faulty_hang, Impl)
