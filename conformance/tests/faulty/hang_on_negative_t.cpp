// Loops forever when slerp is asked for t < 0 (a root finder that never converges).
#include <atomic>

#include "faulty.hpp"

namespace {
std::atomic<bool> converged{false};  // never set: the loop cannot be optimised away
struct Impl : faulty::Correct {
  static constexpr const char* name = "faulty_hang";
  static constexpr const char* description = "correct, but never returns from slerp with t < 0";
  static mutant::Status slerp(const mutant::Q<double>& a, const mutant::Q<double>& b, const double& t,
                              mutant::Q<double>& out) {
    while (t < 0 && !converged.load()) {
    }
    return Correct::slerp(a, b, t, out);
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(faulty_hang, Impl)
