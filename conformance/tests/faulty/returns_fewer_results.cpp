// normalize handles one element fewer than it is asked for (an off-by-one in its batch loop): the
// last element's status byte and outputs are left as the caller's buffers had them. The suite
// pre-fills the status bytes with a value no implementation writes, so the element is judged, and
// fails, instead of passing on whatever the buffer held.
#include <cstddef>
#include <cstdint>
#include <limits>

#include "faulty.hpp"

namespace {
struct Impl : faulty::Correct {
  static constexpr const char* name = "faulty_fewer_results";
  static constexpr const char* description = "correct, but normalize leaves the last element of each batch unwritten";
  static int normalize_batch(std::size_t n, const double* q, double* out_q, std::uint8_t* status) {
    for (std::size_t i = 0; i + 1 < n; ++i) {
      mutant::Q<double> in{q[4 * i], q[4 * i + 1], q[4 * i + 2], q[4 * i + 3]}, r{};
      const mutant::Status s = Correct::normalize(in, r);
      if (s == mutant::Status::domain_error) r.fill(std::numeric_limits<double>::quiet_NaN());
      for (int c = 0; c < 4; ++c) out_q[4 * i + c] = r[c];
      status[i] = static_cast<std::uint8_t>(s);
    }
    return 0;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(faulty_fewer_results, Impl)
