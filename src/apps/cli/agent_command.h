// `sanet agent`: one robot's controller as its own process, beside the server or on a computer
// of its own (docs/remote-robots.md).
#pragma once

#include "options.h"

namespace sanet::cli {

Command AddAgent(CLI::App& app);

}  // namespace sanet::cli
