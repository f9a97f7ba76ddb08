#include "sim/chargers.h"

#include <ns3/simulator.h>

namespace sanet::sim {

void Chargers::Start() {
  if (started_) return;
  bool any = !world_.spec().chargers.empty();
  for (NodeId id = 0; id < world_.size() && !any; ++id)
    if (const energy::NodeEnergy* e = world_.batteries().Of(id)) any = e->spec().wireless_charger.has_value();
  if (!any) return;
  started_ = true;
  ns3::Simulator::ScheduleNow(&Chargers::Update, this);
}

void Chargers::Update() {
  std::vector<double> given = WorldChargersGive();
  WirelessChargersGive(given);
  for (NodeId id = 0; id < world_.size(); ++id)
    if (energy::NodeEnergy* e = world_.batteries().Of(id)) e->SetCharging(given[id]);
  ns3::Simulator::Schedule(ns3::Seconds(kInterval), &Chargers::Update, this);
}

std::vector<double> Chargers::WorldChargersGive() const {
  std::vector<double> given(world_.size(), 0);
  if (world_.spec().chargers.empty()) return given;
  for (NodeId id = 0; id < world_.size(); ++id) {
    if (!world_.batteries().Of(id)) continue;
    const Vec2 at = world_.model(id).body().pose().position();
    for (const Charger& c : world_.spec().chargers)
      if (Norm(at - c.position) <= c.radius) given[id] += c.power_w;
  }
  return given;
}

// A robot charges only motes (nodes without a drive), and only while it is alive and on. The
// motes' shares of its power never add up to more than all of it (an efficient charger's model
// could give each of several close motes nearly all).
void Chargers::WirelessChargersGive(std::vector<double>& given) {
  for (NodeId robot = 0; robot < world_.size(); ++robot) {
    energy::NodeEnergy* carrier = world_.batteries().Of(robot);
    if (!carrier || !carrier->spec().wireless_charger) continue;
    const std::vector<std::pair<NodeId, double>> shares = Alive(robot) ? SharesOf(robot) : decltype(shares){};
    double total = 0;
    for (const auto& [mote, share] : shares) total += share;
    const double scale = total > 1 ? 1 / total : 1;
    for (const auto& [mote, share] : shares) given[mote] += carrier->spec().wireless_charger->power_w * share * scale;
    carrier->SetRadiating(!shares.empty());
  }
}

// The motes that robot's charger reaches and that need charge, with the share each receives.
std::vector<std::pair<NodeId, double>> Chargers::SharesOf(NodeId robot) {
  const energy::WirelessCharger& charger = *world_.batteries().Of(robot)->spec().wireless_charger;
  const Vec2 from = world_.model(robot).body().pose().position();
  std::vector<std::pair<NodeId, double>> shares;
  for (NodeId mote = 0; mote < world_.size(); ++mote) {
    const energy::NodeEnergy* target = world_.batteries().Of(mote);
    if (!target || target->spec().drive || !NeedsCharge(mote, *target)) continue;
    const double share = charger.Efficiency(Norm(world_.model(mote).body().pose().position() - from));
    if (share > 0) shares.emplace_back(mote, share);
  }
  return shares;
}

// Once full, a mote waits until it is down to kTopUpBelow: a charger would otherwise switch on and
// off for the trickle a full mote draws, radiating watts to give it milliwatts.
bool Chargers::NeedsCharge(NodeId mote, const energy::NodeEnergy& energy) {
  topping_up_.resize(world_.size(), 1);
  if (energy.full()) {
    topping_up_[mote] = 0;
    return false;
  }
  if (!topping_up_[mote] && energy.remaining_j() >= kTopUpBelow * energy.spec().battery_j) return false;
  topping_up_[mote] = 1;
  return true;
}

bool Chargers::Alive(NodeId id) const { return !world_.batteries().dead(id) && !world_.SwitchedOff(id); }

}  // namespace sanet::sim
