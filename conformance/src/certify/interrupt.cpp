#include <rotorcert/certify/interrupt.hpp>

#include <csignal>

namespace rotorcert::certify {
namespace {

volatile std::sig_atomic_t g_signal = 0;

extern "C" void record_signal(int sig) {
  if (g_signal != 0) {  // the second one: the user means it
    std::signal(sig, SIG_DFL);
    std::raise(sig);
    return;
  }
  g_signal = sig;
}

}  // namespace

Interrupted::Interrupted(int sig) : std::runtime_error("interrupted by " + signal_name(sig)), signal(sig) {}

InterruptGuard::InterruptGuard() {
  g_signal = 0;
  struct sigaction sa {};
  sa.sa_handler = record_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = 0;  // no SA_RESTART: a blocking poll returns at once with EINTR
  // A signal the tool was started with ignored (nohup, a background job of a script) stays ignored.
  ::sigaction(SIGINT, nullptr, &previous_int_);
  ::sigaction(SIGTERM, nullptr, &previous_term_);
  if (previous_int_.sa_handler != SIG_IGN) ::sigaction(SIGINT, &sa, nullptr);
  if (previous_term_.sa_handler != SIG_IGN) ::sigaction(SIGTERM, &sa, nullptr);
}

InterruptGuard::~InterruptGuard() {
  ::sigaction(SIGINT, &previous_int_, nullptr);
  ::sigaction(SIGTERM, &previous_term_, nullptr);
}

int interruption() { return g_signal; }

std::string signal_name(int sig) {
  switch (sig) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    default: return "signal " + std::to_string(sig);
  }
}

}  // namespace rotorcert::certify
