// The abstract radio's draw on ns-3's energy framework (net/abstract_channel.h has no PHY and so no
// PHY states): transmitting for each frame's airtime from when the channel takes it, receiving for
// each frame's airtime from when it arrives, idle (listening) otherwise, nothing while the node is
// off. A frame sent while receiving draws the transmit current; the abstract radio does not sleep.
// The currents are the 802.11 radio's (energy.radio); what the full model's PHY spends in CCA-busy
// is idle here. It keeps what it charged in each state, so the energy by state adds up to what the
// source lost.
#pragma once

#include <ns3/device-energy-model.h>
#include <ns3/energy-source.h>
#include <ns3/event-id.h>
#include <ns3/nstime.h>

#include <array>

#include "energy/energy_spec.h"
#include "energy/state_tally.h"

namespace sanet::energy {

class AirtimeEnergyModel : public ns3::DeviceEnergyModel {
 public:
  enum State { kTx, kRx, kIdle, kOff, kStates };
  static constexpr const char* kStateNames[kStates] = {"tx", "rx", "idle", "off"};
  using ByState = StateTally<kStates>::ByState;
  static ns3::TypeId GetTypeId();

  // Draws from `source` from now on (a robot spawned mid-run has drawn nothing before).
  void SetEnergySource(ns3::Ptr<ns3::EnergySource> source) override {
    source_ = ns3::PeekPointer(source);
    tally_.Start();
  }
  void SetCurrents(const RadioCurrents& currents) { currents_ = currents; }
  // A frame on the air from now for `seconds`: sent by this radio, or received.
  void OnAir(bool sent, double seconds);
  void SetOn(bool on);

  double GetTotalEnergyConsumption() const override;
  ByState JoulesByState() const;  // up to now
  ByState SecondsByState() const;

  void ChangeState(int) override {}
  void HandleEnergyDepletion() override {}
  void HandleEnergyRecharged() override {}
  void HandleEnergyChanged() override {}

 protected:
  void DoDispose() override;

 private:
  double DoGetCurrentA() const override { return CurrentOf(state_); }
  double CurrentOf(State state) const;
  double Volts() const { return source_ ? source_->GetSupplyVoltage() : 0; }
  State Due() const;  // what the radio does now, by the frames on the air
  void Update();      // enters Due(), and comes back when it changes
  void Enter(State state);

  ns3::EnergySource* source_ = nullptr;  // the source holds this model: a Ptr would be a cycle
  RadioCurrents currents_;
  State state_ = kIdle;
  bool on_ = true;
  ns3::Time tx_until_, rx_until_;
  ns3::EventId next_;
  StateTally<kStates> tally_;
};

}  // namespace sanet::energy
