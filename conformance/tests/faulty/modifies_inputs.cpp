// normalize works in place on the caller's input array (a const_cast "optimisation") before
// copying the result out: the numbers are right, the inputs are gone. HYG-1 (claimed by every
// table) must FAIL, and every other clause PASS.
#include <cstddef>
#include <cstdint>
#include <limits>

#include "faulty.hpp"

namespace {
struct Impl : faulty::Correct {
  static constexpr const char* name = "faulty_modifies_inputs";
  static constexpr const char* description = "correct, but normalize overwrites its input array with the result";
  static int normalize_batch(std::size_t n, const double* q, double* out_q, std::uint8_t* status) {
    double* in_place = const_cast<double*>(q);
    for (std::size_t i = 0; i < n; ++i) {
      mutant::Q<double> r{};
      const mutant::Status s = Correct::normalize({q[4 * i], q[4 * i + 1], q[4 * i + 2], q[4 * i + 3]}, r);
      if (s == mutant::Status::domain_error) r.fill(std::numeric_limits<double>::quiet_NaN());
      for (int c = 0; c < 4; ++c) in_place[4 * i + c] = r[c];
      for (int c = 0; c < 4; ++c) out_q[4 * i + c] = in_place[4 * i + c];
      status[i] = static_cast<std::uint8_t>(s);
    }
    return 0;
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(faulty_modifies_inputs, Impl)
