// Allocates without bound when normalize meets a zero quaternion (a cache that never evicts);
// under the certify tool's address-space limit malloc fails and the null result is written to.
#include <cstdlib>
#include <cstring>

#include "faulty.hpp"

namespace {
struct Impl : faulty::Correct {
  static constexpr const char* name = "faulty_alloc";
  static constexpr const char* description = "correct, but allocates without bound on normalize(0)";
  static mutant::Status normalize(const mutant::Q<double>& q, mutant::Q<double>& out) {
    if (q[0] == 0 && q[1] == 0 && q[2] == 0 && q[3] == 0)
      for (;;) {
        volatile char* block = static_cast<char*>(std::malloc(std::size_t{64} << 20));
        for (std::size_t i = 0; i < (std::size_t{64} << 20); i += 4096) block[i] = 1;  // touch every page
      }
    return Correct::normalize(q, out);
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(faulty_alloc, Impl)
