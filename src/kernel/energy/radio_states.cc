#include "energy/radio_states.h"

#include <ns3/wifi-phy-state-helper.h>

#include <algorithm>

namespace sanet::energy {

RadioStates::RadioStates(ns3::Ptr<ns3::WifiPhy> phy) : phy_(phy) {
  logged_until_ = on_since_ = ns3::Simulator::Now();
  phy_->GetState()->TraceConnectWithoutContext("State", ns3::MakeCallback(&RadioStates::Logged, this));
}

void RadioStates::Logged(ns3::Time start, ns3::Time duration, ::WifiPhyState state) {
  const ns3::Time end = start + duration;
  ns3::Time& in_state = time_.at(static_cast<std::size_t>(state));
  if (state == ::WifiPhyState::TX && last_logged_ == ::WifiPhyState::TX && start < logged_until_ &&
      end < logged_until_) {  // the radio went off during the frame logged ahead: it ended here
    in_state -= logged_until_ - end;
    logged_until_ = end;
    return;
  }
  start = std::max({start, on_since_, logged_until_});
  if (end <= start) return;
  in_state += end - start;
  logged_until_ = end;
  last_logged_ = state;
}

// Up to now: a frame logged ahead is counted only as far as now; time not logged yet is in the
// state the PHY is in now (idle or busy, sleeping, off).
double RadioStates::SecondsIn(::WifiPhyState state) const {
  const ns3::Time now = ns3::Simulator::Now();
  ns3::Time t = time_.at(static_cast<std::size_t>(state));
  if (logged_until_ > now && state == last_logged_) t -= logged_until_ - now;
  if (logged_until_ < now && phy_->GetState()->GetState() == state) t += now - std::max(logged_until_, on_since_);
  return t.GetSeconds();
}

}  // namespace sanet::energy
