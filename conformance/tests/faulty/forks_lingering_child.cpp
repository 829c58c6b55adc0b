// Forks a helper process on its first normalize call (a library that starts a background daemon)
// and leaves it running: the helper inherits every descriptor, the channel to the certify tool
// included, so the channel does not close when the child process exits. One fork per process at
// most, and the helper ends by itself after 60 s, so the fork count stays bounded even if the suite
// fails to end it. With ROTORCERT_FAULTY_PID_FILE set, the child appends "helper_pid group_id" to
// that file, for the test to check that the suite ended the helper with the child's group.
#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "faulty.hpp"

namespace {
bool forked = false;  // per process

void fork_helper() {
  if (forked) return;
  forked = true;
  const pid_t helper = ::fork();
  if (helper == 0) {
    for (int s = 0; s < 60; ++s) ::sleep(1);
    ::_exit(0);
  }
  if (helper < 0) return;
  if (const char* file = std::getenv("ROTORCERT_FAULTY_PID_FILE")) {
    const int fd = ::open(file, O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
    if (fd < 0) return;
    char line[64];
    const int len = std::snprintf(line, sizeof line, "%d %d\n", int(helper), int(::getpgid(0)));
    [[maybe_unused]] const auto ignored = ::write(fd, line, std::size_t(len));
    ::close(fd);
  }
}

struct Impl : faulty::Correct {
  static constexpr const char* name = "faulty_forks";
  static constexpr const char* description = "correct, but forks a helper process that outlives the call";
  static mutant::Status normalize(const mutant::Q<double>& q, mutant::Q<double>& out) {
    fork_helper();
    return Correct::normalize(q, out);
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(faulty_forks, Impl)
