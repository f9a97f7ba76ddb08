// Where and when, for the records a run or a study keeps: this machine's name, and the time in
// UTC as ISO 8601 with milliseconds ("2026-11-24T10:25:40.123Z").
#pragma once

#include <string>

namespace sanet {

std::string HostName();
std::string UtcNow();

}  // namespace sanet
