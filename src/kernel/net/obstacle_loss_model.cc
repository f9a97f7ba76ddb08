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

double ObstacleLossModel::AntennaHeight(const ns3::Ptr<ns3::MobilityModel>& mobility) const {
  const ns3::Ptr<ns3::Node> node = mobility->GetObject<ns3::Node>();
  return node && node->GetId() < antenna_heights_.size() ? antenna_heights_[node->GetId()] : 0.0;
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
  const bool same_pair = !fresh && kept.from == pa && kept.to == pb;
  if (same_pair && kept.a == at_a && kept.b == at_b) return kept.loss_db;
  ++counters_.walked;  // a pair met for the first time, one that moved, or one whose slot another took
  if (!same_pair) kept = {pa, pb, {}, {}, AntennaHeight(a), AntennaHeight(b), 0};
  kept.a = at_a, kept.b = at_b;
  kept.loss_db = obstacles_->LossDb({at_a.x, at_a.y, at_a.z + kept.height_a}, {at_b.x, at_b.y, at_b.z + kept.height_b});
  return kept.loss_db;
}

double ObstacleLossModel::DoCalcRxPower(double tx_power_dbm, ns3::Ptr<ns3::MobilityModel> a,
                                        ns3::Ptr<ns3::MobilityModel> b) const {
  return tx_power_dbm - LossDb(a, b);
}

}  // namespace sanet::net
