// SPDX-License-Identifier: MIT
// The SIGINT handler of the long commands (interrupt.hpp): it stores to a
// lock-free atomic and nothing else, the one thing a handler may do safely.
#include "interrupt.hpp"

#include <atomic>
#include <csignal>

#if __has_include(<unistd.h>)
#include <signal.h>
#define CVMS_POSIX_SIGNALS 1
#endif

namespace cvms::cli {
namespace {

std::atomic<bool> interrupt_flag{false};
static_assert(std::atomic<bool>::is_always_lock_free, "a signal handler may only touch lock-free atomics");

extern "C" void on_interrupt(int /*signal*/) { interrupt_flag.store(true, std::memory_order_relaxed); }

}  // namespace

void catch_interrupt() {
  static const bool installed = [] {
#ifdef CVMS_POSIX_SIGNALS
    struct sigaction action = {};
    action.sa_handler = on_interrupt;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND;  // the second Ctrl-C ends the process
    sigaction(SIGINT, &action, nullptr);
#else
    std::signal(SIGINT, on_interrupt);  // reset to the default on delivery, as SA_RESETHAND
#endif
    return true;
  }();
  (void)installed;
}

bool interrupted() noexcept { return interrupt_flag.load(std::memory_order_relaxed); }

}  // namespace cvms::cli
