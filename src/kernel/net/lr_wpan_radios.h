// The run's IEEE 802.15.4 radios (docs/network.md#ieee-802154): ns-3's lr-wpan devices (2.4 GHz
// O-QPSK at 250 kbit/s, unslotted CSMA-CA, acknowledged unicast with retries) on one spectrum
// channel, each under a 6LoWPAN device that carries the node's IPv6 interface.
//
// - The channel's losses are the scenario's chain at 2405 MHz (path loss, walls, shadowing,
//   fading), behind a model of sanet's that applies each sender's transmit power and each
//   receiver's sensitivity (`lr_wpan.rx_threshold`; ns-3 3.37's LrWpanPhy has none): a frame
//   arriving weaker is not handed to the receiver at all, neither as a frame nor as interference,
//   and costs no reception event (the spectrum channel's maximum-loss cut-off).
// - Addresses come from the node id (net/address_book.h). 6LoWPAN-ND (RFC 6775) needs no address
//   resolution, since a short address is in its IPv6 address; ns-3 3.37 has only IPv6's own
//   neighbour discovery, so sanet writes the neighbour entry a unicast needs before sending it
//   (`KnowNeighbour`) and turns duplicate address detection off.
// - Asleep (a duty cycle or the controller), a radio hears nothing while its MAC is idle: the
//   channel hands it no frame. It still wakes to send, hearing the channel for CCA and the
//   acknowledgement while its MAC is busy, as a mote's radio stack does. (ns-3 3.37's own way,
//   macRxOnWhenIdle false, aborts the process when the MAC turns the receiver off during a
//   damaged frame's reception.) Switched off, the channel carries nothing from or to it (ns-3's
//   MAC has no off state).
#pragma once

#include <ns3/ipv6-address.h>
#include <ns3/lr-wpan-net-device.h>
#include <ns3/node.h>
#include <ns3/pcap-file-wrapper.h>
#include <ns3/propagation-delay-model.h>
#include <ns3/propagation-loss-model.h>
#include <ns3/sixlowpan-net-device.h>
#include <ns3/spectrum-channel.h>

#include <functional>
#include <map>
#include <memory>
#include <vector>

#include "net/address_book.h"
#include "net/network_spec.h"
#include "net/network_traces.h"
#include "net/obstacle_loss_model.h"

namespace sanet::net {

class LrWpanRadios {
 public:
  // `walls`: the obstacles' losses at 2.4 GHz, or null.
  LrWpanRadios(const NetworkSpec& spec, ns3::Ptr<ObstacleLossModel> walls);
  ~LrWpanRadios();

  // Gives node `id` its radio, transmitting at `tx_power_dbm`: the lr-wpan device, 6LoWPAN and
  // the IPv6 interface with its address.
  void Install(NodeId id, ns3::Ptr<ns3::Node> node, double tx_power_dbm);
  bool Has(NodeId id) const { return id < radios_.size() && radios_[id].device; }
  ns3::Ptr<ns3::LrWpanNetDevice> Device(NodeId id) const { return Has(id) ? radios_[id].device : nullptr; }
  // The device IPv6 sends through (sockets bind to it).
  ns3::Ptr<ns3::NetDevice> Interface(NodeId id) const { return radios_.at(id).sixlowpan; }
  // Random streams from `stream` on: returns how many it took (a radio's; the channel's delays).
  std::int64_t AssignStreams(NodeId id, std::int64_t stream);
  std::int64_t AssignChannelStreams(std::int64_t stream) { return delay_->AssignStreams(stream); }

  // Before `from` sends a unicast to `to`: the neighbour entry that maps `to`'s address to its
  // short address.
  void KnowNeighbour(NodeId from, NodeId to);
  void SetAsleep(NodeId id, bool asleep);
  // Asleep with its MAC idle and not switched off: deaf, drawing its sleep current.
  bool Sleeping(NodeId id) const {
    const Radio& r = radios_.at(id);
    return r.asleep && r.mac_idle && !r.off;
  }
  // `changed` is called whenever Sleeping(id) may have changed (the radio's energy model).
  void OnSleepChange(NodeId id, std::function<void()> changed) { radios_.at(id).sleep_changed = std::move(changed); }
  void SwitchOff(NodeId id);
  void SwitchOn(NodeId id, bool asleep);
  bool IsOff(NodeId id) const { return radios_.at(id).off; }

  // The mean power (dBm) at which `to` receives `from` now, without fading.
  double ReceivedPower(NodeId from, NodeId to) const;

  // Every frame from now on: counted (`counts`), and written to `pcap/<node>-802.15.4.pcap` in
  // `pcap_dir` when it is not empty (IEEE 802.15.4 without FCS, link type 230).
  void CountFrames(ChannelCounts* counts) { counts_ = counts; }
  void OpenPcap(NodeId id, const std::string& path);
  void ClosePcaps();
  // Frames each radio sent and received, for the run's trace.
  void ObserveFrames(FrameObserver observer);
  // The nodes whose frames radio `id` received whole in the last kNeighbourWindow seconds (acks
  // name no sender), in id order: its neighbours, where no routing protocol keeps any.
  static constexpr double kNeighbourWindow = 10;
  std::vector<NodeId> Neighbours(NodeId id) const;
  // A unicast that the MAC gave up on (no acknowledgement after its retries, or a busy channel).
  void OnMacDrop(std::function<void(NodeId, ns3::Ptr<const ns3::Packet>)> dropped) { mac_drop_ = std::move(dropped); }

  // What the channel's sensitivity cut asks of each radio, by node id.
  struct Links {
    std::vector<double> tx_power_dbm, sensitivity_dbm;  // with the node's hardware spread
    std::vector<bool> off;                              // switched off: sends nothing
    std::vector<bool> deaf;                             // off, or asleep with its MAC idle: hears nothing
    void Resize(std::size_t n) {
      tx_power_dbm.resize(n, 0), sensitivity_dbm.resize(n, 0), off.resize(n, false), deaf.resize(n, false);
    }
  };

 private:
  struct Radio {
    ns3::Ptr<ns3::LrWpanNetDevice> device;
    ns3::Ptr<ns3::SixLowPanNetDevice> sixlowpan;
    std::uint32_t interface = 0;  // IPv6's
    double tx_power_dbm = 0;
    bool off = false;
    bool asleep = false, mac_idle = true;
    std::function<void()> sleep_changed;
    ns3::Ptr<ns3::PcapFileWrapper> pcap;
    std::map<NodeId, double> heard;  // sender -> when its last frame arrived whole, s
  };
  void Trace(NodeId id);
  void Changed(NodeId id);  // off, asleep or the MAC's idleness: what the channel hands it
  void Sent(NodeId id, ns3::Ptr<const ns3::Packet> frame);
  void Heard(NodeId id, ns3::Ptr<const ns3::Packet> frame);
  void Write(NodeId id, ns3::Ptr<const ns3::Packet> frame);
  FrameEvent Describe(NodeId id, bool sent, ns3::Ptr<const ns3::Packet> frame) const;

  NetworkSpec spec_;
  ns3::Ptr<ns3::SpectrumChannel> channel_;
  ns3::Ptr<ns3::PropagationDelayModel> delay_;
  ns3::Ptr<ns3::PropagationLossModel> mean_;  // without fading, for ReceivedPower
  std::vector<Radio> radios_;                 // by node id; empty where a node has none
  Links links_;
  ChannelCounts* counts_ = nullptr;
  FrameObserver observer_;
  std::function<void(NodeId, ns3::Ptr<const ns3::Packet>)> mac_drop_;
};

}  // namespace sanet::net
