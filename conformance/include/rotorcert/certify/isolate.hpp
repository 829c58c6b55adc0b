// The isolating runner: the implementation under test runs in a forked child process with a
// wall-clock limit and an address-space limit, so a segfault, abort, uncaught exception, hang or
// runaway allocation ends the child, not the certification (RESULT-1: CRASH, TIMEOUT).
//
// A child talks to the parent through a pipe in frames: progress lines ("about to call slerp on
// case ...") and one final result. The parent keeps the last progress line, so a crash can be
// pinned on the input the child was working on. Several children may run at once (ChildPool).
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <string>

namespace rotorcert::certify {

struct ChildLimits {
  double timeout_s = 30;         // wall clock, per child
  std::size_t memory_mb = 2048;  // RLIMIT_AS of the child; 0 = none (sanitizer builds need none)
};

/// The child's side of the pipe.
class ChildChannel {
 public:
  explicit ChildChannel(int fd) : fd_(fd) {}
  /// Records what the child is about to do (the parent keeps the latest).
  void progress(const std::string& text);

 private:
  friend class ChildPool;
  void frame(char kind, const std::string& payload);
  int fd_;
};

struct ChildOutcome {
  enum class Kind { finished, crashed, timed_out };
  Kind kind = Kind::crashed;
  std::string result;         // the child's result (finished only)
  std::string last_progress;  // the last progress line before the end
  std::string message;        // crashed: "SIGSEGV (signal 11)", "uncaught exception: ...", ...
  double seconds = 0;
};

/// Runs up to `jobs` children at a time. Each task runs in its own child (in a process group of its
/// own, killed as a whole when it ends) and returns its result as a string over a dedicated pipe,
/// in frames that carry a token of that child (RESULT-3); what it prints goes to the tool's stderr
/// (the child's stdout is joined to it).
class ChildPool {
 public:
  using Task = std::function<std::string(ChildChannel&)>;
  ChildPool(int jobs, ChildLimits limits);
  ~ChildPool();
  ChildPool(const ChildPool&) = delete;
  ChildPool& operator=(const ChildPool&) = delete;

  /// Starts the task now if a slot is free, else when one frees up (in submission order).
  void submit(std::size_t id, Task task);
  /// Blocks until some child has ended; returns its id and outcome. Precondition: pending() > 0.
  std::pair<std::size_t, ChildOutcome> wait_any();
  std::size_t pending() const { return queued_.size() + running_.size(); }
  const ChildLimits& limits() const { return limits_; }

 private:
  struct Running;
  void start(std::size_t id, Task task);
  int jobs_;
  ChildLimits limits_;
  std::vector<std::pair<std::size_t, Task>> queued_;
  std::map<int, Running*> running_;  // by pid
};

/// Whether this build runs under AddressSanitizer (its shadow memory cannot live under RLIMIT_AS).
bool built_with_sanitizer();

}  // namespace rotorcert::certify
