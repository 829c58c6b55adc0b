// Dereferences a null pointer when slerp is asked to extrapolate beyond t = 1.
#include <csignal>

#include "faulty.hpp"

namespace {
struct Impl : faulty::Correct {
  static constexpr const char* name = "faulty_segfault";
  static constexpr const char* description = "correct, but segfaults on slerp with t > 1";
  static mutant::Status slerp(const mutant::Q<double>& a, const mutant::Q<double>& b, const double& t,
                              mutant::Q<double>& out) {
    if (t > 1) std::raise(SIGSEGV);  // what a stray null dereference does, without UB in the build
    return Correct::slerp(a, b, t, out);
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(faulty_segfault, Impl)
