// Compiled as part of the usarsim_agent layer by tests/layers/upward_include_test.sh, which
// expects it to fail: the agent uses the wire and the scenario, never the robot server.
#include "robot_server/sim_server.h"    // must not be found
#include "usarsim_agent/remote_node.h"  // the agent's own headers are found
