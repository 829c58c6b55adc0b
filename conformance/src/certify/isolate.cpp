#include <rotorcert/certify/isolate.hpp>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <vector>

namespace rotorcert::certify {
namespace {

using Clock = std::chrono::steady_clock;

void write_all(int fd, const char* p, std::size_t n) {
  while (n > 0) {
    const ssize_t w = ::write(fd, p, n);
    if (w < 0 && errno == EINTR) continue;
    if (w < 0) ::_exit(120);  // the parent is gone: nothing left to report to
    p += w;
    n -= static_cast<std::size_t>(w);
  }
}

std::string signal_text(int sig) {
  const char* name = sigabbrev_np(sig);
  return std::string(name ? std::string("SIG") + name : "signal") + " (signal " + std::to_string(sig) + ", " +
         strsignal(sig) + ")";
}

}  // namespace

bool built_with_sanitizer() {
#if defined(__SANITIZE_ADDRESS__)
  return true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer) || __has_feature(thread_sanitizer)
  return true;
#else
  return false;
#endif
#else
  return false;
#endif
}

// Frames: one kind byte ('P' progress, 'R' result, 'E' uncaught exception), a decimal length,
// ':', the payload.
void ChildChannel::frame(char kind, const std::string& payload) {
  const std::string head = std::string(1, kind) + std::to_string(payload.size()) + ":";
  write_all(fd_, head.data(), head.size());
  write_all(fd_, payload.data(), payload.size());
}

void ChildChannel::progress(const std::string& text) { frame('P', text); }

struct ChildPool::Running {
  std::size_t id = 0;
  pid_t pid = -1;
  int fd = -1;
  bool eof = false;
  std::string buffer;  // bytes read, not yet parsed
  ChildOutcome outcome;
  bool got_result = false, got_exception = false;
  Clock::time_point started, deadline;
  bool killed_for_time = false;

  /// Parses complete frames out of the buffer.
  void parse() {
    for (;;) {
      const std::size_t colon = buffer.find(':');
      if (buffer.empty() || colon == std::string::npos) return;
      const std::size_t len = std::stoul(buffer.substr(1, colon - 1));
      if (buffer.size() < colon + 1 + len) return;
      std::string payload = buffer.substr(colon + 1, len);
      const char kind = buffer[0];
      buffer.erase(0, colon + 1 + len);
      if (kind == 'P') outcome.last_progress = std::move(payload);
      else if (kind == 'R') outcome.result = std::move(payload), got_result = true;
      else if (kind == 'E') outcome.message = "uncaught exception: " + payload, got_exception = true;
    }
  }
};

ChildPool::ChildPool(int jobs, ChildLimits limits) : jobs_(jobs < 1 ? 1 : jobs), limits_(limits) {}

ChildPool::~ChildPool() {
  for (auto& [pid, r] : running_) {
    ::kill(pid, SIGKILL);
    ::waitpid(pid, nullptr, 0);
    ::close(r->fd);
    delete r;
  }
}

void ChildPool::submit(std::size_t id, Task task) {
  if (static_cast<int>(running_.size()) < jobs_) start(id, std::move(task));
  else queued_.emplace_back(id, std::move(task));
}

void ChildPool::start(std::size_t id, Task task) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
  if (pid == 0) {
    ::close(fds[0]);
    if (limits_.memory_mb > 0 && !built_with_sanitizer()) {
      const rlim_t bytes = static_cast<rlim_t>(limits_.memory_mb) << 20;
      const rlimit rl{bytes, bytes};
      ::setrlimit(RLIMIT_AS, &rl);
    }
    ::signal(SIGPIPE, SIG_DFL);
    ChildChannel channel(fds[1]);
    int code = 0;
    try {
      channel.frame('R', task(channel));
    } catch (const std::exception& e) {
      channel.frame('E', e.what());
      code = 3;
    } catch (...) {
      channel.frame('E', "an exception not derived from std::exception");
      code = 3;
    }
    std::fflush(stdout);
    std::fflush(stderr);
    ::_exit(code);  // no destructors, no atexit handlers of the implementation under test
  }
  ::close(fds[1]);
  ::fcntl(fds[0], F_SETFL, O_NONBLOCK);
  auto* r = new Running;
  r->id = id;
  r->pid = pid;
  r->fd = fds[0];
  r->started = Clock::now();
  r->deadline = r->started + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limits_.timeout_s));
  running_[pid] = r;
}

