// Launch's verdict on its run: the server knows which robots clients drove and when (summary.json's
// "attendance"); launch alone knows how each agent process ended and its last word on stderr. A
// robot whose agent never drove it, or ended on its own before the run did, fails the run, with
// the agent's own last error line as the cause.
#pragma once

#include <string>
#include <vector>

#include "launch/agent_processes.h"

namespace sanet::launch {

// Adds each agent's end to `results`/summary.json (attendance.ROBOT.agent) and, for each robot
// its agent failed, the cause (attendance.ROBOT.cause) and a status "failed: ..." (unless the run
// was interrupted); writes the file back whole. Returns the failures, one sentence each.
std::vector<std::string> JudgeAgents(const std::string& results, const std::vector<AgentProcess>& agents);

}  // namespace sanet::launch
