// Stopping a run from outside (Ctrl-C, kill, a closed terminal): the run ends at its next step
// with every result written and marked "interrupted". A second signal ends the process at once;
// results are written whole (temporary name, then rename), so that leaves only temporary files.
#pragma once

#include <string>

namespace sanet::cli {

// Installs handlers for SIGINT, SIGTERM and SIGHUP doing the above (the command's: sim installs
// none; a run asks RunOptions::stop_requested).
void InstallStopHandlers();
// The signal that asked the run to stop, or 0. Async-signal-safe to set, cheap to read.
int InterruptSignal();
// "SIGINT", "SIGTERM", "SIGHUP".
const char* SignalName(int signal);
// For a second run in the same process (tests).
void ClearInterrupt();
// Asks for a stop as a signal would.
void RequestInterrupt(int signal);
// For RunOptions::stop_requested: "interrupted by SIGINT" once a signal came, "" before.
std::string InterruptReason();

}  // namespace sanet::cli
