// Installs signal handlers when loaded, as a crash-reporting or "robust" library does: its SIGSEGV,
// SIGBUS, SIGFPE, SIGILL and SIGABRT handler ends the process quietly with status 0, and SIGTERM,
// SIGINT, SIGHUP, SIGALRM and SIGXCPU are ignored. It then faults on normalize(0) and never
// returns from slerp with t < 0: the fault must still be CRASH (a status-0 exit without a result
// is not a PASS), and the hang still TIMEOUT (the limit is enforced with SIGKILL).
#include <unistd.h>

#include <csignal>

#include "faulty.hpp"

namespace {
extern "C" void quiet_exit(int) {
  static const char text[] = "faulty_signals: fatal signal caught, exiting quietly\n";
  [[maybe_unused]] const auto ignored = ::write(2, text, sizeof text - 1);
  ::_exit(0);
}

[[maybe_unused]] const bool handlers_installed = [] {
  struct sigaction quiet {};
  quiet.sa_handler = quiet_exit;
  sigemptyset(&quiet.sa_mask);
  for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) ::sigaction(sig, &quiet, nullptr);
  for (int sig : {SIGTERM, SIGINT, SIGHUP, SIGALRM, SIGXCPU}) std::signal(sig, SIG_IGN);
  return true;
}();

// Never set. Volatile, not a std::atomic: clang 14 folds the load of an internal atomic that
// nothing stores to, and then removes the loop as one without side effects (a hang that returns).
volatile bool converged = false;

struct Impl : faulty::Correct {
  static constexpr const char* name = "faulty_signals";
  static constexpr const char* description = "installs quiet-exit crash handlers, faults on normalize(0), hangs on slerp t < 0";
  static mutant::Status normalize(const mutant::Q<double>& q, mutant::Q<double>& out) {
    if (q[0] == 0 && q[1] == 0 && q[2] == 0 && q[3] == 0) std::raise(SIGSEGV);
    return Correct::normalize(q, out);
  }
  static mutant::Status slerp(const mutant::Q<double>& a, const mutant::Q<double>& b, const double& t,
                              mutant::Q<double>& out) {
    while (t < 0 && !converged) {
    }
    return Correct::slerp(a, b, t, out);
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(faulty_signals, Impl)
