// When an agent's control steps run: on the shared clock's grid, t_k = k / rate, as in a
// simulated run. A process that wakes late runs the latest step due, once; steps it slept
// through entirely are counted as missed, never run in a burst. It also keeps the figures an
// agent reports: steps run and missed, the achieved rate and how late steps ran.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <vector>

#include "hosting/host_clock.h"

namespace sanet::usarsim_agent {

// An agent's clock as its controller's host sees it (`now`: the node's Now()), with the delayed
// actions the host asks for, run as the agent's loop calls RunDue.
class AgentClock : public hosting::HostClock {
 public:
  explicit AgentClock(std::function<double()> now) : now_(std::move(now)) {}
  double Now() const override { return now_(); }
  void After(double delay, std::function<void()> action) override { due_.emplace(Now() + delay, std::move(action)); }
  void RunDue();

 private:
  std::function<double()> now_;
  std::multimap<double, std::function<void()>> due_;  // in time order, then in order asked
};

class StepGrid {
 public:
  explicit StepGrid(double rate) : rate_(rate) {}
  // The step to run at clock time `now`, if one is due (its grid time); counts the missed ones.
  std::optional<double> Due(double now);
  double rate() const { return rate_; }
  std::uint64_t run() const { return run_; }
  std::uint64_t missed() const { return missed_; }
  // Steps run per second between the first and the last step run.
  double achieved_rate() const;
  // How late steps ran (s): median, 99th percentile and maximum over every step run (one sort).
  struct Lateness {
    double p50 = 0, p99 = 0, max = 0;
  };
  Lateness lateness() const;

 private:
  double Time(std::uint64_t k) const { return static_cast<double>(k) / rate_; }
  double rate_;
  std::uint64_t next_ = 0;  // index of the next step on the grid
  std::uint64_t run_ = 0, missed_ = 0;
  double first_ = 0, last_ = 0;
  std::vector<double> lateness_;
};

}  // namespace sanet::usarsim_agent
