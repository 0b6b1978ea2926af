#include "interrupt.hpp"

#include <signal.h>

#include <csignal>

namespace occlusion::cli {

namespace {

std::atomic<bool> interrupted{false};
std::atomic<int> received_signal{0};

static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free,
              "set from a signal handler");

extern "C" void on_signal(int signal_number) {
  received_signal.store(signal_number);
  interrupted.store(true);
}

void install() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  // The next signal takes the default action: a run stuck where it cannot
  // check the flag is still stopped by a second Ctrl-C.
  action.sa_flags = SA_RESETHAND;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

}  // namespace

const std::atomic<bool>& interrupt_flag() {
  static const bool installed = (install(), true);
  (void)installed;
  return interrupted;
}

void reraise_interrupt() {
  const int signal_number = received_signal.load();
  if (signal_number == 0) return;
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

}  // namespace occlusion::cli
