#include "net/indexed_channel.h"

#include <ns3/constant-position-mobility-model.h>
#include <ns3/node.h>
#include <ns3/pointer.h>
#include <ns3/simulator.h>
#include <ns3/wifi-net-device.h>
#include <ns3/wifi-ppdu.h>
#include <ns3/wifi-utils.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace sanet::net {
namespace {
constexpr double kFarthest = 1e7;  // m: beyond this a range is taken as unbounded
}  // namespace

NS_OBJECT_ENSURE_REGISTERED(IndexedWifiChannel);
NS_OBJECT_ENSURE_REGISTERED(IndexedWifiPhy);

ns3::TypeId IndexedWifiChannel::GetTypeId() {
  static ns3::TypeId tid = ns3::TypeId("sanet::IndexedWifiChannel")
                               .SetParent<ns3::YansWifiChannel>()
                               .SetGroupName("sanet")
                               .AddConstructor<IndexedWifiChannel>();
  return tid;
}

// Radios join the base channel (YansWifiPhy::SetChannel calls Add, which is not virtual); this
// channel learns of them from its device list before it needs them.
void IndexedWifiChannel::JoinNewRadios() {
  if (!loss_) {
    ns3::PointerValue loss, delay;
    GetAttribute("PropagationLossModel", loss);
    GetAttribute("PropagationDelayModel", delay);
    loss_ = loss.Get<ns3::PropagationLossModel>();
    if (!range_loss_) range_loss_ = loss_;
    delay_ = delay.Get<ns3::PropagationDelayModel>();
    probe_from_ = ns3::CreateObject<ns3::ConstantPositionMobilityModel>();
    probe_to_ = ns3::CreateObject<ns3::ConstantPositionMobilityModel>();
  }
  const std::size_t first = radios_.size();
  if (first == GetNDevices()) return;
  for (std::size_t i = first; i < GetNDevices(); ++i) {
    ns3::Ptr<ns3::NetDevice> device = GetDevice(i);
    auto phy = ns3::DynamicCast<ns3::YansWifiPhy>(ns3::DynamicCast<ns3::WifiNetDevice>(device)->GetPhy());
    radios_.push_back({phy, phy->GetMobility(), device->GetNode()->GetId()});
    if (phy->GetRxGain() > max_rx_gain_) {
      max_rx_gain_ = phy->GetRxGain();
      ranges_.clear();
    }
  }
  if (!grid_) {
    // Cells as wide as the first radio's range: a query looks at about nine of them.
    const ns3::Ptr<ns3::YansWifiPhy> phy = radios_.front().phy;
    for (const Radio& radio : radios_) top_ = std::max(top_, radio.mobility->GetPosition().z);
    const double range = Range(phy->GetTxPowerEnd() + phy->GetTxGain());
    grid_ = std::make_unique<SpatialGrid>(std::clamp(range, 1.0, kFarthest));
  }
  for (std::size_t i = first; i < radios_.size(); ++i) Index(static_cast<std::uint32_t>(i));
}

void IndexedWifiChannel::Index(std::uint32_t index) {
  const ns3::Vector p = radios_[index].mobility->GetPosition();
  if (p.z > top_) {
    top_ = p.z;
    ranges_.clear();
  }
  grid_->Place(index, p.x, p.y);
}

void IndexedWifiChannel::Moved(std::uint32_t index) {
  if (!grid_) return;  // no frame sent yet: the grid is built from the positions of then
  if (index >= radios_.size()) JoinNewRadios();
  if (index < radios_.size()) Index(index);
}

double IndexedWifiChannel::LossAt(double tx_power_dbm, double distance) const {
  probe_from_->SetPosition(ns3::Vector(0, 0, top_));
  probe_to_->SetPosition(ns3::Vector(distance, 0, top_));
  return range_loss_->CalcRxPower(tx_power_dbm, probe_from_, probe_to_);
}

