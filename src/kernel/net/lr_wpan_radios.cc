#include "net/lr_wpan_radios.h"

#include <ns3/boolean.h>
#include <ns3/double.h>
#include <ns3/icmpv6-l4-protocol.h>
#include <ns3/ipv6-interface.h>
#include <ns3/ipv6-l3-protocol.h>
#include <ns3/lr-wpan-csmaca.h>
#include <ns3/lr-wpan-mac-header.h>
#include <ns3/lr-wpan-mac-trailer.h>
#include <ns3/lr-wpan-mac.h>
#include <ns3/lr-wpan-phy.h>
#include <ns3/lr-wpan-spectrum-value-helper.h>
#include <ns3/mac64-address.h>
#include <ns3/mobility-model.h>
#include <ns3/ndisc-cache.h>
#include <ns3/simulator.h>
#include <ns3/single-model-spectrum-channel.h>
#include <ns3/string.h>

#include "net/channel_losses.h"
#include "net/hardware_spread.h"
#include "net/link_loss_models.h"

namespace sanet::net {

// The scenario's losses with each sender's own transmit power, and each receiver's sensitivity:
// the spectrum channel asks with 0 dBm (it scales the sender's spectrum by the gain), so the
// models that depend on the power a frame arrives with (the sensitivity, fading's cut) are given
// the sender's real one here.
class SensitivityCut : public ns3::PropagationLossModel {
 public:
  static ns3::TypeId GetTypeId() {
    static ns3::TypeId tid =
        ns3::TypeId("sanet::net::SensitivityCut").SetParent<ns3::PropagationLossModel>().SetGroupName("sanet");
    return tid;
  }
  static constexpr double kUnheardDb = 2000;  // past the channel's MaxLossDb: no reception scheduled
  void Set(ns3::Ptr<ns3::PropagationLossModel> losses, const LrWpanRadios::Links* links) {
    losses_ = std::move(losses);
    links_ = links;
  }

 private:
  double DoCalcRxPower(double tx_power_dbm, ns3::Ptr<ns3::MobilityModel> a,
                       ns3::Ptr<ns3::MobilityModel> b) const override {
    const ns3::Ptr<ns3::Node> from = a->GetObject<ns3::Node>(), to = b->GetObject<ns3::Node>();
    const LrWpanRadios::Links& l = *links_;
    if (!from || !to || from->GetId() >= l.tx_power_dbm.size()) return tx_power_dbm;
    if (l.off[from->GetId()] || to->GetId() >= l.deaf.size() || l.deaf[to->GetId()])
      return tx_power_dbm - kUnheardDb;  // a radio switched off sends nothing; one off or asleep hears nothing
    const double sent = l.tx_power_dbm[from->GetId()];
    const double arrives = losses_->CalcRxPower(sent, a, b);
    if (arrives < l.sensitivity_dbm[to->GetId()]) return tx_power_dbm - kUnheardDb;
    return tx_power_dbm + arrives - sent;
  }
  int64_t DoAssignStreams(int64_t) override { return 0; }

