// How long a Wi-Fi PHY spent in each of its states, summed from its own state trace
// (WifiPhyStateHelper's `State`: ns-3 gives a radio's energy only as a total, so the energy by
// state is each state's time times its current times the voltage). The trace logs a frame's
// transmission or reception when it starts, for its whole duration, and idle, busy and sleeping
// time when it ends; `SecondsIn` completes the picture up to now.
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
