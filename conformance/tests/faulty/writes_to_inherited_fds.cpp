// When slerp is asked to extrapolate beyond t = 1, writes a log line to every descriptor from 3 up
// that it inherited (a logger that assumes its side channel is "whatever is open"): one of them is
// the child's channel to the certify tool. The tool reads that channel as untrusted input: bytes
// that are not a frame of its own end the child, and the clause is CRASH, never PASS.
// For the test: ROTORCERT_FAULTY_FD_PAYLOAD_FILE names a file whose bytes are written instead of
// the log line (a forged frame, say), and ROTORCERT_FAULTY_FD_EXIT=1 ends the process with
// _exit(0) right after, as if the clause were over.
#include <fcntl.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

#include "faulty.hpp"

namespace {
std::string payload() {
  std::string text = "faulty_inherited_fds: extrapolating \xff\n";
  if (const char* file = std::getenv("ROTORCERT_FAULTY_FD_PAYLOAD_FILE")) {
    const int fd = ::open(file, O_RDONLY | O_CLOEXEC);
    if (fd < 0) return text;
    text.clear();
    char buf[4096];
    for (ssize_t got; (got = ::read(fd, buf, sizeof buf)) > 0;) text.append(buf, std::size_t(got));
    ::close(fd);
  }
  return text;
}

struct Impl : faulty::Correct {
  static constexpr const char* name = "faulty_inherited_fds";
  static constexpr const char* description = "correct, but writes to every inherited descriptor on slerp t > 1";
  static mutant::Status slerp(const mutant::Q<double>& a, const mutant::Q<double>& b, const double& t,
                              mutant::Q<double>& out) {
    if (t > 1) {
      const std::string text = payload();
      for (int fd = 3; fd < 256; ++fd) [[maybe_unused]] const auto ignored = ::write(fd, text.data(), text.size());
      if (const char* end = std::getenv("ROTORCERT_FAULTY_FD_EXIT"); end && std::string(end) == "1") ::_exit(0);
    }
    return Correct::slerp(a, b, t, out);
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(faulty_inherited_fds, Impl)
