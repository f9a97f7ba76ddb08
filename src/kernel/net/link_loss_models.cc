#include "net/link_loss_models.h"

#include <ns3/node.h>
#include <ns3/simulator.h>

namespace sanet::net {

NS_OBJECT_ENSURE_REGISTERED(ShadowingLossModel);
NS_OBJECT_ENSURE_REGISTERED(FadingLossModel);

std::optional<std::uint32_t> NodeOf(const ns3::Ptr<ns3::MobilityModel>& mobility) {
  const ns3::Ptr<ns3::Node> node = mobility->GetObject<ns3::Node>();
  if (!node) return std::nullopt;
  return node->GetId();
}

ns3::TypeId ShadowingLossModel::GetTypeId() {
  static ns3::TypeId tid = ns3::TypeId("sanet::ShadowingLossModel")
                               .SetParent<ns3::PropagationLossModel>()
                               .SetGroupName("sanet")
                               .AddConstructor<ShadowingLossModel>();
  return tid;
}

double ShadowingLossModel::DoCalcRxPower(double tx_power_dbm, ns3::Ptr<ns3::MobilityModel> a,
                                         ns3::Ptr<ns3::MobilityModel> b) const {
  std::optional<std::uint32_t> from = NodeOf(a), to = NodeOf(b);
  if (!from || !to) return tx_power_dbm;
  ns3::Vector pa = a->GetPosition(), pb = b->GetPosition();
  if (symmetric_ && *to < *from) {
    std::swap(from, to);
    std::swap(pa, pb);
  }
  ++counters_.asked;
  if (kept_.size() >= kMaxKept) kept_.clear();
  auto [found, fresh] = kept_.try_emplace(std::uint64_t{*from} << 32 | *to);
  Kept& kept = found->second;
  if (fresh || kept.ax != pa.x || kept.ay != pa.y || kept.bx != pb.x || kept.by != pb.y) {
    ++counters_.computed;
    kept = {pa.x, pa.y, pb.x, pb.y, field_.GainDb(*from, pa.x, pa.y, *to, pb.x, pb.y)};
  }
  return tx_power_dbm + kept.gain_db;
}

ns3::TypeId FadingLossModel::GetTypeId() {
  static ns3::TypeId tid = ns3::TypeId("sanet::FadingLossModel")
                               .SetParent<ns3::PropagationLossModel>()
                               .SetGroupName("sanet")
                               .AddConstructor<FadingLossModel>();
  return tid;
}

double FadingLossModel::DoCalcRxPower(double tx_power_dbm, ns3::Ptr<ns3::MobilityModel> a,
                                      ns3::Ptr<ns3::MobilityModel> b) const {
  const double mean_dbm = mean_->CalcRxPower(tx_power_dbm, a, b);
  if (mean_dbm + fading_.MaxGainDb() < untaken_below_dbm_) return mean_dbm + fading_.MaxGainDb();
  const std::optional<std::uint32_t> from = NodeOf(a), to = NodeOf(b);
  if (!from || !to) return mean_dbm;
  return mean_dbm + fading_.GainDb(*from, *to, ns3::Simulator::Now().GetTimeStep());
}

}  // namespace sanet::net
