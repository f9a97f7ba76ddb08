// What a node's electronics draw (processor, sensors at rest): a constant power while the node
// is alive, none while it is dead or switched off. It is also the node's ear on its energy
// source: whatever the source (sanet's Battery or ns-3's LiIonEnergySource), it tells each of its
// device models when it is depleted or recharged, and this model passes that on.
#pragma once

#include <ns3/device-energy-model.h>
#include <ns3/energy-source.h>
#include <ns3/nstime.h>

#include <functional>

namespace sanet::energy {

class ElectronicsModel : public ns3::DeviceEnergyModel {
 public:
  static ns3::TypeId GetTypeId();

  void SetEnergySource(ns3::Ptr<ns3::EnergySource> source) override { source_ = source; }
  void SetCallbacks(std::function<void()> depleted, std::function<void()> recharged);
  // The draw while on, in W; and whether the node is on now.
  void SetPower(double watts);
  void SetOn(bool on);
  double GetTotalEnergyConsumption() const override;

  void ChangeState(int new_state) override { SetOn(new_state != 0); }
  void HandleEnergyDepletion() override;
  void HandleEnergyRecharged() override;
  void HandleEnergyChanged() override {}

 private:
  double DoGetCurrentA() const override;
  void Account();  // what was drawn since the last change
  void Change(double watts, bool on);

  ns3::Ptr<ns3::EnergySource> source_;
  double watts_ = 0;
  bool on_ = true;
  double used_j_ = 0;
  ns3::Time last_;
  std::function<void()> depleted_, recharged_;
};

}  // namespace sanet::energy
