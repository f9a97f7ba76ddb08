// `sanet link-curve`: the scenario's radio measured against distance (sim/link_curve.h,
// docs/network.md#link-curves).
#pragma once

#include "options.h"

namespace sanet::cli {

Command AddLinkCurve(CLI::App& app);

}  // namespace sanet::cli
