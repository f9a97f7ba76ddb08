// The server's step loop on a real-time scheduling class (SCHED_FIFO) where the machine permits
// it, so that agent processes sharing its cores cannot delay a physics step; said in the results
// either way.
#pragma once

#include <string>

namespace sanet::wire {

// Tries to move this process to SCHED_FIFO at a middle priority. Returns "SCHED_FIFO" or why not.
std::string UseRealTimePriority();

}  // namespace sanet::wire
