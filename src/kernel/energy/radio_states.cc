#include "energy/radio_states.h"

#include <ns3/wifi-phy-state-helper.h>

#include <algorithm>
#include <utility>

namespace sanet::energy {

RadioStates::RadioStates(ns3::Ptr<ns3::WifiPhy> phy, Currents currents, std::function<double()> voltage)
    : phy_(phy), currents_(currents), voltage_(std::move(voltage)) {
  logged_until_ = on_since_ = ns3::Simulator::Now();
  phy_->GetState()->TraceConnectWithoutContext("State", ns3::MakeCallback(&RadioStates::Logged, this));
}

double RadioStates::Joules(::WifiPhyState state, ns3::Time duration) const {
  return duration.GetSeconds() * currents_.at(static_cast<std::size_t>(state)) * voltage_();
}

void RadioStates::Logged(ns3::Time start, ns3::Time duration, ::WifiPhyState state) {
  const ns3::Time end = start + duration;
  if (state == ::WifiPhyState::TX && last_logged_ == ::WifiPhyState::TX && start < logged_until_ &&
      end < logged_until_) {  // the radio went off during the frame logged ahead: it ended here
    joules_.at(static_cast<std::size_t>(state)) -= Joules(state, logged_until_ - end);
    logged_until_ = end;
    return;
  }
  // Periods do not overlap, but ns-3's trace may log one that does: the idle time before a sleep
  // again when the radio goes off after it. What was counted already is not counted again.
  start = std::max({start, on_since_, logged_until_});
  if (end <= start) return;
  joules_.at(static_cast<std::size_t>(state)) += Joules(state, end - start);
  if (end >= logged_until_) {
    logged_until_ = end;
    last_logged_ = state;
  }
}

// Up to now: a frame logged ahead is counted only as far as now; time not logged yet is in the
// state the PHY is in now (idle or busy, sleeping, off).
double RadioStates::JoulesIn(::WifiPhyState state) const {
  const ns3::Time now = ns3::Simulator::Now();
  double joules = joules_.at(static_cast<std::size_t>(state));
  if (logged_until_ > now && state == last_logged_) joules -= Joules(state, logged_until_ - now);
  if (logged_until_ < now && phy_->GetState()->GetState() == state)
    joules += Joules(state, now - std::max(logged_until_, on_since_));
  return joules;
}

}  // namespace sanet::energy
