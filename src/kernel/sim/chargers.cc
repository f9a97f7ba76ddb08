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

// A robot charges only motes (nodes without a drive), and only while it is alive and on.
void Chargers::WirelessChargersGive(std::vector<double>& given) {
  for (NodeId robot = 0; robot < world_.size(); ++robot) {
    energy::NodeEnergy* carrier = world_.batteries().Of(robot);
    if (!carrier || !carrier->spec().wireless_charger) continue;
    const energy::WirelessCharger& charger = *carrier->spec().wireless_charger;
    bool radiating = false;
    if (Alive(robot)) {
      const Vec2 from = world_.model(robot).body().pose().position();
      for (NodeId mote = 0; mote < world_.size(); ++mote) {
        energy::NodeEnergy* target = world_.batteries().Of(mote);
        if (!target || target->spec().drive) continue;
        const double share = charger.Efficiency(Norm(world_.model(mote).body().pose().position() - from));
        if (share <= 0 || target->full()) continue;
        given[mote] += charger.power_w * share;
        radiating = true;
      }
    }
    carrier->SetRadiating(radiating);
  }
}

bool Chargers::Alive(NodeId id) const { return !world_.batteries().dead(id) && !world_.SwitchedOff(id); }

}  // namespace sanet::sim
