#include "net/wireless_network.h"

#include <ns3/aodv-helper.h>
#include <ns3/aodv-routing-protocol.h>
#include <ns3/boolean.h>
#include <ns3/constant-position-mobility-model.h>
#include <ns3/data-rate.h>
#include <ns3/double.h>
#include <ns3/dsdv-helper.h>
#include <ns3/dsdv-routing-protocol.h>
#include <ns3/dsr-helper.h>
#include <ns3/dsr-main-helper.h>
#include <ns3/dsr-routing.h>
#include <ns3/inet-socket-address.h>
#include <ns3/inet6-socket-address.h>
#include <ns3/internet-stack-helper.h>
#include <ns3/ipv4-address-helper.h>
#include <ns3/ipv4-static-routing-helper.h>
#include <ns3/mobility-model.h>
#include <ns3/olsr-helper.h>
#include <ns3/olsr-routing-protocol.h>
#include <ns3/pointer.h>
#include <ns3/propagation-loss-model.h>
#include <ns3/simple-net-device.h>
#include <ns3/simulator.h>
#include <ns3/string.h>
#include <ns3/udp-socket-factory.h>
#include <ns3/wifi-helper.h>
#include <ns3/wifi-net-device.h>
#include <ns3/yans-wifi-channel.h>
#include <ns3/yans-wifi-helper.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "core/statistics.h"
#include "net/channel_losses.h"
#include "net/hardware_spread.h"

