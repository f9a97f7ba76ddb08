#include "net/obstacle_loss_model.h"

#include <ns3/node.h>

#include <functional>
#include <utility>

namespace sanet::net {

NS_OBJECT_ENSURE_REGISTERED(ObstacleLossModel);

ns3::TypeId ObstacleLossModel::GetTypeId() {
  static ns3::TypeId tid = ns3::TypeId("sanet::ObstacleLossModel")
                               .SetParent<ns3::PropagationLossModel>()
                               .SetGroupName("sanet")
                               .AddConstructor<ObstacleLossModel>();
  return tid;
}

void ObstacleLossModel::SetAntennaHeight(std::uint32_t node, double height) {
  if (node >= antenna_heights_.size()) antenna_heights_.resize(node + 1, 0.0);
  antenna_heights_[node] = height;
  kept_.clear();
}

physics::Vec3 ObstacleLossModel::Antenna(const ns3::Ptr<ns3::MobilityModel>& mobility, const ns3::Vector& at) const {
  double height = 0;
  if (const ns3::Ptr<ns3::Node> node = mobility->GetObject<ns3::Node>();
      node && node->GetId() < antenna_heights_.size())
    height = antenna_heights_[node->GetId()];
  return {at.x, at.y, at.z + height};
}

double ObstacleLossModel::LossDb(ns3::Ptr<ns3::MobilityModel> a, ns3::Ptr<ns3::MobilityModel> b) const {
  if (!obstacles_ || obstacles_->empty()) return 0;
  ++counters_.asked;
  if (std::less<>()(ns3::PeekPointer(b), ns3::PeekPointer(a))) std::swap(a, b);  // the loss is symmetric
  const ns3::Vector at_a = a->GetPosition(), at_b = b->GetPosition();
  const void *pa = ns3::PeekPointer(a), *pb = ns3::PeekPointer(b);
  const std::uint64_t key = std::hash<const void*>()(pa) * 0x9E3779B97F4A7C15ULL ^ std::hash<const void*>()(pb);
  auto [found, fresh] = kept_.try_emplace(key);
  Kept& kept = found->second;
  if (!fresh && kept.from == pa && kept.to == pb && kept.a == at_a && kept.b == at_b) return kept.loss_db;
  ++counters_.walked;  // a pair met for the first time, one that moved, or one whose slot another took
  kept = {pa, pb, at_a, at_b, obstacles_->LossDb(Antenna(a, at_a), Antenna(b, at_b))};
  return kept.loss_db;
}

double ObstacleLossModel::DoCalcRxPower(double tx_power_dbm, ns3::Ptr<ns3::MobilityModel> a,
                                        ns3::Ptr<ns3::MobilityModel> b) const {
  return tx_power_dbm - LossDb(a, b);
}

}  // namespace sanet::net
