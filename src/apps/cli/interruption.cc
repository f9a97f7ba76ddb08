#include "interruption.h"

#include <unistd.h>

#include <csignal>
#include <ctime>
#include <initializer_list>

namespace sanet::cli {
namespace {

volatile std::sig_atomic_t g_signal = 0;
timespec g_first{};  // when the first signal came (the handler alone writes it)

void OnSignal(int signal) {
  timespec now{};
  ::clock_gettime(CLOCK_MONOTONIC, &now);  // safe in a signal handler, as are write and _exit
  // One request can arrive twice at once (`timeout` signals the process and its group; so does a
  // terminal): a second signal within a second of the first is that same request.
  if (g_signal != 0 && (now.tv_sec - g_first.tv_sec) + (now.tv_nsec - g_first.tv_nsec) * 1e-9 < 1.0) return;
  if (g_signal != 0) {  // a second request: stop now
    static const char said[] =
        "sanet: second signal: stopped at once; results not written (only whole files and .tmp files are left)\n";
    [[maybe_unused]] const auto ignored = ::write(STDERR_FILENO, said, sizeof said - 1);
    ::_exit(128 + signal);
  }
  g_first = now;
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
