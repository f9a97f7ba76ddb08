// `sanet launch`: a server and its agents on this machine (docs/protocol.md, "sanet launch").
#pragma once

#include "options.h"

namespace sanet::cli {

Command AddLaunch(CLI::App& app);

}  // namespace sanet::cli
