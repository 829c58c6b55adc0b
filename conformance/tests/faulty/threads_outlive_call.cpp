// Starts a background thread on its first call and never stops or joins it (a lazily created
// worker pool): the thread outlives every call and the clause. The numbers are right. The thread
// is a joinable static std::thread, so a child process that ran static destructors on its way out
// (exit() instead of _exit()) would die in std::terminate after handing over its result.
#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>

#include "faulty.hpp"

namespace {
std::atomic<unsigned long> ticks{0};
std::thread worker;  // never joined
std::once_flag started;

void start_worker() {
  std::call_once(started, [] {
    worker = std::thread([] {
      for (;;) {
        ticks.fetch_add(1);
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
      }
    });
  });
}

struct Impl : faulty::Correct {
  static constexpr const char* name = "faulty_threads";
  static constexpr const char* description = "correct, but leaves a worker thread running after every call";
  static mutant::Status normalize(const mutant::Q<double>& q, mutant::Q<double>& out) {
    start_worker();
    return Correct::normalize(q, out);
  }
  static mutant::Status slerp(const mutant::Q<double>& a, const mutant::Q<double>& b, const double& t,
                              mutant::Q<double>& out) {
    start_worker();
    return Correct::slerp(a, b, t, out);
  }
};
}  // namespace
ROTORCERT_DEFINE_ENTRY(faulty_threads, Impl)
