// Ctrl-C and SIGTERM during `certify` and `report` (RESULT-4). The handlers only record the signal;
// the isolating runner (isolate.hpp) notices it within its 50 ms poll, ends every running child's
// process group and throws Interrupted, so the tool never writes a report from a half-finished
// run: the previous complete report stays, and the results collected so far are in the journal
// (journal.hpp). A second signal ends the tool at once.
#pragma once

#include <signal.h>

#include <stdexcept>
#include <string>

namespace rotorcert::certify {

/// Thrown by ChildPool::wait_any once SIGINT or SIGTERM has arrived.
struct Interrupted : std::runtime_error {
  explicit Interrupted(int sig);
  int signal;
};

/// While it lives, SIGINT and SIGTERM are recorded instead of ending the tool; it puts the previous
/// handlers back when it goes. Outside certification (render, bench) a signal ends the tool at
/// once, which the atomic report writes make safe.
class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

 private:
  struct sigaction previous_int_ {}, previous_term_ {};
};

/// The signal recorded by an InterruptGuard, 0 if none.
int interruption();

/// "SIGINT" / "SIGTERM".
std::string signal_name(int sig);

}  // namespace rotorcert::certify