namespace sanet::net {
namespace {

constexpr std::uint8_t kDefaultTtl = 64;  // ns-3's Ipv4L3Protocol::DefaultTtl
constexpr std::uint32_t kDltIeee80211 = 105;

std::string RateName(double mbps) {
  char s[32];
  if (mbps == 5.5) return "5_5";
  std::snprintf(s, sizeof s, "%g", mbps);
  return s;
}

// ns-3's names of the modes (data rates) of each standard.
std::string ModeName(WifiStandard standard, double mbps) {
  switch (standard) {
    case WifiStandard::k80211b:
      return "DsssRate" + RateName(mbps) + "Mbps";
    case WifiStandard::k80211g:
      return "ErpOfdmRate" + RateName(mbps) + "Mbps";
    case WifiStandard::k80211a:
      return "OfdmRate" + RateName(mbps) + "Mbps";
  }
  return "";
}

// How ns-3 3.37's 802.11 MAC retries a unicast frame: 7 attempts (MaxSsrc), the PHY's slot and
// SIFS, an ACK timeout of SIFS, a slot and the ACK's PHY header, a contention window from 31
// slots (DSSS) or 15 (OFDM) to 1023. (network.ns3 values for these are not read.)
AbstractChannel::Settings::Retries UnicastRetries(WifiStandard standard) {
  AbstractChannel::Settings::Retries r;
  r.attempts = 7, r.cw_max = 1023;
  if (standard == WifiStandard::k80211a)
    r.slot_s = 9e-6, r.sifs_s = 16e-6, r.cw_min = 15;
  else  // 802.11b, and 802.11g with its long slot beside 802.11b stations, as ns-3 sets it
    r.slot_s = 20e-6, r.sifs_s = 10e-6, r.cw_min = standard == WifiStandard::k80211b ? 31 : 15;
  r.ack_s = PreambleSeconds(standard);  // ns-3 waits for an ACK's start: SIFS, a slot and its PHY header
  return r;
}

}  // namespace

WirelessNetwork::WirelessNetwork(const NetworkSpec& spec, const ns3::NodeContainer& nodes,
                                 std::vector<std::string> names, const std::vector<NodeRadio>& radios,
                                 std::vector<RadioObstacle> walls, std::vector<RadioObstacle> lr_wpan_walls)
    : spec_(spec),
      ns3_defaults_(spec.ns3),
      nodes_(nodes),
      book_(nodes.GetN()),
      names_(names),
      trace_(spec_, book_, std::move(names)),
      next_sequence_(nodes.GetN(), 0),
      floods_seen_(nodes.GetN()),
      broadcasts_seen_(nodes.GetN()),
      radios_(radios) {
  if (!walls.empty()) {
    walls_ = ns3::CreateObject<ObstacleLossModel>();
    walls_->SetObstacles(std::make_shared<const ObstacleCrossings>(std::move(walls)));
  }
  if (!lr_wpan_walls.empty()) {
    lr_wpan_walls_ = ns3::CreateObject<ObstacleLossModel>();
    lr_wpan_walls_->SetObstacles(std::make_shared<const ObstacleCrossings>(std::move(lr_wpan_walls)));
  }
  ConfigureRadios();
  // One node at a time: a node may transmit with its own power.
  wifi_.resize(nodes_.GetN());
  ip4_.resize(nodes_.GetN());
  for (NodeId id = 0; id < nodes_.GetN(); ++id)
    if (radios.at(id).RadiosIn(spec_).wifi)
      devices_.Add(abstract_ ? InstallAbstract(id) : InstallRadio(id, radios.at(id)));
  InstallInternet();
  for (NodeId id = 0; id < nodes_.GetN(); ++id)
    if (radios.at(id).RadiosIn(spec_).lr_wpan) InstallLrWpan(id);
  for (NodeId id = 0; id < nodes_.GetN(); ++id) OpenSocket(id);
  jitter_ = ns3::CreateObject<ns3::UniformRandomVariable>();
  jitter_->SetAttribute("Min", ns3::DoubleValue(0));
  jitter_->SetAttribute("Max", ns3::DoubleValue(0.01));
  AssignStreams();
  for (NodeId id = 0; id < nodes_.GetN(); ++id) trace_.Attach(id, nodes_.Get(id));
  for (NodeId id = 0; id < nodes_.GetN(); ++id)
    if (HasLrWpan(id)) trace_.Attach6(id, nodes_.Get(id));
  for (NodeId id = 0; id < nodes_.GetN(); ++id) StartDutyCycle(id);
  if (spec_.flow_monitor) {
    flow_helper_ = std::make_unique<ns3::FlowMonitorHelper>();
    flow_monitor_ = flow_helper_->Install(nodes_);
  }
}

WirelessNetwork::~WirelessNetwork() {
  for (const auto* sockets : {&sockets_, &sockets6_})
    for (auto& socket : *sockets)
      if (socket) socket->SetRecvCallback(ns3::MakeNullCallback<void, ns3::Ptr<ns3::Socket>>());
}

// The helpers every node's radio is installed with: standard, rates, channel, PHY and MAC.
void WirelessNetwork::ConfigureRadios() {
  nominal_noise_figure_ = WifiPhyDefault("RxNoiseFigure");
  wifi_helper_.SetStandard(spec_.standard == WifiStandard::k80211b   ? ns3::WIFI_STANDARD_80211b
                           : spec_.standard == WifiStandard::k80211g ? ns3::WIFI_STANDARD_80211g
                                                                     : ns3::WIFI_STANDARD_80211a);
  const std::string data_mode = ModeName(spec_.standard, spec_.data_rate);
  const std::string control_mode = ModeName(spec_.standard, DataRates(spec_.standard).front());
  // Broadcasts (hence AODV's requests and floods) go at the standard's lowest rate, named here
  // because ns-3's own default for them is the first basic rate (1 Mbps DSSS even for 802.11g).
  wifi_helper_.SetRemoteStationManager("ns3::ConstantRateWifiManager", "DataMode", ns3::StringValue(data_mode),
                                       "ControlMode", ns3::StringValue(control_mode), "NonUnicastMode",
                                       ns3::StringValue(spec_.broadcast_at_data_rate ? data_mode : control_mode));

  ns3::YansWifiChannelHelper channel;
  if (spec_.delay == DelayModel::kConstantSpeed) {
    channel.SetPropagationDelay("ns3::ConstantSpeedPropagationDelayModel");
  } else {
    // ns-3's default draws up to a whole second per frame, longer than any acknowledgement
    // timeout: the scenario bounds it.
    channel.SetPropagationDelay(
        "ns3::RandomPropagationDelayModel", "Variable",
        ns3::StringValue("ns3::UniformRandomVariable[Min=0.0|Max=" + std::to_string(spec_.random_delay_max) + "]"));
  }
  ns3::Ptr<ns3::YansWifiChannel> yans = channel.Create();
  const ChannelLosses losses = BuildChannelLosses(spec_, walls_);
  mean_loss_ = losses.mean;
  shadowing_ = losses.shadowing;
  yans->SetPropagationLossModel(losses.frames);
  if (spec_.radio_model == RadioModel::kAbstract) ConfigureAbstract(losses);
  if (spec_.channel == ChannelModel::kIndexed) {
    indexed_ = ns3::CreateObject<IndexedWifiChannel>();
    ns3::PointerValue delay;
    yans->GetAttribute("PropagationDelayModel", delay);
    indexed_->SetPropagationLossModel(losses.frames);
    indexed_->SetRangeLossModel(losses.range);
    indexed_->SetRangeMargin(losses.range_margin_db);
    indexed_->SetPropagationDelayModel(delay.Get<ns3::PropagationDelayModel>());
    indexed_->SetFloor(spec_.ChannelFloor());
    phy_.UseIndexedPhy();
    yans = indexed_;
  }
  phy_.SetChannel(yans);
  phy_.SetPreambleDetectionModel("ns3::ThresholdPreambleDetectionModel", "MinimumRssi",
                                 ns3::DoubleValue(spec_.rx_threshold));
  mac_.SetType("ns3::AdhocWifiMac");
}

// Each node's own transmit power (and, with a hardware spread, its own noise figure) is set on the
// helper just before its radio is made.
ns3::NetDeviceContainer WirelessNetwork::InstallRadio(NodeId id, const NodeRadio& radio) {
  const ns3::Ptr<ns3::Node> node = nodes_.Get(id);
  const double power = TxPower(id, radio);
  if (walls_) walls_->SetAntennaHeight(node->GetId(), radio.antenna_height);
  phy_.Set("TxPowerStart", ns3::DoubleValue(power));
  phy_.Set("TxPowerEnd", ns3::DoubleValue(power));
  if (spec_.spread.noise_figure_db > 0)
    phy_.Set("RxNoiseFigure", ns3::DoubleValue(std::max(0.0, nominal_noise_figure_ + NoiseFigureOffsetDb(spec_, id))));
  ns3::NetDeviceContainer device = wifi_helper_.Install(phy_, mac_, node);
  if (wifi_.size() <= id) wifi_.resize(id + 1), ip4_.resize(id + 1);
  wifi_[id] = ns3::DynamicCast<ns3::WifiNetDevice>(device.Get(0));
  ip4_[id] = wifi_[id];
  CountFrames(wifi_[id]->GetPhy());
  return device;
}

// The abstract radio's device: ns-3's SimpleNetDevice, its frames serialized at the data rate,
// with an address made from the node's id (ns-3's Allocate counts across the process's runs).
ns3::NetDeviceContainer WirelessNetwork::InstallAbstract(NodeId id) {
  auto device = ns3::CreateObject<ns3::SimpleNetDevice>();
  const std::uint32_t n = id + 1;
  const std::uint8_t mac[6] = {0x02,
                               0x5a,
                               0,
                               static_cast<std::uint8_t>(n >> 16),
                               static_cast<std::uint8_t>(n >> 8),
                               static_cast<std::uint8_t>(n)};
  ns3::Mac48Address address;
  address.CopyFrom(mac);
  device->SetAddress(address);
  device->SetAttribute("DataRate",
                       ns3::DataRateValue(ns3::DataRate(static_cast<std::uint64_t>(spec_.data_rate * 1e6))));
  nodes_.Get(id)->AddDevice(device);
  device->SetChannel(abstract_);
  if (ip4_.size() <= id) wifi_.resize(id + 1), ip4_.resize(id + 1);
  ip4_[id] = device;
  return ns3::NetDeviceContainer(device);
}

// The abstract channel draws from the calibration at the links' mean power (walls, shadowing),
// asking only the radios within the distance where the path loss, lifted by shadowing's most,
// falls to the weakest power the calibration delivers at.
void WirelessNetwork::ConfigureAbstract(const ChannelLosses& losses) {
  if (!spec_.calibration) throw std::invalid_argument("the abstract radio needs a calibration");
  AbstractChannel::Settings s;
  s.calibration = *spec_.calibration;
  s.mean_loss = losses.mean;
  s.tx_power_dbm = [this](std::uint32_t node) { return TxPower(node, radios_.at(node)); };
  s.seed = spec_.seed;
  s.preamble_s = PreambleSeconds(spec_.standard);
  s.data_rate_bps = spec_.data_rate * 1e6, s.broadcast_rate_bps = DataRates(spec_.standard).front() * 1e6;
  s.unicast = UnicastRetries(spec_.standard);
  const double lowest = s.calibration.LowestHeardDbm() - losses.range_margin_db;
  double strongest = spec_.tx_power;
  for (NodeId id = 0; id < radios_.size(); ++id) strongest = std::max(strongest, TxPower(id, radios_[id]));
  auto here = ns3::CreateObject<ns3::ConstantPositionMobilityModel>();
  auto there = ns3::CreateObject<ns3::ConstantPositionMobilityModel>();
  double far = 1;
  for (; far < 1e6; far *= 2) {
    there->SetPosition({far, 0, 0});
    if (losses.range->CalcRxPower(strongest, here, there) < lowest) break;
  }
  s.range_m = far;
  abstract_ = ns3::CreateObject<AbstractChannel>();
  abstract_->Configure(std::move(s));
  abstract_->ObserveGivingUp([this](std::uint32_t node, ns3::Ptr<const ns3::Packet> p) {
    trace_.MacGaveUp(node, p->GetSize() + AbstractChannel::kMacOverhead);
  });
}

// After the IP stack: the radio, 6LoWPAN and the IPv6 interface, with the node's own power.
void WirelessNetwork::InstallLrWpan(NodeId id) {
  if (!lr_wpan_) {
    lr_wpan_ = std::make_unique<LrWpanRadios>(spec_, lr_wpan_walls_);
    lr_wpan_->CountFrames(&frame_counts_);
    lr_wpan_->OnMacDrop([this](NodeId node, ns3::Ptr<const ns3::Packet> p) { trace_.MacGaveUp(node, p->GetSize()); });
    if (frame_observer_) lr_wpan_->ObserveFrames(frame_observer_);  // a spawned robot's radio is the first
  }
  if (lr_wpan_walls_) lr_wpan_walls_->SetAntennaHeight(nodes_.Get(id)->GetId(), radios_.at(id).antenna_height);
  const double power = radios_.at(id).lr_wpan_tx_power.value_or(spec_.lr_wpan.tx_power) + TxPowerOffsetDb(spec_, id);
  lr_wpan_->Install(id, nodes_.Get(id), power);
}

// Frames sent and frames received whole, over all radios: how well the channel delivers,
// whichever channel model carries them.
void WirelessNetwork::CountFrames(ns3::Ptr<ns3::WifiPhy> phy) {
  phy->TraceConnectWithoutContext("PhyTxBegin",
                                  ns3::Callback<void, ns3::Ptr<const ns3::Packet>, double>(
                                      [this](ns3::Ptr<const ns3::Packet>, double) { ++frame_counts_.frames_sent; }));
  phy->TraceConnectWithoutContext("PhyRxEnd",
                                  ns3::Callback<void, ns3::Ptr<const ns3::Packet>>(
                                      [this](ns3::Ptr<const ns3::Packet>) { ++frame_counts_.frames_received; }));
}

// ns-3 numbers random streams from a process-wide counter as objects are created, so a second
// run in one process would draw other numbers: give every random consumer a fixed stream.
void WirelessNetwork::AssignStreams() {
  std::int64_t stream = 0;
  if (devices_.GetN() > 0) {
    if (!abstract_) {
      stream += ns3::WifiHelper().AssignStreams(devices_, stream);
      stream += ns3::YansWifiChannelHelper().AssignStreams(
          ns3::DynamicCast<ns3::YansWifiChannel>(devices_.Get(0)->GetChannel()), stream);
    }
  }
  stream += ns3::InternetStackHelper().AssignStreams(nodes_, stream);
  for (NodeId id = 0; id < nodes_.GetN(); ++id) stream += AssignRoutingStreams(nodes_.Get(id), stream);
  jitter_->SetStream(stream);
  next_stream_ = stream + 1;
  // After every stream an 802.11 run had before 802.15.4 existed: those runs draw as they did.
  for (NodeId id = 0; id < nodes_.GetN(); ++id)
    if (HasLrWpan(id)) next_stream_ += lr_wpan_->AssignStreams(id, next_stream_);
  if (lr_wpan_) next_stream_ += lr_wpan_->AssignChannelStreams(next_stream_);
}

std::int64_t WirelessNetwork::AssignRoutingStreams(ns3::Ptr<ns3::Node> node, std::int64_t stream) {
  auto routing = node->GetObject<ns3::Ipv4>()->GetRoutingProtocol();
  if (auto aodv = ns3::DynamicCast<ns3::aodv::RoutingProtocol>(routing)) return aodv->AssignStreams(stream);
  if (auto olsr = ns3::DynamicCast<ns3::olsr::RoutingProtocol>(routing)) return olsr->AssignStreams(stream);
  if (auto dsdv = ns3::DynamicCast<ns3::dsdv::RoutingProtocol>(routing)) return dsdv->AssignStreams(stream);
  if (auto dsr = node->GetObject<ns3::dsr::DsrRouting>()) return dsr->AssignStreams(stream);
  return 0;
}

// Installed exactly as the first nodes were; its random streams follow all of theirs, so a run
// without spawned robots draws the same numbers as before spawning existed.
void WirelessNetwork::AddNode(ns3::Ptr<ns3::Node> node, const std::string& name, const NodeRadio& radio) {
  const NodeId id = nodes_.GetN();
  nodes_.Add(node);
  book_.Add();
  names_.push_back(name);
  trace_.AddNode(name);
  next_sequence_.push_back(0);
  floods_seen_.emplace_back();
  broadcasts_seen_.emplace_back();
  radios_.push_back(radio);
  wifi_.resize(id + 1);
  ip4_.resize(id + 1);
  const Radios kinds = radio.RadiosIn(spec_);
  ns3::NetDeviceContainer device;
  if (kinds.wifi) device = abstract_ ? InstallAbstract(id) : InstallRadio(id, radio);
  devices_.Add(device);
  internet_.Install(node);
  if (spec_.routing == Routing::kDsr) {
    ns3::DsrHelper dsr;
    ns3::DsrMainHelper().Install(dsr, ns3::NodeContainer(node));
  }
  if (kinds.wifi) {
    auto ip = node->GetObject<ns3::Ipv4>();
    const std::int32_t interface = ip->AddInterface(device.Get(0));
    ip->AddAddress(interface, ns3::Ipv4InterfaceAddress(book_.Of(id), ns3::Ipv4Mask(AddressBook::kMask)));
    ip->SetMetric(interface, 1);
    ip->SetUp(interface);
  }
  if (kinds.lr_wpan) InstallLrWpan(id);
  OpenSocket(id);
  if (kinds.wifi && !abstract_) next_stream_ += wifi_helper_.AssignStreams(device, next_stream_);
  next_stream_ += ns3::InternetStackHelper().AssignStreams(ns3::NodeContainer(node), next_stream_);
  next_stream_ += AssignRoutingStreams(node, next_stream_);
  if (kinds.lr_wpan) next_stream_ += lr_wpan_->AssignStreams(id, next_stream_);
  trace_.Attach(id, node);
  if (kinds.lr_wpan) trace_.Attach6(id, node);
  StartDutyCycle(id);
  if (flow_monitor_) flow_helper_->Install(node);
  if (!pcap_dir_.empty()) OpenPcap(id);
  if (frames_ && HasWifiPhy(id)) frames_->Attach(id, wifi_[id]);
}

void WirelessNetwork::ObserveFrames(FrameObserver observer) {
  frame_observer_ = observer;
  if (lr_wpan_) lr_wpan_->ObserveFrames(observer);
  if (abstract_) abstract_->ObserveFrames(observer);
  frames_ = std::make_unique<FrameTrace>(std::move(observer));
  for (NodeId id = 0; id < nodes_.GetN(); ++id)
    if (HasWifiPhy(id)) frames_->Attach(id, wifi_[id]);
}

void WirelessNetwork::InstallInternet() {
  ns3::InternetStackHelper& internet = internet_;
  ns3::AodvHelper aodv;
  ns3::OlsrHelper olsr;
  ns3::DsdvHelper dsdv;
  ns3::Ipv4StaticRoutingHelper one_hop;  // the subnet route: neighbours only
  switch (spec_.routing) {
    case Routing::kAodv:
      aodv.Set("EnableHello", ns3::BooleanValue(spec_.aodv_hello));
      internet.SetRoutingHelper(aodv);
      break;
    case Routing::kOlsr:
      internet.SetRoutingHelper(olsr);
      break;
    case Routing::kDsdv:
      internet.SetRoutingHelper(dsdv);
      break;
    case Routing::kNone:
    case Routing::kDsr:
      internet.SetRoutingHelper(one_hop);
      break;
  }
  internet.Install(nodes_);
  if (spec_.routing == Routing::kDsr) {
    ns3::DsrHelper dsr;
    ns3::DsrMainHelper dsr_main;
    dsr_main.Install(dsr, nodes_);
  }
  if (devices_.GetN() == nodes_.GetN()) {  // every node on 802.11: addresses in node order
    ns3::Ipv4AddressHelper addresses;
    addresses.SetBase(AddressBook::kNetwork, AddressBook::kMask);
    addresses.Assign(devices_);
    return;
  }
  for (NodeId id = 0; id < nodes_.GetN(); ++id)
    if (HasWifi(id)) AssignAddress(id);
}

// The node's own address, whichever nodes before it have an 802.11 radio.
void WirelessNetwork::AssignAddress(NodeId id) {
  ns3::Ipv4AddressHelper addresses;
  addresses.SetBase(AddressBook::kNetwork, AddressBook::kMask, ns3::Ipv4Address(static_cast<std::uint32_t>(id + 1)));
  addresses.Assign(ns3::NetDeviceContainer(ip4_[id]));
}

// A UDP socket for controller messages on each IP the node speaks: IPv4 over its 802.11 radio,
// IPv6 over its 802.15.4 radio (bound to that interface, where link-local multicast goes out).
void WirelessNetwork::OpenSocket(NodeId id) {
  const auto receive =
      ns3::Callback<void, ns3::Ptr<ns3::Socket>>([this, id](ns3::Ptr<ns3::Socket> s) { Receive(id, s); });
  ns3::Ptr<ns3::Socket> socket, socket6;
  if (HasWifi(id)) {
    socket = ns3::Socket::CreateSocket(nodes_.Get(id), ns3::UdpSocketFactory::GetTypeId());
    socket->Bind(ns3::InetSocketAddress(ns3::Ipv4Address::GetAny(), spec_.port));
    socket->SetAllowBroadcast(true);
    socket->SetIpRecvTtl(true);
    socket->SetRecvCallback(receive);
  }
  if (HasLrWpan(id)) {
    socket6 = ns3::Socket::CreateSocket(nodes_.Get(id), ns3::UdpSocketFactory::GetTypeId());
    socket6->Bind(ns3::Inet6SocketAddress(ns3::Ipv6Address::GetAny(), spec_.port));
    socket6->BindToNetDevice(lr_wpan_->Interface(id));
    socket6->SetIpv6RecvHopLimit(true);
    socket6->SetRecvCallback(receive);
  }
  sockets_.push_back(socket);
  sockets6_.push_back(socket6);
  views_.push_back(std::make_unique<RoutingView>(
      spec_.routing, nodes_.Get(id), book_,
      [this, id](NodeId to) {
        if (to >= nodes_.GetN() || to == id || !HasWifi(id) || !HasWifi(to)) return;
        if (spec_.routing == Routing::kAodv && !views_[id]->HasValidRoute(to))
          trace_.RouteNeeded(id, to, ns3::Simulator::Now().GetSeconds());
        Transmit(id, ns3::InetSocketAddress(book_.Of(to), spec_.port), NewHeader(id, MessageHeader::kRouteProbe, to),
                 {});
      },
      HasLrWpan(id) ? std::function<std::vector<NodeId>()>([this, id] { return lr_wpan_->Neighbours(id); })
                    : std::function<std::vector<NodeId>()>()));
}

MessageHeader WirelessNetwork::NewHeader(NodeId from, MessageHeader::Kind kind, NodeId destination) {
  MessageHeader h;
  h.kind = kind;
  h.origin = from;
  h.destination = destination;
  h.sequence = next_sequence_[from]++;
  h.time_sent_ns = ns3::Simulator::Now().GetNanoSeconds();
  h.ttl = static_cast<std::uint8_t>(spec_.flood_ttl);
  return h;
}

void WirelessNetwork::Transmit(NodeId from, const ns3::Address& to, const MessageHeader& header, const Bytes& payload) {
  auto packet = ns3::Create<ns3::Packet>(payload.data(), payload.size());
  packet->AddHeader(header);
  (ns3::Inet6SocketAddress::IsMatchingType(to) ? sockets6_ : sockets_)[from]->SendTo(packet, 0, to);
}

void WirelessNetwork::TransmitToAll(NodeId from, const MessageHeader& header, const Bytes& payload) {
  if (HasWifi(from))
    Transmit(from, ns3::InetSocketAddress(ns3::Ipv4Address::GetBroadcast(), spec_.port), header, payload);
  if (HasLrWpan(from))
    Transmit(from, ns3::Inet6SocketAddress(ns3::Ipv6Address::GetAllNodesMulticast(), spec_.port), header, payload);
}

// Over 802.11 when both ends have it (routed by the routing protocol), else over 802.15.4 (one
// hop), else nowhere (docs/network.md#two-radios).
void WirelessNetwork::Send(NodeId from, NodeId to, const Bytes& payload) {
  if (to >= nodes_.GetN() || to == from) return;
  trace_.MessageSent(from);
  if (HasWifi(from) && HasWifi(to)) {
    if (spec_.routing == Routing::kAodv && !views_[from]->HasValidRoute(to))
      trace_.RouteNeeded(from, to, ns3::Simulator::Now().GetSeconds());
    return Transmit(from, ns3::InetSocketAddress(book_.Of(to), spec_.port),
                    NewHeader(from, MessageHeader::kUnicast, to), payload);
  }
  if (HasLrWpan(from) && HasLrWpan(to)) {
    lr_wpan_->KnowNeighbour(from, to);
    return Transmit(from, ns3::Inet6SocketAddress(AddressBook::Of6(to), spec_.port),
                    NewHeader(from, MessageHeader::kUnicast, to), payload);
  }
  trace_.Unreachable(from, to, payload.size());
}

// With `broadcast_jitter`, the datagram waits a random time first (from the stream that also
// jitters flood relays), so that nodes whose control steps coincide do not all transmit at once.
void WirelessNetwork::Broadcast(NodeId from, const Bytes& payload) {
  trace_.MessageSent(from);
  const MessageHeader header = NewHeader(from, MessageHeader::kBroadcast, kBroadcast);
  if (spec_.broadcast_jitter <= 0) return TransmitToAll(from, header, payload);
  ns3::Simulator::Schedule(ns3::Seconds(jitter_->GetValue(0, spec_.broadcast_jitter)),
                           [this, from, header, payload] { TransmitToAll(from, header, payload); });
}

void WirelessNetwork::Flood(NodeId from, const Bytes& payload) {
  trace_.MessageSent(from);
  MessageHeader h = NewHeader(from, MessageHeader::kFlood, kBroadcast);
  floods_seen_[from].insert({h.origin, h.sequence});
  TransmitToAll(from, h, payload);
}

void WirelessNetwork::Receive(NodeId node, ns3::Ptr<ns3::Socket> socket) {
  ns3::Address from;
  while (ns3::Ptr<ns3::Packet> packet = socket->RecvFrom(from)) {
    ns3::SocketIpTtlTag ttl;
    ns3::SocketIpv6HopLimitTag hop_limit;
    std::optional<int> hops_left;
    if (packet->RemovePacketTag(ttl)) hops_left = ttl.GetTtl();
    if (packet->RemovePacketTag(hop_limit)) hops_left = hop_limit.GetHopLimit();
    MessageHeader h;
    if (packet->RemoveHeader(h) == 0 || h.origin >= nodes_.GetN()) continue;  // not ours
    if (h.kind == MessageHeader::kRouteProbe || h.origin == node) continue;
    Message m;
    m.from = h.origin;
    m.time_sent = h.time_sent_ns * 1e-9;
    m.time_received = ns3::Simulator::Now().GetSeconds();
    m.payload.resize(packet->GetSize());
    packet->CopyData(m.payload.data(), m.payload.size());
    switch (h.kind) {
      case MessageHeader::kUnicast:
        if (h.destination != node) continue;
        m.delivery = Delivery::kUnicast;
        m.to = node;
        if (hops_left) m.hops = kDefaultTtl - *hops_left + 1;
        break;
      case MessageHeader::kBroadcast:
        if (SeenTwice(node, h)) continue;
        m.delivery = Delivery::kBroadcast;
        m.hops = 1;
        break;
      case MessageHeader::kFlood: {
        if (!floods_seen_[node].insert({h.origin, h.sequence}).second) continue;  // seen already
        m.delivery = Delivery::kFlood;
        m.hops = h.hops + 1;
        if (h.ttl > 1) {
          // Relay once, after a short random wait so that neighbours do not all collide.
          MessageHeader relay = h;
          relay.hops = static_cast<std::uint8_t>(h.hops + 1);
          relay.ttl = static_cast<std::uint8_t>(h.ttl - 1);
          ns3::Simulator::Schedule(ns3::Seconds(jitter_->GetValue()),
                                   [this, node, relay, payload = m.payload] { TransmitToAll(node, relay, payload); });
        }
        break;
      }
      default:
        continue;
    }
    trace_.MessageReceived(node);
    if (receiver_) receiver_(node, m);
  }
}

// Only when both ends have two radios can one broadcast arrive twice.
bool WirelessNetwork::SeenTwice(NodeId node, const MessageHeader& h) {
  if (!HasWifi(h.origin) || !HasLrWpan(h.origin) || !HasWifi(node) || !HasLrWpan(node)) return false;
  return !broadcasts_seen_[node].insert({h.origin, h.sequence}).second;
}

void WirelessNetwork::JoinTap(NodeId id, int fd, const std::string& tap_mac) {
  if (!HasWifi(id))
    throw std::invalid_argument("node " + names_.at(id) + " has no 802.11 radio: taps join 802.11 radios only");
  TapPort::Network network;
  network.kept_udp_ports = {spec_.port};
  if (spec_.routing == Routing::kAodv) network.kept_udp_ports.insert(kAodvPort);
  if (spec_.routing == Routing::kOlsr) network.kept_udp_ports.insert(kOlsrPort);
  if (spec_.routing == Routing::kDsdv) network.kept_udp_ports.insert(kDsdvPort);
  network.node_at = [this](ns3::Ipv4Address a) { return book_.Find(a); };
  // A real packet counts as the node's own: sent, and the start of an AODV discovery if it needs one.
  network.entered = [this](NodeId from, const ns3::Ipv4Header& ip, ns3::Ptr<const ns3::Packet> packet) {
    trace_.ExternalSent(from, ip, packet);
    const auto to = book_.Find(ip.GetDestination());
    if (spec_.routing == Routing::kAodv && to && *to != from && !views_[from]->HasValidRoute(*to))
      trace_.RouteNeeded(from, *to, ns3::Simulator::Now().GetSeconds());
  };
  taps_.push_back(std::make_unique<TapPort>(nodes_.Get(id), id, fd, ns3::Mac48Address(tap_mac.c_str()),
                                            std::move(network), tap_ledger_));
}

double WirelessNetwork::TxPower(NodeId id, const NodeRadio& radio) const {
  return radio.tx_power.value_or(spec_.tx_power) + TxPowerOffsetDb(spec_, id);
}

double WirelessNetwork::ReceivedPower(NodeId from, NodeId to) const {
  if (!SharesWifi(from, to))
    return HasLrWpan(from) && HasLrWpan(to) ? lr_wpan_->ReceivedPower(from, to)
                                            : -std::numeric_limits<double>::infinity();
  return mean_loss_->CalcRxPower(TxPower(from, radios_.at(from)), nodes_.Get(from)->GetObject<ns3::MobilityModel>(),
                                 nodes_.Get(to)->GetObject<ns3::MobilityModel>());
}

// ns-3 3.37 cannot switch a sleeping PHY off (WifiPhyStateHelper::SwitchToOff aborts the process
// on any state but idle, busy, transmitting or receiving): it wakes first, in the same instant.
void WirelessNetwork::SwitchOff(NodeId node) {
  if (HasLrWpan(node)) lr_wpan_->SwitchOff(node);
  if (abstract_ && HasWifi(node)) abstract_->SetOff(node, true);
  if (!HasWifiPhy(node)) return;
  ns3::Ptr<ns3::WifiPhy> phy = Phy(node);
  if (phy->IsStateSleep()) phy->ResumeFromSleep();
  phy->SetOffMode();
}

bool WirelessNetwork::IsOff(NodeId node) const {
  if (HasWifiPhy(node)) return Phy(node)->IsStateOff();
  if (abstract_ && HasWifi(node)) return abstract_->IsOff(node);
  return HasLrWpan(node) && lr_wpan_->IsOff(node);
}

// Awake: a radio put to sleep before it went off wakes with the node.
void WirelessNetwork::SwitchOn(NodeId node) {
  if (!IsOff(node)) return;
  if (node < sleep_wanted_.size()) sleep_wanted_[node] = false;
  if (HasWifiPhy(node)) Phy(node)->ResumeFromOff();
  if (abstract_ && HasWifi(node)) abstract_->SetOff(node, false);
  if (HasLrWpan(node)) lr_wpan_->SwitchOn(node, false);
  if (node < cycle_asleep_.size()) ApplySleep(node);  // back in its duty cycle
}

// The state asked for is kept, and the PHY brought to it only while it is neither sending nor
// receiving: ns-3's own SetSleepMode would otherwise defer itself to the end of the frame and
// could put to sleep a radio woken in the meantime (or one switched off).
bool WirelessNetwork::SetSleep(NodeId node, bool asleep) {
  if (IsOff(node) || (!HasWifiPhy(node) && !HasLrWpan(node))) return false;
  if (sleep_wanted_.size() <= node) sleep_wanted_.resize(node + 1, false);
  sleep_wanted_[node] = asleep;
  ApplySleep(node);
  return true;
}

// A radio with a duty cycle sleeps outside its awake windows, and also inside them while its
// controller asks (SetSleep): either may put it to sleep. Each change of the cycle is an event.
void WirelessNetwork::StartDutyCycle(NodeId node) {
  std::optional<DutyCycle>& cycle = radios_.at(node).duty_cycle;
  if (!cycle) return;
  cycle->phase = PhaseOf(*cycle, spec_.seed, node);
  cycle->random_phase = false;
  if (cycle_asleep_.size() <= node) cycle_asleep_.resize(node + 1, false);
  if (sleep_wanted_.size() <= node) sleep_wanted_.resize(node + 1, false);
  // As an event: the energy model, attached after the radios, then sees the PHY's first sleep.
  ns3::Simulator::ScheduleNow(&WirelessNetwork::CycleStep, this, node);
}

void WirelessNetwork::CycleStep(NodeId node) {
  // ns-3 keeps whole nanoseconds: a change less than one away counts as come, and the next one is
  // at least one away, or a phase drawn from the seed would schedule this again at the same instant.
  const ns3::Time now = ns3::Simulator::Now();
  const CycleState state = CycleAt(*radios_.at(node).duty_cycle, now.GetSeconds() + 1e-9);
  cycle_asleep_[node] = state.asleep;
  ApplySleep(node);
  const ns3::Time wait = std::max(ns3::Seconds(state.next_change) - now, ns3::NanoSeconds(1));
  ns3::Simulator::Schedule(wait, &WirelessNetwork::CycleStep, this, node);
}

ns3::Ptr<ns3::WifiPhy> WirelessNetwork::Phy(NodeId node) const { return wifi_.at(node)->GetPhy(); }

void WirelessNetwork::ApplySleep(NodeId node) {
  const bool wanted = sleep_wanted_[node] || (node < cycle_asleep_.size() && cycle_asleep_[node]);
  if (HasLrWpan(node)) lr_wpan_->SetAsleep(node, wanted);
  if (!HasWifiPhy(node)) return;  // the abstract radio does not sleep
  ns3::Ptr<ns3::WifiPhy> phy = Phy(node);
  if (phy->IsStateOff() || wanted == phy->IsStateSleep()) return;
  if (!wanted) return phy->ResumeFromSleep();
  if (phy->IsStateTx() || phy->IsStateRx() || phy->IsStateSwitching()) {  // after this frame, if still wanted
    ns3::Simulator::Schedule(phy->GetDelayUntilIdle(), &WirelessNetwork::ApplySleep, this, node);
    return;
  }
  phy->SetSleepMode();
}

void WirelessNetwork::Open(trace::ResultsFolder& folder) {
  trace_.Open(folder);
  if (!folder.writes()) return;
  if (spec_.pcap) {
    pcap_dir_ = folder.TempFolder("pcap");
    for (NodeId id = 0; id < nodes_.GetN(); ++id) OpenPcap(id);
  }
  if (flow_monitor_) flowmon_path_ = folder.TempFile("flowmon.xml");
}

// One file per node with every 802.11 frame its radio sent or received, in a temporary folder
// that the results folder moves into place when the run ends.
void WirelessNetwork::OpenPcap(NodeId id) {
  if (HasLrWpan(id)) lr_wpan_->OpenPcap(id, pcap_dir_ + "/" + names_[id] + "-802.15.4.pcap");
  if (pcap_.size() <= id) pcap_.resize(id + 1);
  if (!HasWifiPhy(id)) return;
  auto file = ns3::CreateObject<ns3::PcapFileWrapper>();
  file->Open(pcap_dir_ + "/" + names_[id] + ".pcap", std::ios::out | std::ios::binary);
  file->Init(kDltIeee80211);
  pcap_[id] = file;
  auto phy = Phy(id);
  phy->TraceConnectWithoutContext(
      "MonitorSnifferTx",
      ns3::Callback<void, ns3::Ptr<const ns3::Packet>, uint16_t, ns3::WifiTxVector, ns3::MpduInfo, uint16_t>(
          [this, id](ns3::Ptr<const ns3::Packet> p, uint16_t, ns3::WifiTxVector, ns3::MpduInfo, uint16_t) {
            if (id < pcap_.size() && pcap_[id]) pcap_[id]->Write(ns3::Simulator::Now(), p);
          }));
  phy->TraceConnectWithoutContext(
      "MonitorSnifferRx",
      ns3::Callback<void, ns3::Ptr<const ns3::Packet>, uint16_t, ns3::WifiTxVector, ns3::MpduInfo, ns3::SignalNoiseDbm,
                    uint16_t>([this, id](ns3::Ptr<const ns3::Packet> p, uint16_t, ns3::WifiTxVector, ns3::MpduInfo,
                                         ns3::SignalNoiseDbm, uint16_t) {
        if (id < pcap_.size() && pcap_[id]) pcap_[id]->Write(ns3::Simulator::Now(), p);
      }));
}

void WirelessNetwork::Close() {
  for (auto& file : pcap_)
    if (file) file->Close();
  pcap_.clear();
  if (lr_wpan_) lr_wpan_->ClosePcaps();
  pcap_dir_.clear();
  if (flow_monitor_ && !flowmon_path_.empty()) {
    flow_monitor_->CheckForLostPackets();
    flow_monitor_->SerializeToXmlFile(flowmon_path_, true, true);
  }
}

void WirelessNetwork::Moved(const std::vector<NodeId>& nodes) {
  if (indexed_)
    for (NodeId id : nodes) indexed_->Moved(id);
  if (abstract_)
    for (NodeId id : nodes)
      if (HasWifi(id)) abstract_->Moved(id);
}

std::optional<NetworkTraces> WirelessNetwork::Traces() const {
  NetworkTraces t;
  t.radio = !spec_.wifi_in_use ? kLrWpanName
            : lr_wpan_         ? std::string(StandardName(spec_.standard)) + "+" + kLrWpanName
                               : StandardName(spec_.standard);
  t.routing = RoutingName(spec_.routing);
  t.data_rate_mbps = spec_.wifi_in_use ? spec_.data_rate : kLrWpanRateMbps;
  t.tx_power_dbm = spec_.wifi_in_use ? spec_.tx_power : spec_.lr_wpan.tx_power;
  t.counts = trace_.counts();
  t.discoveries = trace_.discoveries();
  t.packet_logs = spec_.packet_log;
  t.taps = tap_ledger_;
  t.channel = frame_counts_;
  t.channel.model = abstract_ ? "abstract" : spec_.wifi_in_use ? ChannelName(spec_.channel) : "spectrum";
  if (abstract_) {
    t.channel.calibration = spec_.calibration_source;
    t.channel.frames_sent += abstract_->counters().frames;
    t.channel.frames_received += abstract_->counters().delivered;
  }
  if (walls_) {
    t.channel.walls = walls_->walls();
    t.channel.wall_losses = walls_->counters().asked;
    t.channel.wall_walks = walls_->counters().walked;
  }
  if (shadowing_) {
    t.channel.shadowing = true;
    t.channel.shadowing_asked = shadowing_->counters().asked;
    t.channel.shadowing_computed = shadowing_->counters().computed;
  }
  if (indexed_ && spec_.wifi_in_use && !abstract_) {
    t.channel.floor_dbm = spec_.ChannelFloor();
    t.channel.candidates = indexed_->counters().candidates;
    t.channel.handed = indexed_->counters().handed;
  }
  return t;
}

}  // namespace sanet::net
