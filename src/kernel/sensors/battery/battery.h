// The node's battery as its controller reads it: the charge left, its fraction of the capacity,
// the voltage and the power drawn now. On a node with `energy` only (docs/energy.md), which
// carries one by default.
#pragma once

namespace sanet::sensors {

struct BatterySettings {};

}  // namespace sanet::sensors
