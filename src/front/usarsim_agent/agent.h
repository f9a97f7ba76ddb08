// `sanet agent`: one robot's controller as its own process. It claims the robot from a server,
// waits for its first sensor lines, then runs the controller through the same host as a
// simulated run (hosting::ControllerHost: start, steps at the controller's rate, messages after
// the scenario's impairments, failures) until the server ends the run.
#pragma once

#include "hosting/controller_registry.h"
#include "sim/run_spec.h"
#include "usarsim_agent/remote_node.h"

namespace sanet::usarsim_agent {

// Drives `robot` through `link` (handshake done). Returns the process's exit code: 0 when the
// server ended the run, 1 when the controller failed.
int RunAgent(const sim::RunSpec& spec, NodeId robot, const AgentSettings& settings, std::unique_ptr<ServerLink> link,
             hosting::Registry& registry);

}  // namespace sanet::usarsim_agent
