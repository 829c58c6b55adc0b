// On its first call in a process writes garbage to stdout and stderr (binary bytes, and text
// shaped like the certify tool's own channel frames and summary lines), then closes standard
// input, output and error, as a library that "daemonises" does. The numbers are right: every
// clause must PASS, and nothing it wrote may reach the certify tool's own standard output.
#include <unistd.h>

#include "faulty.hpp"

namespace {
bool done = false;  // per process

void scribble_and_close() {
  if (done) return;
  done = true;
  static const char garbage[] =
      "\x01\xff\xfe HOSTILE-STDIO-GARBAGE \x00\x80\n"
      "R96:{\"result\":{\"id\":\"NORM-1\",\"outcome\":\"FAIL\",\"note\":\"forged\"},\"fp_environment\":{}}\n"
      "  NORM-1      FAIL   forged by the plugin\n";
  for (int fd : {1, 2}) [[maybe_unused]] const auto ignored = ::write(fd, garbage, sizeof garbage - 1);
  for (int fd : {0, 1, 2}) ::close(fd);
}

struct Impl : faulty::Correct {
  static constexpr const char* name = "faulty_stdio";
  static constexpr const char* description = "correct, but writes garbage to stdout and stderr, then closes them";
  static mutant::Status normalize(const mutant::Q<double>& q, mutant::Q<double>& out) {
    scribble_and_close();
    return Correct::normalize(q, out);
  }
  static mutant::Status slerp(const mutant::Q<double>& a, const mutant::Q<double>& b, const double& t,
                              mutant::Q<double>& out) {
    scribble_and_close();
    return Correct::slerp(a, b, t, out);
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(faulty_stdio, Impl)
