// The clock a node and its controller live on: the simulation's, or an agent's estimate of it.
#pragma once

#include <functional>

namespace sanet::hosting {

class HostClock {
 public:
  virtual ~HostClock() = default;
  virtual double Now() const = 0;  // s since the start of the run
  // Runs `action` `delay` seconds from now on this clock.
  virtual void After(double delay, std::function<void()> action) = 0;
};

}  // namespace sanet::hosting
