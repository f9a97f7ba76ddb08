// The simulated wireless network: ns-3 802.11 ad hoc radios on one channel with the scenario's
// propagation models, an IPv4 stack with the chosen routing protocol, and a UDP socket per node
// carrying controller messages. Positions come from the nodes' mobility models (physics).
#pragma once

#include <ns3/flow-monitor-helper.h>
#include <ns3/internet-stack-helper.h>
#include <ns3/net-device-container.h>
#include <ns3/node-container.h>
#include <ns3/pcap-file-wrapper.h>
#include <ns3/random-variable-stream.h>
#include <ns3/socket.h>
#include <ns3/wifi-helper.h>
#include <ns3/wifi-phy.h>
#include <ns3/yans-wifi-helper.h>

#include <memory>
#include <set>
#include <string>
#include <vector>

#include "net/abstract_channel.h"
#include "net/address_book.h"
#include "net/channel_losses.h"
#include "net/frame_trace.h"
#include "net/indexed_channel.h"
#include "net/link_loss_models.h"
#include "net/lr_wpan_radios.h"
#include "net/message_header.h"
#include "net/network_spec.h"
#include "net/ns3_attributes.h"
#include "net/obstacle_loss_model.h"
#include "net/packet_trace.h"
#include "net/routing_view.h"
#include "net/tap_port.h"
#include "net/transport.h"

namespace sanet::net {

class WirelessNetwork : public Transport {
 public:
  // `nodes` already carry their mobility models; `radios` holds per-node overrides; `walls`
  // are the obstacles that cost a frame crossing them (ObstacleLossModel), none by default.
  // `lr_wpan_walls`: the same obstacles at 2.4 GHz, for the 802.15.4 radios, if any node has one.
  WirelessNetwork(const NetworkSpec& spec, const ns3::NodeContainer& nodes, std::vector<std::string> names,
                  const std::vector<NodeRadio>& radios, std::vector<RadioObstacle> walls = {},
                  std::vector<RadioObstacle> lr_wpan_walls = {});
  ~WirelessNetwork() override;
  // A node joins while the run goes (a robot a client spawned), with the next id: the same
  // radio, channel, routing and traces as the others. `node` already carries its mobility.
  void AddNode(ns3::Ptr<ns3::Node> node, const std::string& name, const NodeRadio& radio);
  // Joins a real IP stack to node `id` through the tap `fd` (net/tap_port.h): the stack uses the
  // node's address (AddressBook), and its tap interface has the address `tap_mac`.
  void JoinTap(NodeId id, int fd, const std::string& tap_mac);
  // The mean power (dBm) at which `to` receives `from`'s transmissions now, on the radio they
  // share (802.11 if both have one, else 802.15.4; -inf if none): the channel's own propagation
  // loss models at the nodes' positions (path loss, walls, shadowing: what ns-3 itself computes
  // for each frame, before the frame's fading).
  double ReceivedPower(NodeId from, NodeId to) const;
  // Frames that radio receives weaker than this (dBm) are not detected.
  double DetectionThreshold(NodeId from, NodeId to) const {
    return SharesWifi(from, to) || !HasLrWpan(from) || !HasLrWpan(to) ? spec_.rx_threshold : spec_.lr_wpan.rx_threshold;
  }

  void SetReceiver(Receiver receiver) override { receiver_ = std::move(receiver); }
  void Send(NodeId from, NodeId to, const Bytes& payload) override;
  void Broadcast(NodeId from, const Bytes& payload) override;
  void Flood(NodeId from, const Bytes& payload) override;
  NetworkView& View(NodeId node) override { return *views_.at(node); }
  void SwitchOff(NodeId node) override;
  void SwitchOn(NodeId node) override;
  bool SetSleep(NodeId node, bool asleep) override;
  void Open(trace::ResultsFolder& folder) override;
  void Close() override;
  std::optional<NetworkTraces> Traces() const override;
  void ObserveFrames(FrameObserver observer) override;
  // With radio_model abstract: each frame's airtime at its sender and at each radio it reaches.
  void ObserveAbstractAirtime(AbstractChannel::OnAirObserver observer) {
    if (abstract_) abstract_->ObserveAirtime(std::move(observer));
  }
  // Whether `id`'s 802.11 radio is on the abstract channel.
  bool HasAbstractRadio(NodeId id) const { return abstract_ && id < ip4_.size() && ip4_[id] && !wifi_.at(id); }
  void Moved(const std::vector<NodeId>& nodes) override;
  const AddressBook& addresses() const { return book_; }
  // Node `id`'s Wi-Fi device (for the energy model that draws on its PHY's states); null without one.
  ns3::Ptr<ns3::NetDevice> Device(NodeId id) const { return wifi_.at(id); }
  // Node `id`'s 802.15.4 device; null without one.
  ns3::Ptr<ns3::LrWpanNetDevice> LrWpanDevice(NodeId id) const { return lr_wpan_ ? lr_wpan_->Device(id) : nullptr; }
  LrWpanRadios* LrWpan() { return lr_wpan_.get(); }  // null while no node has an 802.15.4 radio
  const PacketTrace& packet_trace() const { return trace_; }

