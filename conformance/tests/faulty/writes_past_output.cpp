// slerp's batch loop writes an end marker one element past the end of its output arrays (an
// off-by-one, "i <= n"): four scalars after out_q[4 n - 1] and a status byte after status[n - 1],
// memory the caller did not hand over. Every element it was asked for is correct.
#include <cstddef>
#include <cstdint>
#include <limits>

#include "faulty.hpp"

namespace {
struct Impl : faulty::Correct {
  static constexpr const char* name = "faulty_overrun";
  static constexpr const char* description = "correct, but slerp writes one element past the end of its outputs";
  static int slerp_batch(std::size_t n, const double* a, const double* b, const double* t, double* out_q,
                         std::uint8_t* status) {
    for (std::size_t i = 0; i <= n; ++i) {
      mutant::Q<double> r{0, 0, 0, 0};
      mutant::Status s = mutant::Status::ok;  // element n: the end marker, a zero quaternion
      if (i < n) {
        const mutant::Q<double> qa{a[4 * i], a[4 * i + 1], a[4 * i + 2], a[4 * i + 3]};
        const mutant::Q<double> qb{b[4 * i], b[4 * i + 1], b[4 * i + 2], b[4 * i + 3]};
        s = Correct::slerp(qa, qb, t[i], r);
        if (s == mutant::Status::domain_error) r.fill(std::numeric_limits<double>::quiet_NaN());
      }
      for (int c = 0; c < 4; ++c) out_q[4 * i + c] = r[c];
      status[i] = static_cast<std::uint8_t>(s);
    }
    return 0;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(faulty_overrun, Impl)
