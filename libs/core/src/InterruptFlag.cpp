#include "passageMesh/core/InterruptFlag.hpp"

#include <csignal>

namespace passageMesh {

namespace {

static_assert(std::atomic<bool>::is_always_lock_free,
              "a signal handler may only touch lock-free atomics");

std::atomic<bool> interrupted{false};

void onInterrupt(int) { interrupted.store(true); }

}  // namespace

const std::atomic<bool>& installInterruptFlag() {
  interrupted.store(false);
  struct sigaction action {};
  action.sa_handler = onInterrupt;
  sigemptyset(&action.sa_mask);
  // SA_RESETHAND: the handler runs once, then SIGINT has its default action again, so the
  // second Ctrl-C ends the process. SA_RESTART: blocking calls in the run are not cut short.
  action.sa_flags = SA_RESETHAND | SA_RESTART;
  sigaction(SIGINT, &action, nullptr);
  return interrupted;
}

}  // namespace passageMesh
