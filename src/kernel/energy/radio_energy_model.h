// ns-3's WifiRadioEnergyModel, unchanged but for three things. It keeps what it charged its
// source in each state (ns-3's keeps a total only), so that the energy by state adds up to what
// the battery lost. At every change of the radio's state
// ns-3's model schedules a switch to OFF for when its source would be empty at the new state's
// current, and cancels the one before. A cancelled ns-3 event stays in the scheduler until its
// time comes, hours or months ahead for a battery, so a radio that changes state thousands of
// times a second filled the scheduler: 224,000 dead events in 5 s of a 400-mote field, each
// insertion slower than the last. This model removes the pending switch first
// (Simulator::Remove), so the scheduler holds one per radio. And it asks its source for an update
// after the change as well as before (ns-3's asks before only), so that sanet's battery, which
// schedules nothing while nothing draws, sees a current that starts.
#pragma once

#include <ns3/nstime.h>
#include <ns3/simulator.h>
#include <ns3/wifi-radio-energy-model.h>

#include <array>

namespace sanet::energy {

class RadioEnergyModel : public ns3::WifiRadioEnergyModel {
 public:
  static ns3::TypeId GetTypeId();
  using ByState = std::array<double, 8>;  // J, by WifiPhyState
  void SetEnergySource(ns3::Ptr<ns3::EnergySource> source) override;
  void ChangeState(int new_state) override;
  // The joules it charged in each state, up to now.
  ByState JoulesByState() const;

 private:
  ByState joules_{};
  ns3::Time since_ = ns3::Simulator::Now();  // the start of the state it is in
  ns3::EnergySource* source_ = nullptr;      // it holds this model: a Ptr would be a cycle
};

}  // namespace sanet::energy
