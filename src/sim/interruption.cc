#include "sim/interruption.h"

#include <unistd.h>

#include <csignal>
#include <initializer_list>

namespace sanet::sim {
namespace {

volatile std::sig_atomic_t g_signal = 0;

void OnSignal(int signal) {
  if (g_signal != 0) ::_exit(128 + signal);  // the second: now
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

void ClearInterrupt() { g_signal = 0; }
void RequestInterrupt(int signal) { g_signal = signal; }

}  // namespace sanet::sim