std::pair<std::size_t, ChildOutcome> ChildPool::wait_any() {
  if (running_.empty()) throw std::logic_error("ChildPool::wait_any with nothing running");
  for (;;) {
    // A child is done when its pipe is closed (it exited, or was killed) and it has been reaped.
    for (auto it = running_.begin(); it != running_.end(); ++it) {
      Running* r = it->second;
      if (!r->eof) continue;
      int wstatus = 0;
      if (::waitpid(r->pid, &wstatus, 0) < 0) wstatus = 0;
      ChildOutcome out = std::move(r->outcome);
      out.seconds = std::chrono::duration<double>(Clock::now() - r->started).count();
      if (r->killed_for_time) {
        out.kind = ChildOutcome::Kind::timed_out;
        char limit[32];
        std::snprintf(limit, sizeof limit, "%g", limits_.timeout_s);
        out.message = std::string("no result within the wall-clock limit of ") + limit + " s";
      } else if (WIFSIGNALED(wstatus)) {
        out.kind = ChildOutcome::Kind::crashed;
        out.message = "terminated by " + signal_text(WTERMSIG(wstatus));
      } else if (WIFEXITED(wstatus) && WEXITSTATUS(wstatus) == 0 && r->got_result) {
        out.kind = ChildOutcome::Kind::finished;
      } else {
        out.kind = ChildOutcome::Kind::crashed;
        if (!r->got_exception)
          out.message = "exited with status " + std::to_string(WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : -1) +
                        " before handing over a result";
      }
      const std::size_t id = r->id;
      ::close(r->fd);
      delete r;
      running_.erase(it);
      if (!queued_.empty()) {
        auto next = std::move(queued_.front());
        queued_.erase(queued_.begin());
        start(next.first, std::move(next.second));
      }
      return {id, std::move(out)};
    }
    // Wait for output or the nearest deadline.
    std::vector<pollfd> pfds;
    std::vector<Running*> order;
    auto nearest = Clock::time_point::max();
    for (auto& [pid, r] : running_) {
      pfds.push_back({r->fd, POLLIN, 0});
      order.push_back(r);
      if (!r->killed_for_time) nearest = std::min(nearest, r->deadline);
    }
    int wait_ms = -1;
    if (nearest != Clock::time_point::max()) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(nearest - Clock::now()).count();
      wait_ms = static_cast<int>(std::max<long long>(0, std::min<long long>(left + 1, 60'000)));
    }
    const int n = ::poll(pfds.data(), pfds.size(), wait_ms);
    if (n < 0 && errno != EINTR) throw std::runtime_error(std::string("poll: ") + std::strerror(errno));
    for (std::size_t i = 0; i < pfds.size(); ++i) {
      if (!(pfds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      Running* r = order[i];
      char buf[65536];
      for (;;) {
        const ssize_t got = ::read(r->fd, buf, sizeof buf);
        if (got > 0) {
          r->buffer.append(buf, static_cast<std::size_t>(got));
          continue;
        }
        if (got == 0) r->eof = true;
        else if (errno == EINTR) continue;
        break;  // EAGAIN: drained for now
      }
      r->parse();
    }
    const auto now = Clock::now();
    for (auto& [pid, r] : running_)
      if (!r->killed_for_time && !r->eof && now >= r->deadline) {
        ::kill(pid, SIGKILL);
        r->killed_for_time = true;  // its pipe closes as it dies
      }
  }
}

}  // namespace rotorcert::certify
