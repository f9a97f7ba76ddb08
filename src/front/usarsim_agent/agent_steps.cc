#include "usarsim_agent/agent_steps.h"

#include <algorithm>
#include <cmath>

namespace sanet::usarsim_agent {

std::optional<double> StepGrid::Due(double now) {
  if (now < Time(next_)) return std::nullopt;
  // Every step whose successor is also due was slept through.
  const auto latest = static_cast<std::uint64_t>(std::floor(now * rate_));
  std::uint64_t k = std::max(next_, latest);
  while (k > next_ && Time(k) > now) --k;  // floor() may round up by an ulp
  if (run_ > 0) missed_ += k - next_;      // the steps before the agent's first are not its to run
  next_ = k + 1;
  const double t = Time(k);
  if (run_ == 0) first_ = t;
  last_ = t;
  ++run_;
  lateness_.push_back(now - t);
  return t;
}

double StepGrid::achieved_rate() const { return run_ > 1 && last_ > first_ ? (run_ - 1) / (last_ - first_) : 0; }

StepGrid::Lateness StepGrid::lateness() const {
  if (lateness_.empty()) return {};
  std::vector<double> sorted = lateness_;
  std::sort(sorted.begin(), sorted.end());
  const auto at = [&](double q) { return sorted[static_cast<std::size_t>(q * (sorted.size() - 1))]; };
  return {at(0.5), at(0.99), sorted.back()};
}

void AgentClock::RunDue() {
  while (!due_.empty() && due_.begin()->first <= Now()) {
    auto action = std::move(due_.begin()->second);
    due_.erase(due_.begin());
    action();
  }
}

}  // namespace sanet::usarsim_agent
