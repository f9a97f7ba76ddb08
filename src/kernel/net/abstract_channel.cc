#include "net/abstract_channel.h"

#include <ns3/mobility-model.h>
#include <ns3/node.h>
#include <ns3/simulator.h>

#include <algorithm>

#include "core/counter_random.h"

namespace sanet::net {
namespace {

constexpr std::uint64_t kDeliveryKey = 0x41425354ull;  // "ABST"

ns3::Ptr<ns3::MobilityModel> MobilityOf(const ns3::Ptr<ns3::SimpleNetDevice>& device) {
  return device->GetNode()->GetObject<ns3::MobilityModel>();
}

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
  if (devices_.size() <= index) devices_.resize(index + 1), sent_.resize(index + 1, 0), off_.resize(index + 1, false);
  devices_[index] = device;
  by_address_[ns3::Mac48Address::ConvertFrom(device->GetAddress())] = index;
  Moved(index);
}

void AbstractChannel::Moved(std::uint32_t index) {
  if (index >= devices_.size() || !devices_[index]) return;
  const ns3::Vector at = MobilityOf(devices_[index])->GetPosition();
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
    if (addressee != by_address_.end()) Offer(origin, addressee->second, frame, p, protocol, to, from);
    return;
  }
  const ns3::Vector at = MobilityOf(sender)->GetPosition();
  near_.clear();
  grid_.Near(at.x, at.y, settings_.range_m, near_);
  for (std::uint32_t receiver : near_)
    if (receiver != origin) Offer(origin, receiver, frame, p, protocol, to, from);
}

// The receiver gets the frame with the calibration's probability at the link's mean power.
void AbstractChannel::Offer(std::uint32_t from, std::uint32_t to, std::uint64_t frame, ns3::Ptr<ns3::Packet> p,
                            uint16_t protocol, ns3::Mac48Address dst, ns3::Mac48Address src) {
  if (off_[to]) return;
  ++counters_.asked;
  const ns3::Ptr<ns3::SimpleNetDevice>& receiver = devices_[to];
  const double dbm =
      settings_.mean_loss->CalcRxPower(settings_.tx_power_dbm(from), MobilityOf(devices_[from]), MobilityOf(receiver));
  if (dbm < lowest_dbm_) return;
  CounterRandom draw(settings_.seed, {kDeliveryKey, from, to, frame});
  if (draw.Uniform() >= settings_.calibration.Prr(dbm)) return;
  ++counters_.delivered;
  ns3::Simulator::ScheduleWithContext(to, ns3::Seconds(settings_.calibration.AccessDelay(dbm)),
                                      &ns3::SimpleNetDevice::Receive, receiver, p->Copy(), protocol, dst, src);
}

}  // namespace sanet::net
