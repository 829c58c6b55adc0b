// Calls exit(0) when slerp is asked to extrapolate beyond t = 1 (a library that "handles" a bad
// argument by ending the program, successfully). Atexit handlers and static destructors run, the
// status is 0, and no result was handed over: that must never read as PASS.
#include <cstdlib>

#include "faulty.hpp"

namespace {
struct Impl : faulty::Correct {
  static constexpr const char* name = "faulty_exit";
  static constexpr const char* description = "correct, but calls exit(0) on slerp with t > 1";
  static mutant::Status slerp(const mutant::Q<double>& a, const mutant::Q<double>& b, const double& t,
                              mutant::Q<double>& out) {
    if (t > 1) std::exit(0);
    return Correct::slerp(a, b, t, out);
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(faulty_exit, Impl)
