// `sanet serve`: the world in real time for protocol clients (docs/protocol.md).
#pragma once

#include "options.h"

namespace sanet::cli {

Command AddServe(CLI::App& app);

}  // namespace sanet::cli
