// Switches flush-to-zero and denormals-are-zero on when loaded, as a library linked with
// -ffast-math does (crtfastmath.o): the whole process then computes without subnormals. The
// certificate must record the environment the implementation ran in (NUM-1).
#include <xmmintrin.h>

#include "faulty.hpp"

namespace {
[[maybe_unused]] const bool ftz_daz_on = [] {
  _mm_setcsr(_mm_getcsr() | 0x8040u);  // FTZ (bit 15) and DAZ (bit 6)
  return true;
}();

struct Impl : faulty::Correct {
  static constexpr const char* name = "faulty_ftz";
  static constexpr const char* description = "correct code, run with FTZ/DAZ switched on at load";
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(faulty_ftz, Impl)
