#include "net/abstract_channel.h"

#include <ns3/node.h>
#include <ns3/simulator.h>

#include <algorithm>

#include "core/counter_random.h"
#include "net/frame_trace.h"

namespace sanet::net {
namespace {

constexpr std::uint64_t kDeliveryKey = 0x41425354ull;  // "ABST"

}  // namespace

ns3::TypeId AbstractChannel::GetTypeId() {
  static ns3::TypeId tid = ns3::TypeId("sanet::net::AbstractChannel")
                               .SetParent<ns3::SimpleChannel>()
                               .SetGroupName("sanet")
                               .AddConstructor<AbstractChannel>();
  return tid;
}

void AbstractChannel::Configure(Settings settings) {
  settings_ = std::move(settings);
  lowest_dbm_ = settings_.calibration.LowestHeardDbm();
  grid_ = SpatialGrid(std::max(1.0, settings_.range_m));
}

void AbstractChannel::Add(ns3::Ptr<ns3::SimpleNetDevice> device) {
  const std::uint32_t index = device->GetNode()->GetId();
  if (devices_.size() <= index) {
    devices_.resize(index + 1), mobility_.resize(index + 1);
    sent_.resize(index + 1, 0), off_.resize(index + 1, false);
  }
  devices_[index] = device;
  mobility_[index] = device->GetNode()->GetObject<ns3::MobilityModel>();
  by_address_[ns3::Mac48Address::ConvertFrom(device->GetAddress())] = index;
  Moved(index);
}

void AbstractChannel::Moved(std::uint32_t index) {
  if (index >= devices_.size() || !devices_[index]) return;
  const ns3::Vector at = mobility_[index]->GetPosition();
  grid_.Place(index, at.x, at.y);
}

void AbstractChannel::Send(ns3::Ptr<ns3::Packet> p, uint16_t protocol, ns3::Mac48Address to, ns3::Mac48Address from,
                           ns3::Ptr<ns3::SimpleNetDevice> sender) {
  const std::uint32_t origin = sender->GetNode()->GetId();
  const std::uint64_t frame = sent_[origin]++;
  if (off_[origin]) return;
  ++counters_.frames;
  if (!to.IsBroadcast() && !to.IsGroup()) {
    const auto addressee = by_address_.find(to);
    const std::optional<std::uint32_t> peer =
        addressee == by_address_.end() ? std::nullopt : std::optional(addressee->second);
    if (observer_) Observe(origin, true, peer, p, protocol, false);
    acknowledged_ = false, attempts_ = settings_.unicast.attempts;
    if (peer) Offer(origin, *peer, frame, p, protocol, to, from);
    // The sender is on the air for every attempt: all of them where nobody acknowledges.
    if (on_air_) on_air_(origin, true, Airtime(p->GetSize(), false) * attempts_);
    if (!acknowledged_ && gave_up_) gave_up_(origin, p);
    return;
  }
  if (observer_) Observe(origin, true, std::nullopt, p, protocol, true);
  if (on_air_) on_air_(origin, true, Airtime(p->GetSize(), true));
  const ns3::Vector at = mobility_[origin]->GetPosition();
  near_.clear();
  grid_.Near(at.x, at.y, settings_.range_m, near_);
  for (std::uint32_t receiver : near_)
    if (receiver != origin) Offer(origin, receiver, frame, p, protocol, to, from);
}

// The receiver gets the frame with the calibration's probability at the link's mean power; a
// unicast has the MAC's attempts.
void AbstractChannel::Offer(std::uint32_t from, std::uint32_t to, std::uint64_t frame, ns3::Ptr<ns3::Packet> p,
                            uint16_t protocol, ns3::Mac48Address dst, ns3::Mac48Address src) {
  if (off_[to]) return;
  ++counters_.asked;
  const double dbm = settings_.mean_loss->CalcRxPower(settings_.tx_power_dbm(from), mobility_[from], mobility_[to]);
  if (dbm < lowest_dbm_) return;
  const bool broadcast = dst.IsBroadcast() || dst.IsGroup();
  const double beyond = AirtimeBeyondSerialization(p->GetSize(), broadcast);
  double retrying = 0;
  if (broadcast) {
    const double prr = settings_.calibration.Prr(dbm);
    if (CounterRandom(settings_.seed, {kDeliveryKey, from, to, frame, 0}).Uniform() >= prr) return;
  } else {
    const auto spent = UnicastRetries(from, to, frame, settings_.calibration.UnicastPrr(dbm),
                                      beyond + p->GetSize() * 8 / settings_.data_rate_bps);
    if (!spent) return;
    retrying = *spent;
  }
  ++counters_.delivered;
  const ns3::Time delay = ns3::Seconds(beyond + settings_.calibration.AccessDelay(dbm) + retrying);
  if (observer_ || on_air_)
    ns3::Simulator::ScheduleWithContext(to, delay, &AbstractChannel::Arrive, this, from, to, p->Copy(), protocol, dst,
                                        src);
  else
    ns3::Simulator::ScheduleWithContext(to, delay, &ns3::SimpleNetDevice::Receive, devices_[to], p->Copy(), protocol,
                                        dst, src);
}

// The time from the first attempt's start to the start of the first that reached the addressee;
// none if no attempt did.
std::optional<double> AbstractChannel::UnicastRetries(std::uint32_t from, std::uint32_t to, std::uint64_t frame,
                                                      double prr, double airtime) {
  const Settings::Retries& r = settings_.unicast;
  double spent = 0;
  std::optional<double> arrived;
  for (int k = 0; k < r.attempts; ++k) {
    CounterRandom draw(settings_.seed, {kDeliveryKey, from, to, frame, static_cast<std::uint64_t>(k)});
    const bool reached = draw.Uniform() < prr;
    if (reached && !arrived) arrived = spent;
    if (reached && draw.Uniform() < prr) {
      attempts_ = k + 1, acknowledged_ = true;
      break;
    }
    const int window = std::min(((r.cw_min + 1) << std::min(k + 1, 16)) - 1, r.cw_max);
    const double ack_timeout = r.sifs_s + r.slot_s + r.ack_s, difs = r.sifs_s + 2 * r.slot_s;
    spent += airtime + ack_timeout + difs + std::floor(draw.Uniform() * (window + 1)) * r.slot_s;
  }
  return arrived;
}

double AbstractChannel::Airtime(std::uint32_t bytes, bool broadcast) const {
  return bytes * 8 / settings_.data_rate_bps + AirtimeBeyondSerialization(bytes, broadcast);
}

double AbstractChannel::AirtimeBeyondSerialization(std::uint32_t bytes, bool broadcast) const {
  const double rate = broadcast ? settings_.broadcast_rate_bps : settings_.data_rate_bps;
  return settings_.preamble_s + kMacOverhead * 8 / rate + bytes * 8 * (1 / rate - 1 / settings_.data_rate_bps);
}

void AbstractChannel::Arrive(std::uint32_t from, std::uint32_t to, ns3::Ptr<ns3::Packet> p, uint16_t protocol,
                             ns3::Mac48Address dst, ns3::Mac48Address src) {
  if (off_[to]) return;  // switched off or dead while the frame was on its way
  const bool broadcast = dst.IsBroadcast() || dst.IsGroup();
  if (observer_) Observe(to, false, from, p, protocol, broadcast);
  if (on_air_) on_air_(to, false, Airtime(p->GetSize(), broadcast));
  devices_[to]->Receive(p, protocol, dst, src);
}

void AbstractChannel::Observe(std::uint32_t node, bool sent, std::optional<std::uint32_t> peer,
                              ns3::Ptr<const ns3::Packet> p, uint16_t protocol, bool broadcast) const {
  FrameEvent e;
  e.t = ns3::Simulator::Now().GetSeconds();
  e.node = node;
  e.sent = sent;
  if (peer) e.peer = NodeId{*peer};
  e.bytes = p->GetSize() + kMacOverhead;
  e.kind = PayloadKind(protocol, p->Copy(), broadcast);
  observer_(e);
}

}  // namespace sanet::net
