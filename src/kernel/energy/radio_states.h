// The energy a Wi-Fi PHY spent in each of its states, summed from its own state trace
// (WifiPhyStateHelper's `State`): ns-3 gives a radio's energy only as a total. Each period the
// trace logs costs its time times its state's current times the supply voltage when it is logged
// (constant for sanet's Battery; the curve's for a LiIonCell). The trace logs a transmission when
// it starts, for its whole duration (and again, as far as it went, if the radio goes off during
// it), and reception, idle, busy and sleeping time when it ends; `JoulesIn` completes the picture
// up to now. Periods are counted once: ns-3 logs the idle time before a sleep again when a radio
// that slept is switched off.
#pragma once

#include <ns3/nstime.h>
#include <ns3/simulator.h>
#include <ns3/wifi-phy-state.h>
#include <ns3/wifi-phy.h>

#include <array>
#include <functional>

namespace sanet::energy {

class RadioStates {
 public:
  using Currents = std::array<double, 8>;  // A, by WifiPhyState
  RadioStates(ns3::Ptr<ns3::WifiPhy> phy, Currents currents, std::function<double()> voltage);
  // The joules spent in `state` from the start to now.
  double JoulesIn(::WifiPhyState state) const;
  // The radio was switched on again (after an off): ns-3 may log the idle time before the off
  // and after as one period, so periods are counted from here.
  void SwitchedOn() { on_since_ = ns3::Simulator::Now(); }

 private:
  void Logged(ns3::Time start, ns3::Time duration, ::WifiPhyState state);
  double Joules(::WifiPhyState state, ns3::Time duration) const;

  ns3::Ptr<ns3::WifiPhy> phy_;
  Currents currents_;
  std::function<double()> voltage_;
  std::array<double, 8> joules_{};  // by WifiPhyState
  ns3::Time logged_until_, on_since_;
  ::WifiPhyState last_logged_ = ::WifiPhyState::IDLE;
};

}  // namespace sanet::energy
