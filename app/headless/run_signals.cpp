#include "run_signals.h"

#include <signal.h>
#include <unistd.h>

#include <atomic>

namespace sph::cli {
namespace {

std::atomic<int> g_signal{0};
std::atomic<const char*> g_partial{nullptr};

/// Async-signal-safe: a flag the first time; unlink and _exit the second time (exit 128 + signal).
void on_stop(int sig) {
  int expected = 0;
  if (g_signal.compare_exchange_strong(expected, sig)) return;
  if (const char* p = g_partial.load()) ::unlink(p);
  ::_exit(128 + sig);
}

}  // namespace

void install_stop_handlers() {
  struct sigaction sa {};
  sa.sa_handler = on_stop;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

int stop_signal() { return g_signal.load(); }

void set_partial_file(const char* path) { g_partial.store(path); }

}  // namespace sph::cli
