#include <rotorcert/certify/isolate.hpp>


#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/random.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <string_view>
#include <vector>

#include <rotorcert/certify/interrupt.hpp>

namespace rotorcert::certify {
namespace {

using Clock = std::chrono::steady_clock;

// The child's channel is untrusted input: the implementation runs in the child's address space
// and may write to any descriptor it has. These bound what the parent accepts from it.
constexpr std::size_t kMaxProgressBytes = std::size_t{1} << 20;  // one progress line
constexpr std::size_t kMaxResultBytes = std::size_t{1} << 30;    // one result (error lists included)
constexpr std::size_t kMaxLengthDigits = 10;
constexpr std::size_t kMaxMessageBytes = 4000;  // of a message kept for the report
// The exit status of a child that could not write to its channel (the parent is gone, or the
// implementation closed or replaced the descriptor).
constexpr int kChannelLost = 120;

/// In a child: the token its frames carry (one child per process, set right after the fork).
std::string child_token;

/// A fresh random token for one child's channel: 32 hex digits. Every frame carries it, so bytes
/// the implementation writes to the channel (it is a descriptor of the child like any other)
/// cannot pass for a frame unless it reads the token out of the child's memory.
std::string new_token() {
  unsigned char b[16];
  if (::getrandom(b, sizeof b, 0) != static_cast<ssize_t>(sizeof b)) {
    static std::uint64_t counter = 0;
    const auto now = static_cast<std::uint64_t>(Clock::now().time_since_epoch().count());
    const std::uint64_t mix[2] = {now ^ (static_cast<std::uint64_t>(::getpid()) << 40), ++counter * 0x9E3779B97F4A7C15ull};
    std::memcpy(b, mix, sizeof b);
  }
  static const char digits[] = "0123456789abcdef";
  std::string t;
  for (unsigned char c : b) t += digits[c >> 4], t += digits[c & 15];
  return t;
}

void write_all(int fd, const char* p, std::size_t n) {
  while (n > 0) {
    const ssize_t w = ::write(fd, p, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) ::_exit(kChannelLost);  // nothing left to report to
    p += w;
    n -= static_cast<std::size_t>(w);
  }
}

std::string signal_text(int sig) {
  const char* name = sigabbrev_np(sig);
  return std::string(name ? std::string("SIG") + name : "signal") + " (signal " + std::to_string(sig) + ", " +
         strsignal(sig) + ")";
}

/// Text from the child as the report may show it: valid UTF-8 without control characters (those
/// and every invalid byte become \xNN), at most `max` bytes of it. report.json is JSON, and the
/// JSON writer rejects invalid UTF-8.
std::string printable(std::string_view s, std::size_t max = kMaxMessageBytes) {
  std::string r;
  auto escape = [&](unsigned char c) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "\\x%02X", c);
    r += buf;
  };
  std::size_t i = 0;
  while (i < s.size() && r.size() < max) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c < 0x80) {
      if (c < 0x20 || c == 0x7F) escape(c);
      else r += static_cast<char>(c);
      ++i;
      continue;
    }
    // A UTF-8 sequence: its length from the lead byte, continuation bytes 10xxxxxx, no overlong
    // forms, no surrogates, nothing above U+10FFFF.
    const std::size_t len = c >= 0xC2 && c <= 0xDF ? 2 : c >= 0xE0 && c <= 0xEF ? 3 : c >= 0xF0 && c <= 0xF4 ? 4 : 0;
    bool ok = len > 0 && i + len <= s.size();
    for (std::size_t k = 1; ok && k < len; ++k) ok = (static_cast<unsigned char>(s[i + k]) & 0xC0) == 0x80;
    if (ok && len >= 3) {
      const auto c1 = static_cast<unsigned char>(s[i + 1]);
      ok = !(c == 0xE0 && c1 < 0xA0) && !(c == 0xED && c1 >= 0xA0) && !(c == 0xF0 && c1 < 0x90) && !(c == 0xF4 && c1 >= 0x90);
    }
    if (!ok) {
      escape(c);
      ++i;
      continue;
    }
    r.append(s.substr(i, len));
    i += len;
  }
  if (i < s.size()) r += " [cut]";
  return r;
}

