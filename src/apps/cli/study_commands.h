// `sanet sweep` and `sanet report`: studies of many runs (docs/studies.md).
#pragma once

#include "options.h"

namespace sanet::cli {

Command AddSweep(CLI::App& app);
Command AddReport(CLI::App& app);

}  // namespace sanet::cli
