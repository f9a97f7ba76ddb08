// An IEEE 802.15.4 transceiver's draw on ns-3's energy framework (ns-3 3.37 has no device energy
// model for lr-wpan): the current of the state its PHY is in, from the PHY's TrxState trace.
//
//   PHY state (ns-3's LrWpanPhy)                       sanet state   CC2420 mode (datasheet)
//   BUSY_TX, TX_ON                                     tx            transmit
//   BUSY_RX; RX_ON unless asleep                       rx            receive (listening costs as much)
//   asleep with its MAC idle (net::LrWpanRadios)       sleep         power down
//   TRX_OFF                                            idle          idle: oscillator on
//   the node switched off or dead                      off           nothing
//
// A radio is asleep by its duty cycle or its controller's SetRadioSleep; it still wakes to send and
// to hear the acknowledgement, while its MAC is busy (net/lr_wpan_radios.h).
// It keeps what it charged in each state, so the energy by state adds up to what the source lost.
#pragma once

#include <ns3/device-energy-model.h>
#include <ns3/energy-source.h>
#include <ns3/lr-wpan-net-device.h>
#include <ns3/nstime.h>

#include <array>
#include <functional>

#include "energy/energy_spec.h"
#include "energy/state_tally.h"

namespace sanet::energy {

class LrWpanEnergyModel : public ns3::DeviceEnergyModel {
 public:
  enum State { kTx, kRx, kIdle, kSleep, kOff, kStates };
  static constexpr const char* kStateNames[kStates] = {"tx", "rx", "idle", "sleep", "off"};
  using ByState = StateTally<kStates>::ByState;
  static ns3::TypeId GetTypeId();

  void SetEnergySource(ns3::Ptr<ns3::EnergySource> source) override { source_ = ns3::PeekPointer(source); }
  void SetCurrents(const RadioCurrents& currents) { currents_ = currents; }
  // Follows `device`'s PHY from now on, and whether it sleeps (`sleeping`, asked again at each
  // call of SleepChanged).
  void Attach(ns3::Ptr<ns3::LrWpanNetDevice> device, std::function<bool()> sleeping);
  void SleepChanged() { PhyChanged(phy_state_); }
  // The node is on (alive, not switched off) or not: off, the transceiver draws nothing.
  void SetOn(bool on);

  double GetTotalEnergyConsumption() const override;
  ByState JoulesByState() const;  // up to now
  ByState SecondsByState() const;
  State state() const { return state_; }

  void ChangeState(int) override {}
  void HandleEnergyDepletion() override {}
  void HandleEnergyRecharged() override {}
  void HandleEnergyChanged() override {}

 private:
  double DoGetCurrentA() const override { return CurrentOf(state_); }
  double CurrentOf(State state) const;
  double Volts() const { return source_ ? source_->GetSupplyVoltage() : 0; }
  void PhyChanged(ns3::LrWpanPhyEnumeration state);
  State StateOf(ns3::LrWpanPhyEnumeration phy) const;
  void Enter(State state);

  ns3::EnergySource* source_ = nullptr;  // the source holds this model: a Ptr would be a cycle
  std::function<bool()> sleeping_;
  RadioCurrents currents_;
  State state_ = kRx;  // a fresh PHY listens (macRxOnWhenIdle)
  ns3::LrWpanPhyEnumeration phy_state_ = ns3::IEEE_802_15_4_PHY_RX_ON;
  bool on_ = true;
  StateTally<kStates> tally_;
};

}  // namespace sanet::energy
