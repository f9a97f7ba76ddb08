#include "energy/charge_harvester.h"

#include <ns3/energy-source.h>

namespace sanet::energy {

NS_OBJECT_ENSURE_REGISTERED(ChargeHarvester);

ns3::TypeId ChargeHarvester::GetTypeId() {
  static ns3::TypeId tid = ns3::TypeId("sanet::energy::ChargeHarvester")
                               .SetParent<ns3::EnergyHarvester>()
                               .SetGroupName("Energy")
                               .AddConstructor<ChargeHarvester>();
  return tid;
}

void ChargeHarvester::SetPower(double watts) {
  if (watts == watts_) return;
  if (source_) source_->UpdateEnergySource();
  watts_ = watts;
  if (source_) source_->UpdateEnergySource();
}

}  // namespace sanet::energy
