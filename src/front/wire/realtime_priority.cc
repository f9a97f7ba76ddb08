#include "wire/realtime_priority.h"

#include <sched.h>

#include <cerrno>
#include <cstring>

namespace sanet::wire {

std::string UseRealTimePriority() {
  sched_param param{};
  // Middle of the range: above every normal process, below the kernel's own real-time threads.
  param.sched_priority = (sched_get_priority_min(SCHED_FIFO) + sched_get_priority_max(SCHED_FIFO)) / 2;
  if (sched_setscheduler(0, SCHED_FIFO, &param) != 0)
    return std::string("not permitted (") + std::strerror(errno) + "): normal scheduling";
  return "SCHED_FIFO";
}

}  // namespace sanet::wire