// Every loss model sanet builds (log-distance, Friis, two-ray ground, each with an optional range
// cut-off) loses more with distance, so the range is where the received power crosses the floor:
// found by doubling, then bisection. Both ends sit at the highest antenna seen, where the
// two-ray model loses least and the distance in 3D equals the one on the ground; the candidates'
// exact power is checked anyway, so the range only has to be wide enough.
double IndexedWifiChannel::Range(double tx_power_dbm) {
  if (auto found = ranges_.find(tx_power_dbm); found != ranges_.end()) return found->second;
  const double target = floor_ - max_rx_gain_ - margin_db_;
  double inside = 0, outside = 1;
  while (LossAt(tx_power_dbm, outside) >= target && outside < kFarthest) {
    inside = outside;
    outside *= 2;
  }
  double range = std::numeric_limits<double>::infinity();
  if (outside < kFarthest) {
    for (int i = 0; i < 60 && outside - inside > 1e-6; ++i) {
      const double middle = 0.5 * (inside + outside);
      (LossAt(tx_power_dbm, middle) >= target ? inside : outside) = middle;
    }
    range = outside * 1.0001 + 1e-3;
  }
  ranges_[tx_power_dbm] = range;
  return range;
}

// As YansWifiChannel::Send, receiver by receiver in the order radios joined (so receptions at
// equal times are scheduled in the same order as Yans schedules them), but over the grid's
// candidates only, and without the ones under the floor.
void IndexedWifiChannel::SendNear(ns3::Ptr<ns3::YansWifiPhy> sender, ns3::Ptr<const ns3::WifiPpdu> ppdu,
                                  double tx_power_dbm) {
  // The sender's position first: reading one publishes the bodies of steps that have ended
  // (net::PoseFeed), which re-indexes them.
  const ns3::Ptr<ns3::MobilityModel> from = sender->GetMobility();
  const ns3::Vector at = from->GetPosition();
  JoinNewRadios();
  near_.clear();
  const double range = Range(tx_power_dbm);
  grid_->Near(at.x, at.y, range, near_);
  for (std::uint32_t index : near_) {
    const Radio& to = radios_[index];
    if (to.phy == sender || to.phy->GetChannelNumber() != sender->GetChannelNumber()) continue;
    ++counters_.candidates;
    // Beyond the range (on the ground, never more than in 3D) even the loss models' most
    // favourable draws leave the frame under the floor: skip them before any model is asked.
    const ns3::Vector there = to.mobility->GetPosition();
    if (std::hypot(there.x - at.x, there.y - at.y) > range) continue;
    const double rx_power_dbm = loss_->CalcRxPower(tx_power_dbm, from, to.mobility);
    if (rx_power_dbm + to.phy->GetRxGain() < floor_) continue;
    ++counters_.handed;
    ns3::Simulator::ScheduleWithContext(to.context, delay_->GetDelay(from, to.mobility), &IndexedWifiChannel::Receive,
                                        to.phy, ppdu, rx_power_dbm);
  }
}

// What YansWifiChannel::Receive does: the PHY's own sensitivity check, then the preamble.
void IndexedWifiChannel::Receive(ns3::Ptr<ns3::YansWifiPhy> phy, ns3::Ptr<const ns3::WifiPpdu> ppdu,
                                 double rx_power_dbm) {
  const double width = ppdu->GetTransmissionChannelWidth();
  if (rx_power_dbm + phy->GetRxGain() < phy->GetRxSensitivity() + ns3::RatioToDb(width / 20.0)) return;
  ns3::RxPowerWattPerChannelBand powers;
  powers.insert({ns3::WifiSpectrumBand(0, 0), ns3::DbmToW(rx_power_dbm + phy->GetRxGain())});
  phy->StartReceivePreamble(ppdu, powers, ppdu->GetTxDuration());
}

ns3::TypeId IndexedWifiPhy::GetTypeId() {
  static ns3::TypeId tid = ns3::TypeId("sanet::IndexedWifiPhy")
                               .SetParent<ns3::YansWifiPhy>()
                               .SetGroupName("sanet")
                               .AddConstructor<IndexedWifiPhy>();
  return tid;
}

void IndexedWifiPhy::StartTx(ns3::Ptr<const ns3::WifiPpdu> ppdu, const ns3::WifiTxVector&) {
  ns3::StaticCast<IndexedWifiChannel>(GetChannel())
      ->SendNear(this, ppdu, GetTxPowerForTransmission(ppdu) + GetTxGain());
}

void RadioPhyHelper::UseIndexedPhy() { m_phy.at(0).SetTypeId(IndexedWifiPhy::GetTypeId()); }

}  // namespace sanet::net