/// Closes every descriptor from `from` on (close_range where the kernel has it, one by one else).
void close_from(unsigned from) {
#ifdef SYS_close_range
  if (::syscall(SYS_close_range, from, ~0U, 0) == 0) return;
#endif
  long max = ::sysconf(_SC_OPEN_MAX);
  if (max < 0 || max > 65536) max = 65536;
  for (long fd = from; fd < max; ++fd) ::close(static_cast<int>(fd));
}

/// The child's process environment, before any code of the implementation runs: its own process
/// group (the parent ends the whole group, helpers the implementation forks included); killed
/// if the parent dies; the channel at descriptor 3 and no other descriptors above stdio; stdin
/// from /dev/null; stdout onto stderr, so that nothing the child prints can reach the tool's own
/// standard output. Returns the channel's descriptor.
int prepare_child(int channel, pid_t parent) {
  ::setpgid(0, 0);
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() != parent) ::_exit(kChannelLost);  // the parent died before the line above
  // The channel first (it may sit at 0..2 when the tool was started with stdio closed), close-on-
  // exec; everything above it closed (other children's pipes, whatever the tool's caller left open).
  if (channel != 3) {
    if (::dup3(channel, 3, O_CLOEXEC) < 0) ::_exit(kChannelLost);
    ::close(channel);
  } else {
    ::fcntl(3, F_SETFD, FD_CLOEXEC);
  }
  close_from(4);
  const int null = ::open("/dev/null", O_RDWR);  // 0..2 itself where one was closed
  if (null >= 0 && null != 0) ::dup2(null, 0);
  if (::dup2(2, 1) < 0 && null >= 0) ::dup2(null, 1);  // stderr closed: stdout goes nowhere
  if (null > 3) ::close(null);
  return 3;
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

// Frames: one kind byte ('P' progress, 'R' result, 'E' uncaught exception), the channel's token,
// a decimal length, ':', the payload. A child writes any number of P frames, then exactly one R
// or E frame, then nothing.
void ChildChannel::frame(char kind, const std::string& payload) {
  const std::string head = std::string(1, kind) + child_token + std::to_string(payload.size()) + ":";
  write_all(fd_, head.data(), head.size());
  write_all(fd_, payload.data(), payload.size());
}

void ChildChannel::progress(const std::string& text) { frame('P', text); }

struct ChildPool::Running {
  std::size_t id = 0;
  pid_t pid = -1;  // also the id of its process group
  int fd = -1;
  std::string token;  // every frame of the child's carries it
  bool eof = false;     // the channel is closed (every writer gone) or no longer read
  bool exited = false;  // reaped; wstatus holds how it ended
  int wstatus = 0;
  bool status_lost = false;  // reaped by someone else: how it ended is unknown
  std::string buffer;        // bytes read, not yet parsed
  std::size_t received = 0;  // bytes read in all
  ChildOutcome outcome;
  bool got_result = false, got_exception = false;
  std::string channel_error;  // what was wrong with the channel: the child is ended, the clause CRASH
  Clock::time_point started, deadline, eof_at;
  bool killed_for_time = false;

  void kill_group() const { ::kill(-pid, SIGKILL); }

  void reject(const std::string& why) {
    if (channel_error.empty()) channel_error = why;
    buffer.clear();
    eof = true;  // read no further
    kill_group();
  }

  /// Parses complete frames out of the buffer; anything that is not a frame rejects the channel.
  void parse() {
    while (!buffer.empty() && channel_error.empty()) {
      if (got_result || got_exception) return reject(std::to_string(buffer.size()) + " bytes after its final frame");
      const char kind = buffer[0];
      if (kind != 'P' && kind != 'R' && kind != 'E')
        return reject("bytes that are not a frame: \"" + printable(std::string_view(buffer).substr(0, 40)) + "\"");
      const std::size_t have = std::min(buffer.size() - 1, token.size());
      if (buffer.compare(1, have, token, 0, have) != 0)
        return reject("a frame without the channel's token (not written by the certify tool's code): \"" +
                      printable(std::string_view(buffer).substr(0, 40)) + "\"");
      if (have < token.size()) return;  // the header is not complete yet
      const std::size_t digits = 1 + token.size();
      std::size_t i = digits, len = 0;
      while (i < buffer.size() && i - digits < kMaxLengthDigits && buffer[i] >= '0' && buffer[i] <= '9')
        len = len * 10 + static_cast<std::size_t>(buffer[i++] - '0');
      if (i == buffer.size()) return;  // the header is not complete yet (and at most 1 + 32 + 10 bytes)
      if (i == digits || buffer[i] != ':')  // no digits, an eleventh digit, anything else
        return reject("a malformed frame header: \"" + printable(std::string_view(buffer).substr(0, 80)) + "\"");
      if (len > (kind == 'P' ? kMaxProgressBytes : kMaxResultBytes))
        return reject("a frame of " + std::to_string(len) + " bytes, more than the channel allows");
      if (buffer.size() < i + 1 + len) return;  // the payload is not complete yet
      std::string payload = buffer.substr(i + 1, len);
      buffer.erase(0, i + 1 + len);
      if (kind == 'P') outcome.last_progress = printable(payload, kMaxProgressBytes);
      else if (kind == 'R') outcome.result = std::move(payload), got_result = true;
      else outcome.message = "uncaught exception: " + printable(payload), got_exception = true;
    }
  }

