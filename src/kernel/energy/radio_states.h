// How long a Wi-Fi PHY spent in each of its states, summed from its own state trace
// (WifiPhyStateHelper's `State`): where a radio's time went, beside the energy its model charged
// in each state (energy/radio_energy_model.h). The trace logs a transmission when it starts, for
// its whole duration (and again, as far as it went, if the radio goes off during it), and
// reception, idle, busy and sleeping time when it ends; `SecondsIn` completes the picture up to
// now. Periods are counted once: ns-3 logs the idle time before a sleep again when a radio that
// slept is switched off.
#pragma once

#include <ns3/nstime.h>
#include <ns3/simulator.h>
#include <ns3/wifi-phy-state.h>
#include <ns3/wifi-phy.h>

#include <array>

namespace sanet::energy {

class RadioStates {
 public:
  explicit RadioStates(ns3::Ptr<ns3::WifiPhy> phy);
  // The seconds spent in `state` from the start to now.
  double SecondsIn(::WifiPhyState state) const;
  // The radio was switched on again (after an off): ns-3 may log the idle time before the off
  // and after as one period, so periods are counted from here.
  void SwitchedOn() { on_since_ = ns3::Simulator::Now(); }

 private:
  void Logged(ns3::Time start, ns3::Time duration, ::WifiPhyState state);

  ns3::Ptr<ns3::WifiPhy> phy_;
  std::array<ns3::Time, 8> time_{};  // by WifiPhyState
  ns3::Time logged_until_, on_since_;
  ::WifiPhyState last_logged_ = ::WifiPhyState::IDLE;
};

}  // namespace sanet::energy
