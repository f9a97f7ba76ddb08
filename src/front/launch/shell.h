// Running the system's network tools (ip, tc) for launch's namespaces and radio taps.
#pragma once

#include <string>

namespace sanet::launch {

// Runs `command` through the shell with its output discarded; returns its exit status.
int RunQuietly(const std::string& command);

}  // namespace sanet::launch
