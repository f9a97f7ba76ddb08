#include "interruption.h"

#include <unistd.h>

#include <csignal>
#include <initializer_list>

namespace sanet::cli {
namespace {

volatile std::sig_atomic_t g_signal = 0;

void OnSignal(int signal) {
  if (g_signal != 0) {  // the second: now (write and _exit are safe in a signal handler)
    static const char said[] =
        "sanet: second signal: stopped at once; results not written (only whole files and .tmp files are left)\n";
    [[maybe_unused]] const auto ignored = ::write(STDERR_FILENO, said, sizeof said - 1);
    ::_exit(128 + signal);
  }
  g_signal = signal;
}

}  // namespace

void InstallStopHandlers() {
  struct sigaction action {};
  action.sa_handler = OnSignal;
  sigemptyset(&action.sa_mask);
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) sigaction(signal, &action, nullptr);
}

int InterruptSignal() { return g_signal; }

const char* SignalName(int signal) {
  switch (signal) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    case SIGHUP:
      return "SIGHUP";
    default:
      return "a signal";
  }
}

std::string InterruptReason() { return g_signal ? std::string("interrupted by ") + SignalName(g_signal) : ""; }

void ClearInterrupt() { g_signal = 0; }
void RequestInterrupt(int signal) { g_signal = signal; }

}  // namespace sanet::cli
