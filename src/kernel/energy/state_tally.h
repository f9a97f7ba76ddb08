// The seconds and joules a device energy model spent in each of its states, for models that change
// state at events (energy/lr_wpan_energy_model.h, energy/airtime_energy_model.h): what was drawn
// in a state is added when the model leaves it, and what the current state drew since it was
// entered is added when asked.
#pragma once

#include <ns3/nstime.h>
#include <ns3/simulator.h>

#include <array>
#include <cstddef>

namespace sanet::energy {

template <std::size_t States>
class StateTally {
 public:
  using ByState = std::array<double, States>;

  void Start() { since_ = ns3::Simulator::Now(); }
  // Leaves `state`, which drew `amperes` at `volts` since the last change, now.
  void Leave(std::size_t state, double amperes, double volts) {
    const ns3::Time now = ns3::Simulator::Now();
    const double dt = (now - since_).GetSeconds();
    seconds_[state] += dt;
    joules_[state] += dt * amperes * volts;
    since_ = now;
  }
  ns3::Time since() const { return since_; }
  // Up to now, `state` being the one the model is in.
  ByState Joules(std::size_t state, double amperes, double volts) const {
    ByState joules = joules_;
    joules[state] += (ns3::Simulator::Now() - since_).GetSeconds() * amperes * volts;
    return joules;
  }
  ByState Seconds(std::size_t state) const {
    ByState seconds = seconds_;
    seconds[state] += (ns3::Simulator::Now() - since_).GetSeconds();
    return seconds;
  }

 private:
  ByState joules_{}, seconds_{};
  ns3::Time since_;
};

}  // namespace sanet::energy