  ns3::Ptr<ns3::PropagationLossModel> losses_;
  const LrWpanRadios::Links* links_ = nullptr;
};

namespace {

constexpr std::uint32_t kDltIeee802154NoFcs = 230;

ns3::Mac64Address ExtendedOf(NodeId id) {
  std::uint8_t bytes[8] = {0x02, 0x5a, 0x4e, 0, 0, 0, 0, 0};
  for (int i = 0; i < 4; ++i) bytes[7 - i] = static_cast<std::uint8_t>((id + 1) >> (8 * i));
  ns3::Mac64Address out;
  out.CopyFrom(bytes);
  return out;
}

}  // namespace

LrWpanRadios::LrWpanRadios(const NetworkSpec& spec, ns3::Ptr<ObstacleLossModel> walls) : spec_(spec) {
  const ChannelLosses losses = BuildChannelLosses(spec_, walls, kLrWpanFrequencyHz, spec_.lr_wpan.rx_threshold);
  mean_ = losses.mean;
  auto cut = ns3::CreateObject<SensitivityCut>();
  cut->Set(losses.frames, &links_);
  auto channel = ns3::CreateObject<ns3::SingleModelSpectrumChannel>();
  channel->SetAttribute("MaxLossDb", ns3::DoubleValue(SensitivityCut::kUnheardDb / 2));
  channel->AddPropagationLossModel(cut);
  if (spec_.delay == DelayModel::kConstantSpeed) {
    delay_ = ns3::CreateObject<ns3::ConstantSpeedPropagationDelayModel>();
  } else {
    delay_ = ns3::CreateObject<ns3::RandomPropagationDelayModel>();
    delay_->SetAttribute(
        "Variable",
        ns3::StringValue("ns3::UniformRandomVariable[Min=0.0|Max=" + std::to_string(spec_.random_delay_max) + "]"));
  }
  channel->SetPropagationDelayModel(delay_);
  channel_ = channel;
}

LrWpanRadios::~LrWpanRadios() { ClosePcaps(); }

void LrWpanRadios::Install(NodeId id, ns3::Ptr<ns3::Node> node, double tx_power_dbm) {
  if (radios_.size() <= id) radios_.resize(id + 1), links_.Resize(id + 1);
  Radio& r = radios_[id];
  r.tx_power_dbm = tx_power_dbm;
  links_.tx_power_dbm[id] = tx_power_dbm;
  links_.sensitivity_dbm[id] = spec_.lr_wpan.rx_threshold + NoiseFigureOffsetDb(spec_, id);  // once, not per frame
  r.device = ns3::CreateObject<ns3::LrWpanNetDevice>();
  r.device->SetChannel(channel_);
  node->AddDevice(r.device);
  r.device->SetNode(node);
  r.device->GetPhy()->SetMobility(node->GetObject<ns3::MobilityModel>());
  ns3::LrWpanSpectrumValueHelper psd;
  r.device->GetPhy()->SetTxPowerSpectralDensity(psd.CreateTxPowerSpectralDensity(tx_power_dbm, kLrWpanChannel));
  const ns3::Ptr<ns3::LrWpanMac> mac = r.device->GetMac();
  mac->SetPanId(AddressBook::kPanId);
  mac->SetShortAddress(AddressBook::ShortOf(id));
  mac->SetExtendedAddress(ExtendedOf(id));
  mac->SetMacMaxFrameRetries(static_cast<std::uint8_t>(spec_.lr_wpan.max_frame_retries));
  const ns3::Ptr<ns3::LrWpanCsmaCa> csma = r.device->GetCsmaCa();
  csma->SetMacMinBE(static_cast<std::uint8_t>(spec_.lr_wpan.min_be));
  csma->SetMacMaxBE(static_cast<std::uint8_t>(spec_.lr_wpan.max_be));
  csma->SetMacMaxCSMABackoffs(static_cast<std::uint8_t>(spec_.lr_wpan.max_csma_backoffs));

  r.sixlowpan = ns3::CreateObject<ns3::SixLowPanNetDevice>();
  node->AddDevice(r.sixlowpan);
  r.sixlowpan->SetNetDevice(r.device);
  node->GetObject<ns3::Icmpv6L4Protocol>()->SetAttribute("DAD", ns3::BooleanValue(false));
  const ns3::Ptr<ns3::Ipv6> ip = node->GetObject<ns3::Ipv6>();
  r.interface = ip->AddInterface(r.sixlowpan);
  // A host's interface would send router solicitations (ns-3 3.37: five at once, its retransmission
  // timer starting from time zero), which no router here answers: as a router's, it sends none.
  ip->SetForwarding(r.interface, true);
  ip->AddAddress(r.interface, ns3::Ipv6InterfaceAddress(AddressBook::Of6(id), ns3::Ipv6Prefix(64)));
  ip->SetMetric(r.interface, 1);
  ip->SetUp(r.interface);
  Trace(id);
}

std::int64_t LrWpanRadios::AssignStreams(NodeId id, std::int64_t stream) {
  const Radio& r = radios_.at(id);
  std::int64_t used = r.device->GetCsmaCa()->AssignStreams(stream);
  used += r.device->GetPhy()->AssignStreams(stream + used);
  return used;
}

void LrWpanRadios::KnowNeighbour(NodeId from, NodeId to) {
  const Radio& r = radios_.at(from);
  const auto ip = r.device->GetNode()->GetObject<ns3::Ipv6L3Protocol>();
  const ns3::Ptr<ns3::NdiscCache> cache = ip->GetInterface(r.interface)->GetNdiscCache();
  const ns3::Ipv6Address address = AddressBook::Of6(to);
  if (cache->Lookup(address)) return;
  ns3::NdiscCache::Entry* entry = cache->Add(address);
  entry->SetMacAddress(AddressBook::Pseudo48Of(to));
  entry->MarkPermanent();
}

void LrWpanRadios::SetAsleep(NodeId id, bool asleep) {
  radios_.at(id).asleep = asleep;
  Changed(id);
}

// ns-3's lr-wpan MAC has no off state, and taking the IPv6 interface down would drop its address
// for good: a radio switched off is cut from the channel instead, so that nothing it still sends
// (its MAC's queue, retries) reaches anyone and nothing reaches it.
void LrWpanRadios::SwitchOff(NodeId id) {
  radios_.at(id).off = links_.off[id] = true;
  Changed(id);
}

void LrWpanRadios::SwitchOn(NodeId id, bool asleep) {
  Radio& r = radios_.at(id);
  r.off = links_.off[id] = false;
  r.asleep = asleep;
  Changed(id);
}

void LrWpanRadios::Changed(NodeId id) {
  const Radio& r = radios_[id];
  links_.deaf[id] = r.off || (r.asleep && r.mac_idle);
  if (r.sleep_changed) r.sleep_changed();
}

double LrWpanRadios::ReceivedPower(NodeId from, NodeId to) const {
  return mean_->CalcRxPower(links_.tx_power_dbm.at(from),
                            radios_.at(from).device->GetNode()->GetObject<ns3::MobilityModel>(),
                            radios_.at(to).device->GetNode()->GetObject<ns3::MobilityModel>());
}

// A frame sent is seen at the MAC's sniffer (every attempt: retries and acknowledgements too); one
// received whole at its promiscuous receive, before address filtering. MacTxDrop is a unicast given
// up.
void LrWpanRadios::Trace(NodeId id) {
  const ns3::Ptr<ns3::LrWpanMac> mac = radios_[id].device->GetMac();
  mac->TraceConnectWithoutContext("MacStateValue", ns3::Callback<void, ns3::LrWpanMacState, ns3::LrWpanMacState>(
                                                       [this, id](ns3::LrWpanMacState, ns3::LrWpanMacState now) {
                                                         radios_[id].mac_idle = now == ns3::MAC_IDLE;
                                                         Changed(id);
                                                       }));
  mac->TraceConnectWithoutContext("Sniffer", ns3::Callback<void, ns3::Ptr<const ns3::Packet>>(
                                                 [this, id](ns3::Ptr<const ns3::Packet> p) { Sent(id, p); }));
  mac->TraceConnectWithoutContext("MacPromiscRx", ns3::Callback<void, ns3::Ptr<const ns3::Packet>>(
                                                      [this, id](ns3::Ptr<const ns3::Packet> p) { Heard(id, p); }));
  mac->TraceConnectWithoutContext(
      "MacTxDrop", ns3::Callback<void, ns3::Ptr<const ns3::Packet>>([this, id](ns3::Ptr<const ns3::Packet> p) {
        if (mac_drop_) mac_drop_(id, p);
      }));
}

void LrWpanRadios::Sent(NodeId id, ns3::Ptr<const ns3::Packet> frame) {
  if (counts_) ++counts_->frames_sent;
  Write(id, frame);
  if (observer_) observer_(Describe(id, true, frame));
}

void LrWpanRadios::Heard(NodeId id, ns3::Ptr<const ns3::Packet> frame) {
  if (counts_) ++counts_->frames_received;
  Write(id, frame);
  const FrameEvent e = Describe(id, false, frame);
  if (e.peer) radios_[id].heard[*e.peer] = e.t;
  if (observer_) observer_(e);
}

std::vector<NodeId> LrWpanRadios::Neighbours(NodeId id) const {
  std::vector<NodeId> out;
  const double since = ns3::Simulator::Now().GetSeconds() - kNeighbourWindow;
  for (const auto& [node, when] : radios_.at(id).heard)
    if (when >= since) out.push_back(node);
  return out;
}

// What a frame is (data, broadcast or ack) and whom it is for or from, by its short addresses.
FrameEvent LrWpanRadios::Describe(NodeId id, bool sent, ns3::Ptr<const ns3::Packet> frame) const {
  FrameEvent e;
  e.t = ns3::Simulator::Now().GetSeconds();
  e.node = id;
  e.sent = sent;
  e.bytes = frame->GetSize();
  ns3::LrWpanMacHeader mac;
  frame->Copy()->RemoveHeader(mac);
  const auto node_at = [this](ns3::Mac16Address a) -> std::optional<NodeId> {
    std::uint8_t b[2];
    a.CopyTo(b);
    const std::uint32_t n = (b[0] << 8) | b[1];
    if (n == 0 || n > radios_.size() || !radios_[n - 1].device) return std::nullopt;
    return n - 1;
  };
  if (mac.IsAcknowledgment()) {
    e.kind = "ack";
    return e;
  }
  const bool to_all = mac.GetDstAddrMode() != ns3::LrWpanMacHeader::SHORTADDR || mac.GetShortDstAddr().IsBroadcast() ||
                      mac.GetShortDstAddr().IsMulticast();
  e.kind = !mac.IsData() ? "management" : to_all ? "broadcast" : "data";
  if (sent && !to_all) e.peer = node_at(mac.GetShortDstAddr());
  if (!sent && mac.GetSrcAddrMode() == ns3::LrWpanMacHeader::SHORTADDR) e.peer = node_at(mac.GetShortSrcAddr());
  return e;
}

void LrWpanRadios::OpenPcap(NodeId id, const std::string& path) {
  auto file = ns3::CreateObject<ns3::PcapFileWrapper>();
  file->Open(path, std::ios::out | std::ios::binary);
  file->Init(kDltIeee802154NoFcs);
  radios_.at(id).pcap = file;
}

// Without the trailer: ns-3 computes no FCS unless checksums are on, and a zero FCS would show
// every frame as damaged.
void LrWpanRadios::Write(NodeId id, ns3::Ptr<const ns3::Packet> frame) {
  const ns3::Ptr<ns3::PcapFileWrapper>& file = radios_[id].pcap;
  if (!file) return;
  ns3::Ptr<ns3::Packet> copy = frame->Copy();
  ns3::LrWpanMacTrailer fcs;
  copy->RemoveTrailer(fcs);
  file->Write(ns3::Simulator::Now(), copy);
}

void LrWpanRadios::ClosePcaps() {
  for (Radio& r : radios_)
    if (r.pcap) r.pcap->Close(), r.pcap = nullptr;
}

void LrWpanRadios::ObserveFrames(FrameObserver observer) { observer_ = std::move(observer); }

}  // namespace sanet::net