 private:
  ns3::Ptr<ns3::WifiPhy> Phy(NodeId node) const;
  double TxPower(NodeId id, const NodeRadio& radio) const;  // dBm, with the node's hardware spread
  void ApplySleep(NodeId node);  // brings the PHY to sleep when it can, if its controller or its cycle wants it
  void StartDutyCycle(NodeId node);
  void CycleStep(NodeId node);  // the cycle's state now, and an event at its next change
  void ConfigureRadios();
  ns3::NetDeviceContainer InstallRadio(NodeId id, const NodeRadio& radio);
  void CountFrames(ns3::Ptr<ns3::WifiPhy> phy);
  void InstallInternet();
  void AssignStreams();
  std::int64_t AssignRoutingStreams(ns3::Ptr<ns3::Node> node, std::int64_t stream);
  void OpenSocket(NodeId id);
  void Receive(NodeId node, ns3::Ptr<ns3::Socket> socket);
  void InstallLrWpan(NodeId id);  // its 802.15.4 radio, after the IP stack
  bool IsOff(NodeId node) const;
  // An 802.11 radio, ns-3's whole model or the abstract one; and one of the whole model (a PHY).
  bool HasWifi(NodeId id) const { return ip4_.at(id) != nullptr; }
  bool HasWifiPhy(NodeId id) const { return wifi_.at(id) != nullptr; }
  ns3::NetDeviceContainer InstallAbstract(NodeId id);
  void ConfigureAbstract(const ChannelLosses& losses);
  bool SharesWifi(NodeId a, NodeId b) const { return HasWifi(a) && HasWifi(b); }
  bool HasLrWpan(NodeId id) const { return lr_wpan_ && lr_wpan_->Has(id); }
  void AssignAddress(NodeId id);
  void Transmit(NodeId from, const ns3::Address& to, const MessageHeader& header, const Bytes& payload);
  void TransmitToAll(NodeId from, const MessageHeader& header, const Bytes& payload);  // on every radio it has
  bool SeenTwice(NodeId node, const MessageHeader& h);  // a broadcast from two radios, heard on both
  MessageHeader NewHeader(NodeId from, MessageHeader::Kind kind, NodeId destination);
  void OpenPcap(NodeId id);

  NetworkSpec spec_;
  Ns3Defaults ns3_defaults_;  // before every helper and object: network.ns3 in effect while they live
  // Kept for nodes that join later: they are installed exactly as the first ones.
  ns3::WifiHelper wifi_helper_;
  RadioPhyHelper phy_;
  ns3::WifiMacHelper mac_;
  ns3::InternetStackHelper internet_;
  std::int64_t next_stream_ = 0;  // the first random stream nobody uses yet
  ns3::NodeContainer nodes_;
  ns3::NetDeviceContainer devices_;                 // the 802.11 ones, in node order
  std::vector<ns3::Ptr<ns3::WifiNetDevice>> wifi_;  // by node id; null without an 802.11 PHY
  std::vector<ns3::Ptr<ns3::NetDevice>> ip4_;       // by node id: the device IPv4 uses (802.11, whole or abstract)
  ns3::Ptr<AbstractChannel> abstract_;              // with radio_model: abstract
  std::unique_ptr<LrWpanRadios> lr_wpan_;           // when a node has an 802.15.4 radio
  ns3::Ptr<ObstacleLossModel> lr_wpan_walls_;
  std::vector<bool> sleep_wanted_;  // per node: what SetSleep asked for last
  std::vector<bool> cycle_asleep_;  // per node: whether its duty cycle has it asleep now
  AddressBook book_;
  std::vector<std::string> names_;
  PacketTrace trace_;
  std::vector<ns3::Ptr<ns3::Socket>> sockets_;   // by node id: IPv4 over 802.11, or null
  std::vector<ns3::Ptr<ns3::Socket>> sockets6_;  // by node id: IPv6 over 802.15.4, or null
  std::vector<std::unique_ptr<RoutingView>> views_;
  std::vector<std::uint32_t> next_sequence_;
  std::vector<std::set<std::pair<std::uint32_t, std::uint32_t>>> floods_seen_;      // (origin, sequence)
  std::vector<std::set<std::pair<std::uint32_t, std::uint32_t>>> broadcasts_seen_;  // from nodes with two radios
  ns3::Ptr<ns3::UniformRandomVariable> jitter_;
  Receiver receiver_;
  std::string flowmon_path_;  // temporary, in the results folder
  std::string pcap_dir_;      // temporary, in the results folder; empty: no pcap
  std::vector<ns3::Ptr<ns3::PcapFileWrapper>> pcap_;
  std::unique_ptr<ns3::FlowMonitorHelper> flow_helper_;
  ns3::Ptr<ns3::FlowMonitor> flow_monitor_;
  std::vector<NodeRadio> radios_;  // per node
  std::vector<std::unique_ptr<TapPort>> taps_;
  std::unique_ptr<FrameTrace> frames_;  // while someone traces the frames
  FrameObserver frame_observer_;        // the same, for an 802.15.4 radio made later
  TapLedger tap_ledger_;
  ns3::Ptr<IndexedWifiChannel> indexed_;           // with `channel: indexed`
  ns3::Ptr<ObstacleLossModel> walls_;              // in the channel's loss chain, if any obstacle costs
  ns3::Ptr<ns3::PropagationLossModel> mean_loss_;  // the channel's losses without fading
  ns3::Ptr<ShadowingLossModel> shadowing_;         // in mean_loss_, with shadowing on
  double nominal_noise_figure_ = 7;                // dB: WifiPhy's RxNoiseFigure (network.ns3 may set it)
  ChannelCounts frame_counts_;
};

}  // namespace sanet::net