  /// Reads what the channel holds now, without waiting.
  void drain() {
    char buf[65536];
    while (!eof) {
      const ssize_t got = ::read(fd, buf, sizeof buf);
      if (got > 0) {
        received += static_cast<std::size_t>(got);
        buffer.append(buf, static_cast<std::size_t>(got));
        if (received > kMaxResultBytes + kMaxProgressBytes) reject("more data than the channel allows");
        else parse();
        continue;
      }
      if (got == 0) {
        eof = true;
        eof_at = Clock::now();
      } else if (errno == EINTR) {
        continue;
      } else if (errno != EAGAIN && errno != EWOULDBLOCK) {
        eof = true;
        eof_at = Clock::now();
      }
      break;
    }
  }

  /// Whether the child has ended; if so its group is ended too and the child reaped. The group
  /// is killed while the exited child still holds its process id (before reaping), so the id
  /// cannot have been reused.
  bool check_exit() {
    if (exited) return true;
    siginfo_t info{};
    if (::waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOHANG | WNOWAIT) != 0) {
      if (errno == EINTR) return false;
      status_lost = exited = true;  // ECHILD: reaped elsewhere; its id may be reused, so no kill
      return true;
    }
    if (info.si_pid != pid) return false;  // still running
    kill_group();                          // helpers it left behind: forked processes, ...
    while (::waitpid(pid, &wstatus, 0) < 0 && errno == EINTR) {
    }
    exited = true;
    return true;
  }
};

ChildPool::ChildPool(int jobs, ChildLimits limits) : jobs_(jobs < 1 ? 1 : jobs), limits_(limits) {
  // SIGCHLD ignored (a disposition the tool may inherit from whoever started it) reaps children
  // automatically, and their exit status is lost: the pool sets the default disposition.
  struct sigaction current {};
  if (::sigaction(SIGCHLD, nullptr, &current) == 0 && current.sa_handler == SIG_IGN) std::signal(SIGCHLD, SIG_DFL);
}

ChildPool::~ChildPool() {
  for (auto& [pid, r] : running_) {
    r->kill_group();
    if (!r->exited) ::waitpid(pid, nullptr, 0);
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
  const pid_t parent = ::getpid();
  std::string token = new_token();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
  }
  if (pid == 0) {
    ::close(fds[0]);
    const int channel_fd = prepare_child(fds[1], parent);
    child_token = token;
    if (limits_.memory_mb > 0 && !built_with_sanitizer()) {
      const rlim_t bytes = static_cast<rlim_t>(limits_.memory_mb) << 20;
      const rlimit rl{bytes, bytes};
      ::setrlimit(RLIMIT_AS, &rl);
    }
    ::signal(SIGPIPE, SIG_DFL);
    ::signal(SIGINT, SIG_DFL);  // not the parent's recording handlers (interrupt.hpp)
    ::signal(SIGTERM, SIG_DFL);
    ChildChannel channel(channel_fd);
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
  ::setpgid(pid, pid);  // as the child does: the group exists before the parent may signal it
  ::close(fds[1]);
  ::fcntl(fds[0], F_SETFL, O_NONBLOCK);
  auto* r = new Running;
  r->id = id;
  r->pid = pid;
  r->fd = fds[0];
  r->token = std::move(token);
  r->started = Clock::now();
  r->deadline = r->started + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limits_.timeout_s));
  running_[pid] = r;
}

