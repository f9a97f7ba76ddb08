// The tap devices of `loop.network: simulated`: each agent's network namespace gets an interface
// `radio0` with its robot's own address on the simulated network (10.0.0.(id+1)/16), and the
// server holds the other end, an ns-3 FdNetDevice on the robot's node (net/tap_port.h), so what
// the agent's programs send crosses the simulated radio. Linux only; needs CAP_NET_ADMIN (root)
// and /dev/net/tun.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "sim/driver.h"

namespace sanet::launch {

// Whether this process can make taps and move them into namespaces; if not, `why` says what
// is missing and how to get it.
bool RadioTapsPermitted(std::string* why);

// The address the robot's programs use on the simulated network, and its tap's MAC.
std::string RadioAddress(NodeId node);
std::string RadioMac(NodeId node);
constexpr const char* kRadioInterface = "radio0";
constexpr const char* kRadioSubnet = "10.0.0";  // robot i is kRadioSubnet.(i+1)

// Opens a tap for every (robot, namespace), moves it into the namespace, configures it and joins
// it to the robot's node in `world`. Throws std::runtime_error naming the step that failed. The
// world's network owns the taps from then on (closed when the world ends).
void JoinRadioTaps(sim::Driver& world, const std::vector<std::pair<std::string, std::string>>& robot_namespaces);

}  // namespace sanet::launch
