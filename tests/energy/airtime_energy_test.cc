// The abstract radio's energy model: the state it is in follows the frames on the air (sending
// before receiving), off while the node is off, and the seconds in each count from its creation.
#include <gtest/gtest.h>
#include <ns3/simulator.h>

#include "energy/airtime_energy_model.h"

namespace sanet::energy {
namespace {

TEST(AirtimeEnergy, StatesFollowTheFramesOnTheAirFromTheModelsCreation) {
  ns3::Ptr<AirtimeEnergyModel> model;
  AirtimeEnergyModel::ByState seconds{};
  ns3::Simulator::Schedule(ns3::Seconds(5), [&model] {  // a robot spawned at 5 s
    model = ns3::CreateObject<AirtimeEnergyModel>();
    model->SetEnergySource(nullptr);
  });
  ns3::Simulator::Schedule(ns3::Seconds(6), [&model] { model->OnAir(true, 0.5); });
  ns3::Simulator::Schedule(ns3::Seconds(6.2), [&model] {
    EXPECT_DOUBLE_EQ(model->GetCurrentA(), RadioCurrents{}.tx_a) << "sending";
    model->OnAir(false, 1.0);  // heard while sending: received until 7.2 s, after the sending ends
  });
  ns3::Simulator::Schedule(ns3::Seconds(7), [&model] { EXPECT_DOUBLE_EQ(model->GetCurrentA(), RadioCurrents{}.rx_a); });
  ns3::Simulator::Schedule(ns3::Seconds(8), [&model] {
    EXPECT_DOUBLE_EQ(model->GetCurrentA(), RadioCurrents{}.idle_a);
    model->SetOn(false);
  });
  ns3::Simulator::Schedule(ns3::Seconds(10), [&] { seconds = model->SecondsByState(); });
  ns3::Simulator::Run();
  ns3::Simulator::Destroy();
  EXPECT_NEAR(seconds[AirtimeEnergyModel::kTx], 0.5, 1e-9);
  EXPECT_NEAR(seconds[AirtimeEnergyModel::kRx], 0.7, 1e-9);
  EXPECT_NEAR(seconds[AirtimeEnergyModel::kIdle], 1.0 + 0.8, 1e-9);
  EXPECT_NEAR(seconds[AirtimeEnergyModel::kOff], 2.0, 1e-9);
}

}  // namespace
}  // namespace sanet::energy