std::pair<std::size_t, ChildOutcome> ChildPool::wait_any() {
  if (running_.empty()) throw std::logic_error("ChildPool::wait_any with nothing running");
  for (;;) {
    // Ctrl-C or SIGTERM (RESULT-4): no outcome of a half-finished child counts; the destructor
    // ends every running group.
    if (const int sig = interruption(); sig != 0) throw Interrupted(sig);
    // A child is done when it has exited and been reaped: not when its channel closes, since
    // a process it forked may hold the channel open, nor must a child that closed its channel
    // and goes on be taken for finished.
    for (auto it = running_.begin(); it != running_.end(); ++it) {
      Running* r = it->second;
      if (!r->check_exit()) continue;
      r->drain();  // everything the child wrote is in the pipe by now
      ChildOutcome out = std::move(r->outcome);
      out.seconds = std::chrono::duration<double>(Clock::now() - r->started).count();
      const int ws = r->wstatus;
      if (r->killed_for_time) {
        out.kind = ChildOutcome::Kind::timed_out;
        char limit[32];
        std::snprintf(limit, sizeof limit, "%g", limits_.timeout_s);
        out.message = std::string("no result within the wall-clock limit of ") + limit + " s";
      } else if (!r->channel_error.empty()) {
        out.kind = ChildOutcome::Kind::crashed;
        out.result.clear();
        out.message = "its channel to the certify tool carried " + r->channel_error + "; the process was ended";
      } else if (r->status_lost) {
        // Reaped by someone else (a SIGCHLD handler of the host): its result, if it handed one
        // over, is genuine (the frames carry the token); without one it is CRASH.
        out.kind = r->got_result ? ChildOutcome::Kind::finished : ChildOutcome::Kind::crashed;
        if (!r->got_result && !r->got_exception) out.message = "ended without a result, and its exit status was lost";
      } else if (WIFSIGNALED(ws)) {
        out.kind = ChildOutcome::Kind::crashed;
        out.message = "terminated by " + signal_text(WTERMSIG(ws));
      } else if (WIFEXITED(ws) && WEXITSTATUS(ws) == 0 && r->got_result) {
        out.kind = ChildOutcome::Kind::finished;
      } else {
        out.kind = ChildOutcome::Kind::crashed;
        out.result.clear();
        const int code = WIFEXITED(ws) ? WEXITSTATUS(ws) : -1;
        if (r->got_exception) {
          // out.message says which
        } else if (code == 0) {
          out.message = "exited with status 0 without handing over a result (the implementation ended the process)";
        } else if (code == kChannelLost && !r->got_result) {
          out.message = "exited with status " + std::to_string(code) +
                        ": it could not write to its channel to the certify tool (closed or replaced by the implementation?)";
        } else {
          out.message = "exited with status " + std::to_string(code) +
                        (r->got_result ? " after handing over its result" : " before handing over a result");
        }
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
    // Wait for output, an exit or the nearest deadline. An exit is noticed by polling for it:
    // promptly after the channel closed (the child is exiting), every 50 ms otherwise (the
    // channel stays open while a process the child forked holds it).
    std::vector<pollfd> pfds;
    std::vector<Running*> order;
    const auto now = Clock::now();
    auto wake = now + std::chrono::milliseconds(50);
    for (auto& [pid, r] : running_) {
      if (!r->eof) {
        pfds.push_back({r->fd, POLLIN, 0});
        order.push_back(r);
      } else {
        wake = std::min(wake, now + (now - r->eof_at < std::chrono::milliseconds(100) ? std::chrono::milliseconds(1)
                                                                                     : std::chrono::milliseconds(20)));
      }
      if (!r->killed_for_time) wake = std::min(wake, r->deadline);
    }
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(wake - now).count();
    const int wait_ms = static_cast<int>(std::clamp<long long>(left + 1, 0, 50));
    const int n = ::poll(pfds.data(), pfds.size(), wait_ms);
    if (n < 0 && errno != EINTR) throw std::runtime_error(std::string("poll: ") + std::strerror(errno));
    for (std::size_t i = 0; n > 0 && i < pfds.size(); ++i)
      if (pfds[i].revents & (POLLIN | POLLHUP | POLLERR)) order[i]->drain();
    const auto after = Clock::now();
    for (auto& [pid, r] : running_)
      if (!r->killed_for_time && !r->exited && after >= r->deadline) {
        r->kill_group();
        r->killed_for_time = true;
      }
  }
}

}  // namespace rotorcert::certify
